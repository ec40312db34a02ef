// Twin of state_in_variant.fail.cpp: the input channel is a member of its own, next to the fixed
// value and the choice between them, so that the machine latches it at each dispatch.
#include <bsc/bsc.hpp>

namespace cf {
struct check {};
struct Root;
struct Normal;
struct High;
struct ctx {
    bool from_input = false;  // the setpoint: the fixed value, or the input
    int fixed = 0;
    bsc::input<int> input;
    int limit = 100;
};

inline constexpr auto too_high = bsc::guard([](ctx const& c) {
    int const value = c.from_input ? c.input.get() : c.fixed;
    return value > c.limit;
});
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Normal>, bsc::state<High>),
    bsc::state<Normal> + bsc::event<check>[too_high] = bsc::state<High>,
    bsc::state<High> + bsc::event<check>[!too_high] = bsc::state<Normal>);
}  // namespace cf

int main() {
    cf::ctx setpoint{};
    setpoint.from_input = true;  // the setpoint is the input's, from the start
    bsc::machine m{cf::chart, setpoint};
    m.context().input.set(150);  // latched by the next dispatch
    m.dispatch(cf::check{});
    bool const high = m.is<cf::High>();
    m.context().input.set(20);
    m.dispatch(cf::check{});
    return high && m.is<cf::Normal>() ? 0 : 1;
}
