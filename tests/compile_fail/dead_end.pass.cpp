// Twin of dead_end.fail.cpp: Stuck is declared final, an intended end of the chart.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Stuck;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::final_state<Stuck>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Stuck>);
}  // namespace cf
