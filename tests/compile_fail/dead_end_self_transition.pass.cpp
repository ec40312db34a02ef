// Twin of dead_end_self_transition.fail.cpp: once reset, Estop leads back On.
#include <bsc/bsc.hpp>

namespace cf {
struct estop_p {};
struct reset_p {};
struct Root;
struct On;
struct Estop;
struct ctx {
    int error = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<On>, bsc::state<Estop>),
    bsc::state<On> + bsc::event<estop_p> / [](ctx& c) { c.error = 1; } = bsc::state<Estop>,
    bsc::state<Estop> + bsc::event<reset_p> / [](ctx& c) { c.error = 0; } = bsc::state<On>);
}  // namespace cf
