// The twin: Normal's row takes every fault, like Filling's, and is guarded; the document negates
// its guard in Filling's cond.
#include <bsc/export.hpp>

#include <string>

#include "station.hpp"

namespace cf {
inline constexpr auto chart = bsc::make_chart<ctx, bsc::parent_first>(
    station, bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
    bsc::state<Filling> + bsc::event<fault> = bsc::state<Idle>,
    bsc::state<Normal> + bsc::event<fault>[([](ctx const& c) { return c.hot; })] = bsc::state<EStop>,
    bsc::state<EStop> + bsc::event<bottle> = bsc::state<Normal>);

std::string document() { return bsc::to_scxml(chart); }
}  // namespace cf
