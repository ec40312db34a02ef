// Twin of not_an_event.fail.cpp: a class type (or an enumeration) is an event.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
enum class stop { now };
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
