// EXPECT: defect=context_type_has_base_class<cf::ctx>
// ctx inherits its channels from axis_io: bsc finds the members of an aggregate, not of its bases.
#include <bsc/bsc.hpp>

namespace cf {
struct scan {};
struct Root;
struct Homing;
struct Ready;
struct axis_io {
    bsc::input<bool> at_home;
    bsc::output<bool> motor;
};
struct ctx : axis_io {
    int homings = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Homing>, bsc::state<Ready>),
    bsc::state<Homing> + bsc::event<scan>[([](ctx const& c) { return c.at_home.get(); })] /
                             [](ctx& c) { c.motor.set(false); } = bsc::state<Ready>,
    bsc::state<Ready> + bsc::event<scan>[([](ctx const& c) { return !c.at_home.get(); })] /
                            [](ctx& c) { c.motor.set(true); } = bsc::state<Homing>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::scan{});
    return m.is<cf::Ready>();
}
