// EXPECT: defect=eventless_livelock<cf::Busy>
// Busy has an unguarded eventless internal transition (an action with no target): it stays
// enabled after it fires, so dispatch would run it forever.
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
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>, bsc::state<Busy> / [](ctx& c) { ++c.ticks; });
}  // namespace cf
