// Twin of context_not_an_aggregate.fail.cpp: the panel is an aggregate, and its one member is
// visited.
#include <bsc/bsc.hpp>

namespace cf {
struct panel {
    bool pressed = false;
};
}  // namespace cf

int main() {
    cf::panel p;
    return bsc::detail::apply_to_fields(p, [](auto&... fields) { return static_cast<int>(sizeof...(fields)) - 1; });
}
