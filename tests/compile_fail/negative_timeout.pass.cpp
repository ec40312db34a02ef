// Twin of negative_timeout.fail.cpp: a delay of zero is allowed (the first cycle fires it).
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::after(0s) = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
