// Twin of state_in_optional.fail.cpp: the timer is a member of the context itself, which the
// machine updates at each step; "no watchdog yet" is a timer that has not been started.
#include <bsc/bsc.hpp>
#include <chrono>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int runs = 0;
    bsc::timer watchdog{std::chrono::milliseconds{50}};
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / [](ctx& c) { c.watchdog.start(); } = bsc::state<Busy>,
    bsc::state<Busy>[([](ctx const& c) { return c.watchdog.tm(); })] / [](ctx& c) { ++c.runs; } = bsc::state<Idle>);
}  // namespace cf

int main() {
    using std::chrono::milliseconds;
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    m.step(milliseconds{10});  // the watchdog starts timing
    m.step(milliseconds{30});
    bool const busy = m.is<cf::Busy>();
    m.step(milliseconds{60});  // 50 ms since it began: expired, back to Idle
    return busy && m.is<cf::Idle>() && m.context().runs == 1 ? 0 : 1;
}
