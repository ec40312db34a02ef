// EXPECT: defect=finding_not_allowable<bsc::allow<bsc::error::unreachable_state, bsc::error::duplicate_state>
// A chart may allow findings after which its machine still runs as it says (a state never
// entered, say), never a malformed tree: a state declared twice is not a finding to allow.
#include "two_states.hpp"

namespace cf {
inline constexpr auto allowing =
    bsc::make_chart<ctx, bsc::child_first, bsc::allow<bsc::error::unreachable_state, bsc::error::duplicate_state>>(
        bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
        bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
