// Twin of raised_event_not_in_chart.fail.cpp: a transition now handles cf::other.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct other {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> / bsc::raise(other{}) = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>, bsc::state<Busy> + bsc::event<other> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
