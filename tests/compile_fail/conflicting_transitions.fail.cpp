// EXPECT: (bsc::error::at_row<2, bsc::error::conflicting_transitions<cf::Idle, cf::go>.*bsc: conflicting transitions|bsc: conflicting transitions.*bsc::error::at_row<2, bsc::error::conflicting_transitions<cf::Idle, cf::go>)
// Two unguarded transitions leave Idle on go: the chart cannot choose between them.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Other;
struct ctx {
    int error = 0;
};
inline constexpr auto ok = bsc::guard([](ctx const& c) { return c.error == 0; });

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Other>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<go> = bsc::state<Other>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>,
    bsc::state<Other> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
