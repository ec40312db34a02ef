// Twin of in_of_state_not_in_chart.fail.cpp: the guard tests bsc::in<Running>, a state of the
// other region, so the lamp comes on when go finds the motor running.
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
    bsc::state<Off> + bsc::event<go>[bsc::in<Running>] = bsc::state<On>,
    bsc::state<On> + bsc::event<stop> = bsc::state<Off>);

static_assert([] {
    bsc::machine m{chart};
    m.dispatch(go{});  // the motor starts; the lamp's guard saw it stopped
    bool const off = m.is<Off>();
    m.dispatch(go{});
    return off && m.is<On>();
}());
}  // namespace cf
