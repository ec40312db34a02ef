#pragma once
// The controller of a conveyor, shared by the tests of systems (system_test.cpp) and of their
// distribution over nodes (net_node_test.cpp): it starts the motor when asked and stops it when
// the part has arrived. Each test pairs it with a plant of its own.

#include <bsc/bsc.hpp>

namespace conveyor {
struct Root;
struct Idle;
struct Running;

struct controller_io {
    bsc::input<bool> request;
    bsc::input<bool> arrived;
    bsc::output<bool> motor;
};
inline constexpr auto controller = bsc::make_chart<controller_io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Running>),
    bsc::state<Idle>[([](controller_io const& c) { return c.request.get() && !c.arrived.get(); })] /
        [](controller_io& c) { c.motor.set(true); } = bsc::state<Running>,
    bsc::state<Running>[([](controller_io const& c) { return c.arrived.get(); })] /
        [](controller_io& c) { c.motor.set(false); } = bsc::state<Idle>);
}  // namespace conveyor
