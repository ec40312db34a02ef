// EXPECT: defect=raised_event_not_in_chart<cf::other>
// The action of Idle -go-> Busy raises cf::other, which no transition handles. The action
// is checked when the machine's dispatch of cf::go is instantiated.
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
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
