// EXPECT: defect=multiple_initial_states<cf::Busy>
// Two markers name the same child, which the markers alone declare: one child, two markers.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Sub1;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Busy>(bsc::initial<Sub1>, bsc::initial<Sub1>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
