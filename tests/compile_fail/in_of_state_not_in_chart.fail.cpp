// EXPECT: defect=at_row<3, in_of_state_not_in_chart<cf::Runing>
// The guard of the third row tests bsc::in<Runing>, a misspelt Running: no state of the chart.
#include "motor_lamp.hpp"

namespace cf {
struct Runing;
inline constexpr auto chart = motor_lamp<Runing>();
}  // namespace cf
