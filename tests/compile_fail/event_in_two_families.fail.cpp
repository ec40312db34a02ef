// EXPECT: bsc::error::event_in_two_families<cf::fault>.*bsc: event in two families|bsc: event in two families.*bsc::error::event_in_two_families<cf::fault>
// `fault` derives from both `alarm` and `stop`, which do not derive from one another: rows on
// either would take it, and an event's families must form one chain.
#include <bsc/bsc.hpp>

namespace cf {
struct alarm {};
struct stop {};
struct fault : alarm, stop {};
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
    bsc::state<Idle> + bsc::event<alarm> = bsc::state<Alarmed>,
    bsc::state<Idle> + bsc::event<stop> = bsc::state<Stopped>,
    bsc::state<Alarmed> + bsc::event<go> = bsc::state<Idle>, bsc::state<Stopped> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Broken> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
