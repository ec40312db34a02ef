// Twin of root_must_be_composite.fail.cpp: Idle is the initial child of a composite root.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
