// EXPECT: defect=at_row<2, dead_transition_behind_outer<cf::Filling, cf::estop, cf::Idle, cf::Normal>
// Under parent-first priority Normal's unguarded row on estop is tried first whenever Filling is
// active, so Filling's row on estop never fires.
#include "station.hpp"

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    station, bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
    bsc::state<Filling> + bsc::event<estop> = bsc::state<Idle>,
    bsc::state<Normal> + bsc::event<estop> = bsc::state<EStop>,
    bsc::state<EStop> + bsc::event<reset> = bsc::state<Normal>);
}  // namespace cf
