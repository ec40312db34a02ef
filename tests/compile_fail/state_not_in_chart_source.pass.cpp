// Twin of state_not_in_chart_source.fail.cpp: the row leaves Busy, a declared state.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Ghost;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
