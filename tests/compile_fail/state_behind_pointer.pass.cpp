// Twin of state_behind_pointer.fail.cpp: the context holds the timer itself, and the machine
// updates it at each step.
#include <bsc/bsc.hpp>
#include <chrono>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Heating;
struct ctx {
    bsc::timer heat_timer{std::chrono::seconds{2}};
    int cycles = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Heating>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.heat_timer.start(); } = bsc::state<Heating>,
    bsc::state<Heating>[([](ctx const& c) { return c.heat_timer.tm(); })] /
        [](ctx& c) { ++c.cycles; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    using std::chrono::seconds;
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    m.step(seconds{1});  // timing begins
    m.step(seconds{2});
    bool const heating = m.is<cf::Heating>();
    m.step(seconds{3});  // 2 s since timing began: expired
    return heating && m.is<cf::Idle>() && m.context().cycles == 1 ? 0 : 1;
}
