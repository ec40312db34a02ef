#pragma once
// The chart of the compile-fail tests about bsc::in<S> of a state not in the chart: a motor and
// a lamp in two regions; the lamp comes on when go finds the state Tested active.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Motor;
struct Stopped;
struct Running;
struct Lamp;
struct Off;
struct On;
struct ctx {};

template <class Tested>
constexpr auto motor_lamp() {
    return bsc::make_chart<ctx>(bsc::parallel<Root>(bsc::composite<Motor>(bsc::initial<Stopped>, bsc::state<Running>),
                                                    bsc::composite<Lamp>(bsc::initial<Off>, bsc::state<On>)),
                                bsc::state<Stopped> + bsc::event<go> = bsc::state<Running>,
                                bsc::state<Running> + bsc::event<stop> = bsc::state<Stopped>,
                                bsc::state<Off> + bsc::event<go>[bsc::in<Tested>] = bsc::state<On>,
                                bsc::state<On> + bsc::event<stop> = bsc::state<Off>);
}
}  // namespace cf
