// EXPECT: bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout
// Busy's 5 s timeout can never fire: the unguarded 1 s timeout leaves Busy first, every time.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Late;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Late>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::after(1s) = bsc::state<Idle>,
    bsc::state<Busy> + bsc::after(5s) = bsc::state<Late>,
    bsc::state<Late> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
