// The twin: is<Busy>() asks about a state of the chart.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Bsuy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

inline bool busy() {
    bsc::machine m{chart};
    (void)m.dispatch(go{});
    return m.is<Busy>();
}
}  // namespace cf
