// EXPECT: (bsc::error::at_row<2, bsc::error::state_not_in_chart<cf::Ghost>.*bsc: a row names a state that the state tree does not declare|bsc: a row names a state that the state tree does not declare.*bsc::error::at_row<2, bsc::error::state_not_in_chart<cf::Ghost>)
// The target of the second row, Ghost, is not declared in the state tree.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Ghost;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Ghost>);
}  // namespace cf
