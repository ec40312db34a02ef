// EXPECT: (bsc::error::at_row<3, bsc::error::invalid_deferral<cf::Busy, cf::job>.*bsc: invalid deferral|bsc: invalid deferral.*bsc::error::at_row<3, bsc::error::invalid_deferral<cf::Busy, cf::job>)
// A deferring row keeps its event for later; with a target it would also be a transition.
#include <bsc/bsc.hpp>

namespace cf {
struct start {};
struct job {};
struct finish {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<job> / bsc::defer = bsc::state<Idle>,
    bsc::state<Busy> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace cf
