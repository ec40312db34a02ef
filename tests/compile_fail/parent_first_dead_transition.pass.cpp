// The twin: Normal's row on estop is guarded, so Filling's row fires when the guard is false.
// (Child first, the unguarded outer row is fine too: Filling's row is tried first.)
#include "station.hpp"

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    station, bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
    bsc::state<Filling> + bsc::event<estop> = bsc::state<Idle>,
    bsc::state<Normal> + bsc::event<estop>[([](ctx const&, estop const& e) { return e.latched; })] = bsc::state<EStop>,
    bsc::state<EStop> + bsc::event<reset> = bsc::state<Normal>);

inline constexpr auto child_first = bsc::make_chart<ctx>(station,
                                                         bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
                                                         bsc::state<Filling> + bsc::event<estop> = bsc::state<Idle>,
                                                         bsc::state<Normal> + bsc::event<estop> = bsc::state<EStop>,
                                                         bsc::state<EStop> + bsc::event<reset> = bsc::state<Normal>);
}  // namespace cf
