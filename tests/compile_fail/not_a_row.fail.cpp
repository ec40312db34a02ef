// EXPECT: (bsc::error::not_a_row<bsc::detail::state_ref<cf::Busy> ?>.*bsc: after the state tree, every argument of make_chart must be a row|bsc: after the state tree, every argument of make_chart must be a row.*bsc::error::not_a_row<bsc::detail::state_ref<cf::Busy> ?>)
// After the state tree, make_chart takes rows only; bsc::state<Busy> on its own names a
// state, it is not a transition.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy>);
}  // namespace cf
