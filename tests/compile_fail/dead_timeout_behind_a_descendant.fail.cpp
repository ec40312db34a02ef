// EXPECT: transition_row<cf::Busy, bsc::detail::timeout_trigger, [^>]*, cf::Late>::~transition_row|timeout_row_never_fires\(3, 2\)
// Busy's 5 s timeout can never fire: Step, Busy's only child, is active whenever Busy is, and
// its unguarded 1 s timeout leaves Busy first, every time.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Step;
struct Late;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>), bsc::state<Late>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Step> + bsc::after(1s) = bsc::state<Idle>,
    bsc::state<Busy> + bsc::after(5s) = bsc::state<Late>, bsc::state<Late> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
