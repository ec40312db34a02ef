#pragma once
// Parts shared by the charts of the production cell: the brick, the motor commands, the
// timing of the cell, an axis of motion for the plant models, and make_chart over groups of
// rows. See cell.hpp for how the paper maps to the code.

#include <chrono>
#include <cstdint>
#include <tuple>

#include <bsc/bsc.hpp>

namespace pcell {

using namespace std::chrono_literals;

/// A metal brick as data: `id` 0 means "no brick"; the press sets `forged`.
struct brick {
    std::uint8_t id = 0;
    bool forged = false;
    constexpr explicit operator bool() const { return id != 0; }
    friend constexpr bool operator==(brick const&, brick const&) = default;
};

/// A motor command, sent by a controller to a plant model: drive towards the higher end of
/// the axis (`fwd`), towards position 0 (`rev`), or stop. (The belts' motors are on or off.)
using drive = std::int8_t;
inline constexpr drive stop = 0;
inline constexpr drive fwd = 1;
inline constexpr drive rev = -1;

// ---- Timing ---------------------------------------------------------------------------------
// The cell is stepped every `period`. Every movement of the plant takes at least two periods,
// so a controller that reacts to a sensor in the next step is always in time.

inline constexpr auto period = 100ms;

inline constexpr auto belt_slot_time = 300ms;         // a belt moves a brick by one slot
inline constexpr auto table_step_time = 200ms;        // the table lifts or turns by one step
inline constexpr auto robot_turn_time = 300ms;        // the robot turns from one stop to the next
inline constexpr auto arm_step_time = 200ms;          // an arm extends or retracts by one step
inline constexpr auto press_step_time = 300ms;        // the plate moves from one level to the next
inline constexpr auto grip_time = 300ms;              // an electromagnet takes hold of a brick
inline constexpr auto release_time = 300ms;           // ... and lets it go
inline constexpr auto deposit_clear_time = 600ms;     // the deposit belt moves a dropped brick on
inline constexpr auto deposit_run_out_time = 1200ms;  // ... then runs until it is surely empty

// ---- Positions ------------------------------------------------------------------------------

inline constexpr std::uint8_t feed_slots = 4;     // slot 3 is under the photoelectric sensor
inline constexpr std::uint8_t deposit_slots = 3;  // a brick dropped by arm2 lands in slot 0

inline constexpr std::uint8_t table_top = 2;     // vertical: 0 (feed belt level) .. 2 (arm1 level)
inline constexpr std::uint8_t table_unload = 2;  // rotation: 0 (facing the belt) .. 2 (45 degrees)
inline constexpr std::uint8_t press_bottom = 0;  // the plate: unloaded by arm2
inline constexpr std::uint8_t press_middle = 1;  // loaded by arm1
inline constexpr std::uint8_t press_top = 2;     // forging
inline constexpr std::uint8_t arm_limit = 2;     // an arm extends from 0 to 2

/// The four stops of the robot's rotation, in the order it passes them.
inline constexpr std::uint8_t arm1_to_table = 0;
inline constexpr std::uint8_t arm2_to_press = 1;  // the default position (paper, section II)
inline constexpr std::uint8_t arm2_to_belt = 2;
inline constexpr std::uint8_t arm1_to_press = 3;
inline constexpr std::uint8_t robot_limit = 3;

/// How far each arm extends for each of its jobs.
inline constexpr std::uint8_t arm1_reach_table = 2;
inline constexpr std::uint8_t arm1_reach_press = 1;  // any further and arm1 hits the press
inline constexpr std::uint8_t arm2_reach_press = 1;
inline constexpr std::uint8_t arm2_reach_belt = 2;

// ---- Charts from groups of rows ---------------------------------------------------------------

// ---- An axis of motion --------------------------------------------------------------------
// A motor (input channel `Motor` of the context: fwd, rev or stop) drives a position (plain
// variable `Position`) between 0 and `Limit`, one unit per `step`. Driving past either end
// breaks the machine (`Damage`): the mechanical limit of requirement R3. The region has three
// states: Still, Fwd (moving towards Limit) and Rev (moving towards 0).

template <class Region, class Still, class Fwd, class Rev>
constexpr auto axis_region() {
    return bsc::composite<Region>(bsc::initial<Still>, bsc::state<Fwd>, bsc::state<Rev>);
}

template <class Context, class Still, class Fwd, class Rev, class Damage, auto Motor, auto Position, std::uint8_t Limit,
          class Step>
constexpr auto axis_rows(Step step) {
    return bsc::rows(
        bsc::state<Still>[([](Context const& c) { return (c.*Motor).get() == fwd; })] = bsc::state<Fwd>,
        bsc::state<Still>[([](Context const& c) { return (c.*Motor).get() == rev; })] = bsc::state<Rev>,
        bsc::state<Fwd>[([](Context const& c) { return (c.*Motor).get() == stop; })] = bsc::state<Still>,
        bsc::state<Fwd>[([](Context const& c) { return (c.*Motor).get() == rev; })] = bsc::state<Rev>,
        bsc::state<Fwd> +
            bsc::after(step)[([](Context const& c) { return c.*Position >= Limit; })] = bsc::state<Damage>,
        bsc::state<Fwd> + bsc::after(step) / [](Context& c) { ++(c.*Position); } = bsc::state<Fwd>,
        bsc::state<Rev>[([](Context const& c) { return (c.*Motor).get() == stop; })] = bsc::state<Still>,
        bsc::state<Rev>[([](Context const& c) { return (c.*Motor).get() == fwd; })] = bsc::state<Fwd>,
        bsc::state<Rev> + bsc::after(step)[([](Context const& c) { return c.*Position == 0; })] = bsc::state<Damage>,
        bsc::state<Rev> + bsc::after(step) / [](Context& c) { --(c.*Position); } = bsc::state<Rev>);
}

/// Rows to put before an axis's own: moving the axis while `blocked` holds (something is in its
/// way) breaks the machine, and so does starting it.
template <class Context, class Still, class Fwd, class Rev, class Damage, auto Motor, class Blocked>
constexpr auto collision_rows(Blocked blocked) {
    auto const starting = [](Context const& c) { return (c.*Motor).get() != stop; };
    return bsc::rows(bsc::state<Fwd>[blocked] = bsc::state<Damage>,  //
                     bsc::state<Rev>[blocked] = bsc::state<Damage>,  //
                     bsc::state<Still>[bsc::guard(blocked) && starting] = bsc::state<Damage>);
}

}  // namespace pcell
