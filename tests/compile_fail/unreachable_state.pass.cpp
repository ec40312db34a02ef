// Twin of unreachable_state.fail.cpp: a transition now leads into Orphan.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Orphan;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Orphan>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Orphan>,
    bsc::state<Orphan> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
