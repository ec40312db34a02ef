// EXPECT: defect=context_not_an_aggregate<cf::panel>
// The walk of a context's members (detail::apply_to_fields, which channels, timers, retentive
// state and the explorer go through) reached a class that is not an aggregate: it has a
// constructor and private members. The public walks treat such a member as one value and never
// look inside, so the test calls the walk itself.
#include <bsc/bsc.hpp>

namespace cf {
class panel {
public:
    panel() : pressed_(false) {}
    bool pressed() const { return pressed_; }

private:
    bool pressed_;
};
}  // namespace cf

int main() {
    cf::panel p;
    return bsc::detail::apply_to_fields(p, [](auto&...) { return 0; });
}
