// The twin: Step's 1 s timeout moves to Other, inside Busy, so Busy's own 5 s timeout still
// comes due.
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
struct Other;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>, bsc::state<Other>),
                         bsc::state<Late>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Step> + bsc::after(1s) = bsc::state<Other>,
    bsc::state<Other> + bsc::event<go> = bsc::state<Idle>, bsc::state<Busy> + bsc::after(5s) = bsc::state<Late>,
    bsc::state<Late> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
