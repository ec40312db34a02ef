// EXPECT: defect=state_out_of_reach<cf::axis, member_number<1>, std::optional<bsc::timer> ?>
// The timer is in a std::optional inside cf::axis, a struct of the context: the error names axis.
#include <bsc/bsc.hpp>
#include <chrono>
#include <optional>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Moving;
struct axis {
    int position = 0;
    std::optional<bsc::timer> watchdog;
};
struct ctx {
    int moves = 0;
    axis x;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Moving>),
    bsc::state<Idle> +
        bsc::event<go> /
            [](ctx& c) { c.x.watchdog.emplace(std::chrono::milliseconds{50}).start(); } = bsc::state<Moving>,
    bsc::state<Moving>[([](ctx const& c) { return c.x.watchdog && c.x.watchdog->tm(); })] = bsc::state<Idle>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    return m.is<cf::Moving>();
}
