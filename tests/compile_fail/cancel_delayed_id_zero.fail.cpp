// EXPECT: defect=cancel_delayed_id_zero
// bsc::cancel_delayed(0) does not compile in a constexpr chart: 0 is no id, and cancels nothing.
#include <bsc/bsc.hpp>

#include <chrono>

namespace cf {
struct go {};
struct stop {};
struct tick {};
struct Root;
struct Idle;
struct Wait;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Wait>),
    bsc::state<Idle> + bsc::event<go> / bsc::raise_after(std::chrono::seconds{2}, tick{}) = bsc::state<Wait>,
    bsc::state<Wait> + bsc::event<tick> = bsc::state<Idle>,
    bsc::state<Wait> + bsc::event<stop> / bsc::cancel_delayed(0) = bsc::state<Idle>);
}  // namespace cf
