// EXPECT: bsc::to_scxml: under parent-first priority a row of an ancestor takes an event derived from
// Parent first, Normal's row on overheat is tried before Filling's row on fault for an overheat,
// but not for another fault: an SCXML cond cannot say that without the event's name.
#include <bsc/export.hpp>

#include <string>

#include "station.hpp"

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    station, bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
    bsc::state<Filling> + bsc::event<fault> = bsc::state<Idle>,
    bsc::state<Normal> + bsc::event<overheat> = bsc::state<EStop>,
    bsc::state<EStop> + bsc::event<bottle> = bsc::state<Normal>);

std::string document() { return bsc::to_scxml(chart); }
}  // namespace cf
