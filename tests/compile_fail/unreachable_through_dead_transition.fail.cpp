// EXPECT: defect=unreachable_state<cf::Lost>
// The only row into Lost leaves Done, a final child of the root, and can never fire (it is
// reported as a dead transition too): reachability follows only rows that can fire.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Done;
struct Lost;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::final_state<Done>, bsc::state<Lost>),
    bsc::state<Idle> + bsc::event<stop> = bsc::state<Done>, bsc::state<Done> + bsc::event<go> = bsc::state<Lost>,
    bsc::state<Lost> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
