// Twin of eventless_livelock_internal.fail.cpp: the internal transition is guarded, so it
// stops firing once the guard fails.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int ticks = 0;
};
inline constexpr auto counting = bsc::guard([](ctx const& c) { return c.ticks < 3; });

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>), bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>, bsc::state<Busy>[counting] / [](ctx& c) { ++c.ticks; });
}  // namespace cf
