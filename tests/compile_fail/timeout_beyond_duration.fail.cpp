// EXPECT: defect=timeout_beyond_duration
// A delay beyond bsc::duration (nanoseconds, about 292 years) does not compile in a constexpr chart.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::after(std::chrono::years(1000)) = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
