// EXPECT: (bsc::error::missing_initial_state<cf::Busy>.*bsc: this composite state has no initial child|bsc: this composite state has no initial child.*bsc::error::missing_initial_state<cf::Busy>)
// The composite Busy does not say which of its children a transition to Busy enters.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Sub1;
struct Sub2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Busy>(bsc::state<Sub1>, bsc::state<Sub2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Sub1> + bsc::event<go> = bsc::state<Sub2>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
