// EXPECT: defect=duplicate_event_name<cf::panel::go, cf::remote::go>
// Two event types are both called "go": dispatch_by_name could not tell which one is meant.
#include <bsc/bsc.hpp>

#include <string_view>

namespace cf {
namespace panel {
struct go {};
}  // namespace panel
namespace remote {
struct go {};
}  // namespace remote
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<panel::go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<remote::go> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch_by_name("go");
}
}  // namespace cf
