#pragma once
// The manufacturing cell as a closed, finite model for bsc::verify: the controller of
// controller.hpp in closed loop with a small plant whose only freedom is whether a piece
// arrives in each cycle. The Basic Statechart paper [BSC] (docs/references.md) reports a
// reachability analysis of the controlled model (deadlock-free, reinitiable, live); this is the
// same analysis done on the chart that runs.
//
// The plant here is coarser than plant.hpp (which keeps a history of every piece): positions
// P1..P4 hold a piece or not, the belt needs `belt_cycles` cycles to carry a piece to P1, the
// cylinder `arm_cycles` cycles for a full advance. Everything is a small integer or a flag, so
// a state of the closed loop is a few dozen bytes.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "controller.hpp"

namespace cell::finite {

using namespace std::chrono_literals;

inline constexpr bsc::duration period = 500ms;
inline constexpr int belt_cycles = 2;  ///< cycles of belt motion from the input buffer to P1
inline constexpr int arm_cycles = 2;   ///< cycles of valve-on for a full advance (a 90 degree turn)

struct plant {
    bool waiting = false;       ///< a piece is in the input buffer (IN)
    bool carrying = false;      ///< the belt carries a piece towards P1
    std::uint8_t belt_run = 0;  ///< cycles it has been carried
    std::array<bool, 4> at{};   ///< a piece at P1..P4
    std::uint8_t arm = 0;       ///< cycles of advance so far
    bool advanced = false;      ///< the arm is fully advanced (S1)
    bool robot_was_on = false;  ///< the robot ran in the last cycle
    bool empty_turn = false;    ///< the table turned with nothing at P1..P3 (constraint 3)
    bool collision = false;     ///< a piece was put where one already was
};

/// The closed loop: the controller and the plant. Any controller chart over cell::data will do,
/// so the tests can plug in deliberately broken variants.
template <class Chart>
struct loop {
    bsc::machine<Chart, bsc::scan_policy> controller;
    finite::plant plant;
};

/// The plant's sensors, written into the controller's inputs (read at its next cycle).
inline void present(plant const& p, data const& d) {
    d.IN.set(p.waiting);
    d.P1.set(p.at[0]);
    d.P2.set(p.at[1]);
    d.P3.set(p.at[2]);
    d.P4.set(p.at[3]);
    d.S1.set(p.advanced);
}

/// One cycle: the plant presents its sensors, the controller steps, the plant follows the
/// actuators; then a piece arrives at the input buffer if `arrival` says so.
template <class Chart>
void cycle(loop<Chart>& s, bool arrival, bsc::duration now) {
    auto& d = s.controller.context();
    auto& p = s.plant;
    present(p, d);
    s.controller.step(now);
    if (d.belt.get()) {
        if (!p.carrying && p.waiting) {
            p.carrying = true;
            p.waiting = false;
            p.belt_run = 0;
        }
        if (p.carrying && ++p.belt_run >= belt_cycles) {
            p.collision = p.collision || p.at[0];
            p.at[0] = true;
            p.carrying = false;
            p.belt_run = 0;
        }
    }
    if (d.valve.get()) {
        if (!p.advanced && ++p.arm >= arm_cycles) {
            p.empty_turn = p.empty_turn || !(p.at[0] || p.at[1] || p.at[2]);
            p.collision = p.collision || p.at[3];  // P4 would be carried back to P1
            p.at = {false, p.at[0], p.at[1], p.at[2]};
            p.advanced = true;
            p.arm = 0;
        }
    } else {
        p.advanced = false;
        p.arm = 0;
    }
    if (p.robot_was_on && !d.robot.get()) p.at[3] = false;  // stored
    p.robot_was_on = d.robot.get();
    if (arrival) p.waiting = true;
}

inline std::string describe_plant(plant const& p) {
    std::string s = " | IN=" + std::to_string(p.waiting) + " P=";
    for (bool b : p.at) s += b ? '1' : '0';
    return s + (p.advanced ? " S1" : "");
}

/// The explorer's model of the closed loop: two choices per cycle, a piece arrives or not.
/// A shorter scan period means more cycles per timer, hence more states.
template <class Chart>
auto model(Chart const& chart, bsc::duration scan = period) {
    using state = loop<Chart>;
    auto step = [](state& s, std::size_t choice, bsc::duration now) { cycle(s, choice == 1, now); };
    auto describe = [](state const& s) { return s.controller.active_states().joined() + describe_plant(s.plant); };
    auto label = [](std::uint16_t c) { return std::string(c == 1 ? "cycle, a piece arrives" : "cycle"); };
    return bsc::verify::system_model{
        state{bsc::machine<Chart, bsc::scan_policy>{chart, data{}}, plant{}}, scan, 2, step, describe, label};
}

}  // namespace cell::finite
