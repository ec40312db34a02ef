// EXPECT: defect=state_out_of_reach<cf::ctx, member_number<1>, std::optional<bsc::timer> ?>
// The timer is inside a std::optional, where the machine cannot reach it to update it.
#include <bsc/bsc.hpp>
#include <chrono>
#include <optional>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int runs = 0;
    std::optional<bsc::timer> watchdog;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> +
        bsc::event<go> / [](ctx& c) { c.watchdog.emplace(std::chrono::milliseconds{50}).start(); } = bsc::state<Busy>,
    bsc::state<Busy>[([](ctx const& c) { return c.watchdog && c.watchdog->tm(); })] = bsc::state<Idle>);
}  // namespace cf

bool run() {
    bsc::machine m{cf::chart, cf::ctx{}};
    m.dispatch(cf::go{});
    return m.is<cf::Busy>();
}
