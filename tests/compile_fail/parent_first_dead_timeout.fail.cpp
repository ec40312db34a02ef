// EXPECT: transition_row<cf::Step, bsc::detail::timeout_trigger, [^>]*, cf::Retry>::~transition_row|timeout_row_never_fires\(3, 2\)
// Under parent-first priority, Busy's unguarded 1 s timeout and Step's 1 s timeout come due
// together (Step, Busy's only child, is entered with it), and Busy's, the outer one, is tried
// first: Step's never fires.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Step;
struct Retry;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>), bsc::state<Retry>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Busy> + bsc::after(1s) = bsc::state<Idle>,
    bsc::state<Step> + bsc::after(1s) = bsc::state<Retry>, bsc::state<Retry> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
