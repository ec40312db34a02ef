// EXPECT: bsc::error::done_of_state_not_in_chart<cf::Wrok>
// The row takes the completion of Wrok, a misspelt Work that is no state of the chart: nothing
// raises bsc::done<Wrok>.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Work;
struct Busy;
struct Idle;
struct Next;
struct Wrok;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Work>, bsc::composite<Work>(bsc::initial<Busy>, bsc::final_state<Idle>),
                         bsc::state<Next>),
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Work> + bsc::event<bsc::done<Wrok>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Work>);
}  // namespace cf
