// EXPECT: defect=member_not_retainable<cf::display>
// cf::display has a constructor: it is neither an aggregate nor a scalar, so bsc::save cannot store it.
#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
class display {
public:
    display() = default;
    explicit display(int v) : shown_(v) {}
    int shown() const { return shown_; }

private:
    int shown_ = 0;
};
struct ctx {
    int count = 0;
    display screen;
};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

std::size_t run() {
    bsc::machine m{chart, ctx{}};
    return bsc::save(m).size();
}
}  // namespace cf
