// EXPECT: defect=dead_transition<cf::Done, cf::go, cf::Idle>
// Done is a final child of the root: once it is entered the machine has halted, so the row
// leaving it can never fire.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Done;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::final_state<Done>),
                                                   bsc::state<Idle> + bsc::event<stop> = bsc::state<Done>,
                                                   bsc::state<Done> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
