#pragma once
// The plant models of the production cell: one chart per machine, the paper's environment
// automata (Env_FeedBelt, Env_Table, ...). Each reads its motors from input channels, publishes
// its sensors on output channels, and carries the bricks it holds as data. A brick passes from
// one machine to the next as a signal that lasts one step (`to_table`, `to_arm1`, ...), sent by
// the machine that lets it go; the receiver takes it if it can hold it, and is damaged (the
// brick falls, or lands on another) if it cannot.
//
// Every plant model is a parallel state of regions (its axes of motion, its bricks, its
// sensors) inside a root whose other child is the final state Damage: a violation of a safety
// requirement leaves the parallel state, and the machine halts there.

#include <array>
#include <cstdint>

#include "parts.hpp"

namespace pcell {

// States shared by the plant models (each chart has its own copy of them).
struct Damage;   // a safety requirement was violated: final
struct Sensors;  // the region that publishes the sensors
struct Sensing;

/// The sensors region: whenever a sensor's value differs from what the plant's state says,
/// publish the plant's state. It runs last in each step, after every other region.
template <class Context>
constexpr auto sensor_rows() {
    return bsc::rows(bsc::state<Sensing>[([](Context const& c) { return Context::stale(c); })] /
                     [](Context& c) { Context::publish(c); });
}

// ==== Feed belt ===================================================================================

struct EnvFeedBelt;
struct FeedBeltWorks;
struct FbBelt;
struct FbStill;
struct FbMoving;
struct FbDropping;
struct FbStart;
struct FbReady;

struct feed_belt_io {
    bsc::input<bool> motor;
    bsc::input<brick> put;         // a brick put at the start of the belt (for one step)
    bsc::output<bool> sensor;      // the photoelectric sensor: a brick in the last slot
    bsc::output<bool> start_free;  // the first two slots are empty: a brick may be put on
    bsc::output<brick> to_table;   // the brick falling off the end of the belt (for one step)
    std::array<brick, feed_slots> slots{};
    std::uint8_t fed = 0;  // bricks put on the belt so far

    static constexpr bool stale(feed_belt_io const& c) {
        return c.sensor.pending() != bool(c.slots[feed_slots - 1]) || c.start_free.pending() != start_is_free(c);
    }
    static constexpr void publish(feed_belt_io& c) {
        c.sensor.set(bool(c.slots[feed_slots - 1]));
        c.start_free.set(start_is_free(c));
    }
    static constexpr bool start_is_free(feed_belt_io const& c) { return !c.slots[0] && !c.slots[1]; }
    /// One slot forward; the brick in the last slot, if any, falls off the end.
    static constexpr void advance(feed_belt_io& c) {
        c.to_table.set(c.slots[feed_slots - 1]);
        for (auto i = static_cast<std::size_t>(feed_slots) - 1; i > 0; --i) c.slots[i] = c.slots[i - 1];
        c.slots[0] = brick{};
    }
};

inline constexpr auto env_feed_belt_chart = bsc::make_chart<feed_belt_io>(
    bsc::composite<EnvFeedBelt>(
        bsc::initial<FeedBeltWorks>,
        bsc::parallel<FeedBeltWorks>(
            bsc::composite<FbBelt>(bsc::initial<FbStill>, bsc::state<FbMoving>, bsc::state<FbDropping>),
            bsc::composite<FbStart>(bsc::initial<FbReady>), bsc::composite<Sensors>(bsc::initial<Sensing>)),
        bsc::final_state<Damage>),
    bsc::rows(
        bsc::state<FbStill>[([](feed_belt_io const& c) { return c.motor.get(); })] = bsc::state<FbMoving>,
        bsc::state<FbMoving>[([](feed_belt_io const& c) { return !c.motor.get(); })] = bsc::state<FbStill>,
        bsc::state<FbMoving> +
            bsc::after(belt_slot_time)[([](feed_belt_io const& c) { return bool(c.slots[feed_slots - 1]); })] /
                feed_belt_io::advance = bsc::state<FbDropping>,
        bsc::state<FbMoving> + bsc::after(belt_slot_time) / feed_belt_io::advance = bsc::state<FbMoving>,
        bsc::state<FbDropping> / [](feed_belt_io& c) { c.to_table.set(brick{}); } = bsc::state<FbMoving>,
        // R1: a brick put on another one.
        bsc::state<FbReady>[([](feed_belt_io const& c) { return c.put.get() && c.slots[0]; })] = bsc::state<Damage>,
        bsc::state<FbReady>[([](feed_belt_io const& c) { return bool(c.put.get()); })] /
            [](feed_belt_io& c) {
                c.slots[0] = c.put.get();
                ++c.fed;
            }),
    sensor_rows<feed_belt_io>());

// ==== Elevating rotary table ======================================================================

struct EnvTable;
struct TableWorks;
struct TaLift;
struct LiftStill;
struct LiftUp;
struct LiftDown;
struct TaTurn;
struct TurnStill;
struct TurnOut;
struct TurnBack;
struct TaBrick;
struct TaEmpty;
struct TaLoaded;
struct TaGiving;

struct table_io {
    bsc::input<drive> lift;       // vertical motor
    bsc::input<drive> turn;       // rotation motor
    bsc::input<brick> from_belt;  // a brick falling off the feed belt
    bsc::input<bool> arm1_over;   // the robot's arm1 is extended over the table
    bsc::input<bool> arm1_grips;  // ... at the unloading position, its magnet on, empty
    bsc::output<std::uint8_t> height_sensor;
    bsc::output<std::uint8_t> angle_sensor;
    bsc::output<brick> to_arm1;  // the brick taken by arm1's magnet (for one step)
    std::uint8_t height = 0;
    std::uint8_t angle = 0;
    brick load{};

    static constexpr bool at_loading(table_io const& c) { return c.height == 0 && c.angle == 0; }
    static constexpr bool at_unloading(table_io const& c) { return c.height == table_top && c.angle == table_unload; }
    static constexpr bool stale(table_io const& c) {
        return c.height_sensor.pending() != c.height || c.angle_sensor.pending() != c.angle;
    }
    static constexpr void publish(table_io& c) {
        c.height_sensor.set(c.height);
        c.angle_sensor.set(c.angle);
    }
};

inline constexpr auto table_arm1_over = [](table_io const& c) { return c.arm1_over.get(); };

inline constexpr auto env_table_chart = bsc::make_chart<table_io>(
    bsc::composite<EnvTable>(
        bsc::initial<TableWorks>,
        bsc::parallel<TableWorks>(
            axis_region<TaLift, LiftStill, LiftUp, LiftDown>(), axis_region<TaTurn, TurnStill, TurnOut, TurnBack>(),
            bsc::composite<TaBrick>(bsc::initial<TaEmpty>, bsc::state<TaLoaded>, bsc::state<TaGiving>),
            bsc::composite<Sensors>(bsc::initial<Sensing>)),
        bsc::final_state<Damage>),
    // R2: the table moves into arm1.
    collision_rows<table_io, LiftStill, LiftUp, LiftDown, Damage, &table_io::lift>(table_arm1_over),
    axis_rows<table_io, LiftStill, LiftUp, LiftDown, Damage, &table_io::lift, &table_io::height, table_top>(
        table_step_time),
    collision_rows<table_io, TurnStill, TurnOut, TurnBack, Damage, &table_io::turn>(table_arm1_over),
    axis_rows<table_io, TurnStill, TurnOut, TurnBack, Damage, &table_io::turn, &table_io::angle, table_unload>(
        table_step_time),
    bsc::rows(
        // A brick falls beside the table if it is not at the loading position.
        bsc::state<TaEmpty>[([](table_io const& c) { return c.from_belt.get() && !table_io::at_loading(c); })] =
            bsc::state<Damage>,
        bsc::state<TaEmpty>[([](table_io const& c) { return bool(c.from_belt.get()); })] /
            [](table_io& c) { c.load = c.from_belt.get(); } = bsc::state<TaLoaded>,
        // R1: a second brick on the table.
        bsc::state<TaLoaded>[([](table_io const& c) { return bool(c.from_belt.get()); })] = bsc::state<Damage>,
        bsc::state<TaLoaded>[([](table_io const& c) { return c.arm1_grips.get() && table_io::at_unloading(c); })] /
            [](table_io& c) {
                c.to_arm1.set(c.load);
                c.load = brick{};
            } = bsc::state<TaGiving>,
        bsc::state<TaGiving>[([](table_io const& c) { return bool(c.from_belt.get()); })] = bsc::state<Damage>,
        bsc::state<TaGiving> / [](table_io& c) { c.to_arm1.set(brick{}); } = bsc::state<TaEmpty>),
    sensor_rows<table_io>());

// ==== Robot =======================================================================================

struct EnvRobot;
struct RobotWorks;
struct RoTurn;
struct TurretStill;
struct TurretFwd;
struct TurretRev;
struct RoArm1;
struct Arm1Still;
struct Arm1Out;
struct Arm1In;
struct RoArm2;
struct Arm2Still;
struct Arm2Out;
struct Arm2In;
struct RoMagnet1;
struct Mag1Off;
struct Mag1On;
struct Mag1Holding;
struct Mag1Dropping;
struct RoMagnet2;
struct Mag2Off;
struct Mag2On;
struct Mag2Holding;
struct Mag2Dropping;

struct robot_io {
    bsc::input<drive> turn;  // the rotation of the robot (both arms)
    bsc::input<drive> arm1;  // extension of arm1 (upper level: table to press)
    bsc::input<drive> arm2;  // extension of arm2 (lower level: press to deposit belt)
    bsc::input<bool> magnet1;
    bsc::input<bool> magnet2;
    bsc::input<brick> from_table;  // the brick arm1's magnet took from the table
    bsc::input<brick> from_press;  // the brick arm2's magnet took from the press
    bsc::output<std::uint8_t> angle_sensor;
    bsc::output<std::uint8_t> arm1_sensor;
    bsc::output<std::uint8_t> arm2_sensor;
    bsc::output<bool> arm1_over_table;
    bsc::output<bool> arm1_grips;     // arm1's magnet is on, empty, at the table's unloading position
    bsc::output<bool> arm1_in_press;  // arm1 is extended into the press area
    bsc::output<bool> arm2_in_press;
    bsc::output<bool> arm2_grips;  // arm2's magnet is on, empty, at the press's unloading position
    bsc::output<brick> to_press;   // the brick dropped by arm1 (for one step)
    bsc::output<brick> to_belt;    // the brick dropped by arm2 (for one step)
    std::uint8_t angle = arm2_to_press;
    std::uint8_t ext1 = 0;
    std::uint8_t ext2 = 0;
    brick held1{};
    brick held2{};

    struct readings {
        bool over_table, grips1, in_press1, in_press2, grips2;
    };
    static constexpr readings read(robot_io const& c) {
        return {c.angle == arm1_to_table && c.ext1 > 0,
                c.magnet1.get() && !c.held1 && c.angle == arm1_to_table && c.ext1 == arm1_reach_table,
                c.angle == arm1_to_press && c.ext1 > 0, c.angle == arm2_to_press && c.ext2 > 0,
                c.magnet2.get() && !c.held2 && c.angle == arm2_to_press && c.ext2 == arm2_reach_press};
    }
    static constexpr bool stale(robot_io const& c) {
        auto const r = read(c);
        return c.angle_sensor.pending() != c.angle || c.arm1_sensor.pending() != c.ext1 ||
               c.arm2_sensor.pending() != c.ext2 || c.arm1_over_table.pending() != r.over_table ||
               c.arm1_grips.pending() != r.grips1 || c.arm1_in_press.pending() != r.in_press1 ||
               c.arm2_in_press.pending() != r.in_press2 || c.arm2_grips.pending() != r.grips2;
    }
    static constexpr void publish(robot_io& c) {
        auto const r = read(c);
        c.angle_sensor.set(c.angle);
        c.arm1_sensor.set(c.ext1);
        c.arm2_sensor.set(c.ext2);
        c.arm1_over_table.set(r.over_table);
        c.arm1_grips.set(r.grips1);
        c.arm1_in_press.set(r.in_press1);
        c.arm2_in_press.set(r.in_press2);
        c.arm2_grips.set(r.grips2);
    }
};

inline constexpr auto env_robot_chart = bsc::make_chart<robot_io>(
    bsc::composite<EnvRobot>(
        bsc::initial<RobotWorks>,
        bsc::parallel<RobotWorks>(axis_region<RoTurn, TurretStill, TurretFwd, TurretRev>(),
                                  axis_region<RoArm1, Arm1Still, Arm1Out, Arm1In>(),
                                  axis_region<RoArm2, Arm2Still, Arm2Out, Arm2In>(),
                                  bsc::composite<RoMagnet1>(bsc::initial<Mag1Off>, bsc::state<Mag1On>,
                                                            bsc::state<Mag1Holding>, bsc::state<Mag1Dropping>),
                                  bsc::composite<RoMagnet2>(bsc::initial<Mag2Off>, bsc::state<Mag2On>,
                                                            bsc::state<Mag2Holding>, bsc::state<Mag2Dropping>),
                                  bsc::composite<Sensors>(bsc::initial<Sensing>)),
        bsc::final_state<Damage>),
    // R2: turning with an arm extended sweeps it through the table, the press or the belt.
    collision_rows<robot_io, TurretStill, TurretFwd, TurretRev, Damage, &robot_io::turn>(
        [](robot_io const& c) { return c.ext1 > 0 || c.ext2 > 0; }),
    axis_rows<robot_io, TurretStill, TurretFwd, TurretRev, Damage, &robot_io::turn, &robot_io::angle, robot_limit>(
        robot_turn_time),
    // R2: arm1 extended too far while pointing towards the press hits the press (paper, II).
    bsc::rows(bsc::state<Arm1Out> + bsc::after(arm_step_time)[([](robot_io const& c) {
                  return c.angle == arm1_to_press && c.ext1 >= arm1_reach_press;
              })] = bsc::state<Damage>),
    axis_rows<robot_io, Arm1Still, Arm1Out, Arm1In, Damage, &robot_io::arm1, &robot_io::ext1, arm_limit>(arm_step_time),
    axis_rows<robot_io, Arm2Still, Arm2Out, Arm2In, Damage, &robot_io::arm2, &robot_io::ext2, arm_limit>(arm_step_time),
    bsc::rows(
        // Arm1's magnet: takes a brick from the table, lets it go into the press.
        bsc::state<Mag1Off>[([](robot_io const& c) { return bool(c.from_table.get()); })] =
            bsc::state<Damage>,  // nothing holds the brick: it falls
        bsc::state<Mag1Off>[([](robot_io const& c) { return c.magnet1.get(); })] = bsc::state<Mag1On>,
        bsc::state<Mag1On>[([](robot_io const& c) { return bool(c.from_table.get()); })] /
            [](robot_io& c) { c.held1 = c.from_table.get(); } = bsc::state<Mag1Holding>,
        bsc::state<Mag1On>[([](robot_io const& c) { return !c.magnet1.get(); })] = bsc::state<Mag1Off>,
        bsc::state<Mag1Holding>[([](robot_io const& c) { return bool(c.from_table.get()); })] =
            bsc::state<Damage>,  // R1: two bricks on arm1
        bsc::state<Mag1Holding>[([](robot_io const& c) {
            return !c.magnet1.get() && c.angle == arm1_to_press && c.ext1 == arm1_reach_press;
        })] /
            [](robot_io& c) {
                c.to_press.set(c.held1);
                c.held1 = brick{};
            } = bsc::state<Mag1Dropping>,
        bsc::state<Mag1Holding>[([](robot_io const& c) { return !c.magnet1.get(); })] =
            bsc::state<Damage>,  // let go anywhere else: the brick falls
        bsc::state<Mag1Dropping> / [](robot_io& c) { c.to_press.set(brick{}); } = bsc::state<Mag1Off>,
        // Arm2's magnet: takes a brick from the press, lets it go onto the deposit belt.
        bsc::state<Mag2Off>[([](robot_io const& c) { return bool(c.from_press.get()); })] = bsc::state<Damage>,
        bsc::state<Mag2Off>[([](robot_io const& c) { return c.magnet2.get(); })] = bsc::state<Mag2On>,
        bsc::state<Mag2On>[([](robot_io const& c) { return bool(c.from_press.get()); })] /
            [](robot_io& c) { c.held2 = c.from_press.get(); } = bsc::state<Mag2Holding>,
        bsc::state<Mag2On>[([](robot_io const& c) { return !c.magnet2.get(); })] = bsc::state<Mag2Off>,
        bsc::state<Mag2Holding>[([](robot_io const& c) { return bool(c.from_press.get()); })] =
            bsc::state<Damage>,  // R1: two bricks on arm2
        bsc::state<Mag2Holding>[([](robot_io const& c) {
            return !c.magnet2.get() && c.angle == arm2_to_belt && c.ext2 == arm2_reach_belt;
        })] /
            [](robot_io& c) {
                c.to_belt.set(c.held2);
                c.held2 = brick{};
            } = bsc::state<Mag2Dropping>,
        bsc::state<Mag2Holding>[([](robot_io const& c) { return !c.magnet2.get(); })] = bsc::state<Damage>,
        bsc::state<Mag2Dropping> / [](robot_io& c) { c.to_belt.set(brick{}); } = bsc::state<Mag2Off>),
    sensor_rows<robot_io>());

// ==== Press =======================================================================================

struct EnvPress;
struct PressWorks;
struct PrPlate;
struct PlateStill;
struct PlateUp;
struct PlateDown;
struct PrBrick;
struct PrEmpty;
struct PrLoaded;
struct PrGiving;

struct press_io {
    bsc::input<drive> plate;      // the plate's motor
    bsc::input<bool> arm1_in;     // arm1 is extended into the press area
    bsc::input<bool> arm2_in;     // arm2 likewise
    bsc::input<brick> from_arm1;  // a brick dropped by arm1
    bsc::input<bool> arm2_grips;  // arm2's magnet is on, empty, at the unloading position
    bsc::output<std::uint8_t> plate_sensor;
    bsc::output<brick> to_arm2;  // the brick taken by arm2's magnet (for one step)
    std::uint8_t level = press_middle;
    brick load{};

    static constexpr bool stale(press_io const& c) { return c.plate_sensor.pending() != c.level; }
    static constexpr void publish(press_io& c) { c.plate_sensor.set(c.level); }
};

inline constexpr auto env_press_chart = bsc::make_chart<press_io>(
    bsc::composite<EnvPress>(
        bsc::initial<PressWorks>,
        bsc::parallel<PressWorks>(
            axis_region<PrPlate, PlateStill, PlateUp, PlateDown>(),
            bsc::composite<PrBrick>(bsc::initial<PrEmpty>, bsc::state<PrLoaded>, bsc::state<PrGiving>),
            bsc::composite<Sensors>(bsc::initial<Sensing>)),
        bsc::final_state<Damage>),
    // R2: the plate moves while an arm is in the press.
    collision_rows<press_io, PlateStill, PlateUp, PlateDown, Damage, &press_io::plate>(
        [](press_io const& c) { return c.arm1_in.get() || c.arm2_in.get(); }),
    axis_rows<press_io, PlateStill, PlateUp, PlateDown, Damage, &press_io::plate, &press_io::level, press_top>(
        press_step_time),
    bsc::rows(
        // A brick falls if the plate is not at arm1's level.
        bsc::state<PrEmpty>[([](press_io const& c) { return c.from_arm1.get() && c.level != press_middle; })] =
            bsc::state<Damage>,
        bsc::state<PrEmpty>[([](press_io const& c) { return bool(c.from_arm1.get()); })] /
            [](press_io& c) { c.load = c.from_arm1.get(); } = bsc::state<PrLoaded>,
        // R1: a second brick in the press.
        bsc::state<PrLoaded>[([](press_io const& c) { return bool(c.from_arm1.get()); })] = bsc::state<Damage>,
        // The plate at the top forges the brick.
        bsc::state<PrLoaded>[([](press_io const& c) { return c.level == press_top && !c.load.forged; })] /
            [](press_io& c) { c.load.forged = true; },
        bsc::state<PrLoaded>[([](press_io const& c) { return c.arm2_grips.get() && c.level == press_bottom; })] /
            [](press_io& c) {
                c.to_arm2.set(c.load);
                c.load = brick{};
            } = bsc::state<PrGiving>,
        bsc::state<PrGiving>[([](press_io const& c) { return bool(c.from_arm1.get()); })] = bsc::state<Damage>,
        bsc::state<PrGiving> / [](press_io& c) { c.to_arm2.set(brick{}); } = bsc::state<PrEmpty>),
    sensor_rows<press_io>());

// ==== Deposit belt ================================================================================

struct EnvDepositBelt;
struct DepositBeltWorks;
struct DbBelt;
struct DbStill;
struct DbMoving;
struct DbStart;
struct DbReady;

struct deposit_belt_io {
    bsc::input<bool> motor;
    bsc::input<brick> from_arm2;  // a brick dropped by arm2 onto the start of the belt
    std::array<brick, deposit_slots> slots{};
    std::uint8_t delivered = 0;  // bricks that have left the cell at the end of the belt
    std::uint8_t unforged = 0;   // ... of which were not forged
    brick last{};                // the last brick that left

    /// One slot forward; the brick in the last slot leaves the cell.
    static constexpr void advance(deposit_belt_io& c) {
        if (auto const out = c.slots[deposit_slots - 1]) {
            ++c.delivered;
            c.unforged = static_cast<std::uint8_t>(c.unforged + (out.forged ? 0 : 1));
            c.last = out;
        }
        for (auto i = static_cast<std::size_t>(deposit_slots) - 1; i > 0; --i) c.slots[i] = c.slots[i - 1];
        c.slots[0] = brick{};
    }
};

inline constexpr auto env_deposit_belt_chart = bsc::make_chart<deposit_belt_io>(
    bsc::composite<EnvDepositBelt>(
        bsc::initial<DepositBeltWorks>,
        bsc::parallel<DepositBeltWorks>(bsc::composite<DbBelt>(bsc::initial<DbStill>, bsc::state<DbMoving>),
                                        bsc::composite<DbStart>(bsc::initial<DbReady>)),
        bsc::final_state<Damage>),
    bsc::rows(
        bsc::state<DbStill>[([](deposit_belt_io const& c) { return c.motor.get(); })] = bsc::state<DbMoving>,
        bsc::state<DbMoving>[([](deposit_belt_io const& c) { return !c.motor.get(); })] = bsc::state<DbStill>,
        bsc::state<DbMoving> + bsc::after(belt_slot_time) / deposit_belt_io::advance = bsc::state<DbMoving>,
        // R1: a brick dropped onto another one.
        bsc::state<DbReady>[([](deposit_belt_io const& c) { return c.from_arm2.get() && c.slots[0]; })] =
            bsc::state<Damage>,
        bsc::state<DbReady>[([](deposit_belt_io const& c) { return bool(c.from_arm2.get()); })] /
            [](deposit_belt_io& c) { c.slots[0] = c.from_arm2.get(); }));

using feed_belt_plant = bsc::machine<bsc::chart_ref<env_feed_belt_chart>>;
using table_plant = bsc::machine<bsc::chart_ref<env_table_chart>>;
using robot_plant = bsc::machine<bsc::chart_ref<env_robot_chart>>;
using press_plant = bsc::machine<bsc::chart_ref<env_press_chart>>;
using deposit_belt_plant = bsc::machine<bsc::chart_ref<env_deposit_belt_chart>>;

}  // namespace pcell
