// Twin of state_in_optional_nested.fail.cpp: the timer is a member of cf::axis itself, and the
// machine finds it at any depth of the context's structs.
#include <bsc/bsc.hpp>
#include <chrono>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Moving;
struct axis {
    int position = 0;
    bsc::timer watchdog{std::chrono::milliseconds{50}};
};
struct ctx {
    int moves = 0;
    axis x;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Moving>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.x.watchdog.start(); } = bsc::state<Moving>,
    bsc::state<Moving>[([](ctx const& c) { return c.x.watchdog.tm(); })] /
        [](ctx& c) { ++c.moves; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    using std::chrono::milliseconds;
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    m.step(milliseconds{10});  // the watchdog starts timing
    bool const moving = m.is<cf::Moving>();
    m.step(milliseconds{60});  // expired: back to Idle
    return moving && m.is<cf::Idle>() && m.context().moves == 1 ? 0 : 1;
}
