// Twin of in_of_state_not_in_chart.fail.cpp: the guard tests bsc::in<Running>, a state of the
// other region, so the lamp comes on when go finds the motor running.
#include "motor_lamp.hpp"

namespace cf {
inline constexpr auto chart = motor_lamp<Running>();

static_assert([] {
    bsc::machine m{chart};
    m.dispatch(go{});  // the motor starts; the lamp's guard saw it stopped
    bool const off = m.is<Off>();
    m.dispatch(go{});
    return off && m.is<On>();
}());
}  // namespace cf
