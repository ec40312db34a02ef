// EXPECT: defect=unhandled_event<cf::other>
// No transition of the chart is triggered by cf::other, so dispatching it is rejected.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct other {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
    m.dispatch(other{});
}
}  // namespace cf
