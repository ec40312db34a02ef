// Twin of event_in_two_families.fail.cpp: `stop` now derives from `alarm`, so fault's
// families form the chain stop, alarm.
#include <bsc/bsc.hpp>

namespace cf {
struct alarm {};
struct stop : alarm {};
struct fault : stop {};
struct go {};
struct Root;
struct Idle;
struct Alarmed;
struct Stopped;
struct Broken;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Alarmed>, bsc::state<Stopped>,
                         bsc::state<Broken>),
    bsc::state<Idle> + bsc::event<fault> = bsc::state<Broken>,
    bsc::state<Idle> + bsc::event<stop> = bsc::state<Stopped>,
    bsc::state<Idle> + bsc::event<alarm> = bsc::state<Alarmed>,
    bsc::state<Alarmed> + bsc::event<go> = bsc::state<Idle>, bsc::state<Stopped> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Broken> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
