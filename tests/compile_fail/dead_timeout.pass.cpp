// The twin of dead_timeout.fail.cpp: the 1 s timeout is internal (it re-arms and Busy stays
// active), so the 5 s one fires.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Late;
struct ctx {
    int ticks = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Late>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::after(1s) / [](ctx& c) { ++c.ticks; },
    bsc::state<Busy> + bsc::after(5s) = bsc::state<Late>,
    bsc::state<Late> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
