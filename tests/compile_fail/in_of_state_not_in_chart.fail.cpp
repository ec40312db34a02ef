// EXPECT: defect=at_row<3, in_of_state_not_in_chart<cf::Runing>
// The guard of the third row tests bsc::in<Runing>, a misspelt Running: no state of the chart.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Motor;
struct Stopped;
struct Running;
struct Runing;
struct Lamp;
struct Off;
struct On;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::parallel<Root>(bsc::composite<Motor>(bsc::initial<Stopped>, bsc::state<Running>),
                        bsc::composite<Lamp>(bsc::initial<Off>, bsc::state<On>)),
    bsc::state<Stopped> + bsc::event<go> = bsc::state<Running>,
    bsc::state<Running> + bsc::event<stop> = bsc::state<Stopped>,
    bsc::state<Off> + bsc::event<go>[bsc::in<Runing>] = bsc::state<On>,
    bsc::state<On> + bsc::event<stop> = bsc::state<Off>);
}  // namespace cf
