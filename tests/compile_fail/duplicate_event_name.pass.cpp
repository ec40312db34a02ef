// Twin of duplicate_event_name.fail.cpp: remote::go names itself "remote_go", so every event of
// the chart has a name of its own.
#include <bsc/bsc.hpp>

#include <string_view>

namespace cf {
namespace panel {
struct go {};
}  // namespace panel
namespace remote {
struct go {
    static constexpr std::string_view name = "remote_go";
};
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
