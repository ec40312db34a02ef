// Twin of context_type_has_base_class.fail.cpp: ctx keeps its base class, and bsc::fields<ctx>
// lists every member, the base's included, so the machine latches at_home and publishes motor.
// (Holding axis_io as a member, `axis_io io;`, needs no bsc::fields.)
#include <array>
#include <bsc/bsc.hpp>
#include <string_view>

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
}  // namespace cf

template <>
struct bsc::fields<cf::ctx> {
    static constexpr std::array<std::string_view, 3> names{"at_home", "motor", "homings"};
    template <class Self, class F>
    static constexpr decltype(auto) apply(Self& self, F&& f) {
        return f(self.at_home, self.motor, self.homings);
    }
};

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Homing>, bsc::state<Ready>),
    bsc::state<Homing> + bsc::event<scan>[([](ctx const& c) { return c.at_home.get(); })] /
                             [](ctx& c) {
                                 c.motor.set(false);
                                 ++c.homings;
                             } = bsc::state<Ready>,
    bsc::state<Ready> + bsc::event<scan>[([](ctx const& c) { return !c.at_home.get(); })] /
                            [](ctx& c) { c.motor.set(true); } = bsc::state<Homing>);
}  // namespace cf

int main() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.context().at_home.set(true);
    m.dispatch(cf::scan{});  // latches at_home: homed
    bool const ready = m.is<cf::Ready>() && m.context().homings == 1;
    m.context().at_home.set(false);
    m.dispatch(cf::scan{});  // the motor is switched on again, published at the end of the dispatch
    return ready && m.is<cf::Homing>() && m.context().motor.get() ? 0 : 1;
}
