// The twin of finding_not_allowable.fail.cpp: the findings allowed are findings; Lost, never
// entered and without a way out, is two (SCXML accepts such a chart), and the chart compiles
// and runs.
#include "two_states.hpp"

namespace cf {
struct Lost;
inline constexpr auto allowing =
    bsc::make_chart<ctx, bsc::child_first, bsc::allow<bsc::error::unreachable_state, bsc::error::dead_end_state>>(
        bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Lost>),
        bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf

int main() {
    bsc::machine m{cf::allowing};
    m.dispatch(cf::go{});
    return m.is<cf::Busy>() ? 0 : 1;
}
