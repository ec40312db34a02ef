// EXPECT: defect=not_an_event_of_the_chart<cf::other>
// cf::other triggers no row: it has no number in the chart's event_set.
#include <bsc/bsc.hpp>

#include <cstddef>

namespace cf {
struct go {};
struct stop {};
struct other {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

inline constexpr std::size_t number = bsc::event_set<decltype(chart)>::number_of<other>;
}  // namespace cf
