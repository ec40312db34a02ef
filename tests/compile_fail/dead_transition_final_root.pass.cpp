// The twin of dead_transition_final_root.fail.cpp: Done is a final child of a nested composite,
// not of the root, so the machine does not halt there and the row leaving it can fire.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Run;
struct Idle;
struct Done;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Run>, bsc::composite<Run>(bsc::initial<Idle>, bsc::final_state<Done>)),
    bsc::state<Idle> + bsc::event<stop> = bsc::state<Done>, bsc::state<Done> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
