// The twin of unreachable_through_dead_transition.fail.cpp: the row into Lost leaves Idle.
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
    bsc::state<Idle> + bsc::event<stop> = bsc::state<Done>, bsc::state<Idle> + bsc::event<go> = bsc::state<Lost>,
    bsc::state<Lost> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
