#pragma once
// The controller actors of the production cell, one per machine, each built like the paper's
// Table actor (Fig. 3.2, 3.3): a top-level supervisor with the states Off and On, switched by
// the manual on/off switch, and inside On the second-level controller of the machine. In Off
// the machine's motors are off (the exit actions of On); On remembers where it was (history),
// so switching off and on again resumes the work. The second-level controllers set their
// outputs in the entry actions of their states, like the paper's modal function blocks, whose
// mode is the state.
//
// Actors talk to each other with global signals (levels) in a four-phase handshake: the
// receiver raises `ready`, the sender does its part and raises `done`, the receiver lowers
// `ready` and the sender lowers `done`. The receiver raises `ready` (by a transition inside its
// waiting state, not by the state's entry action, which history would run again) only once the
// sender's `done` of the previous round is low, and takes `done` only while its own `ready` is
// published, so that a partner's signal seen late (a slow or lost peer of a distributed cell) is
// never taken for the next round. A signal is lowered by the transition that completes its phase, not by an
// exit action: switching a controller off (which exits every state inside On) leaves its signals
// as they are, so a partner waits for it instead of reading a lowered signal as the next phase,
// and the handshake resumes when it is switched on again.
//
// The paper names no guard or action. For the diagrams of the actors (docs/composition.md),
// each is named (bsc::named) after what it reads or writes: a guard after the signals it tests
// ("table_ready", "angle == table_unload"), an action after the outputs and variables it sets
// ("motor=0, fed=1"; 1 and 0 for true and false).

#include <cstdint>

#include "parts.hpp"

namespace pcell {

// The top-level supervisor's states, the same in every controller.
struct Off;
struct On;

// The supervisor's switch, the same in every controller: On while the manual switch is on.
inline constexpr auto switched_on = bsc::named<"on">(bsc::guard([](auto const& c) { return c.on.get(); }));

// ==== Feed belt actor ==============================================================================

struct FeedBeltActor;
struct FbRun;   // transporting
struct FbWait;  // a brick at the end of the belt, the table not ready
struct FbFeed;  // the brick goes onto the table
struct FbFed;   // handshake with the table actor

struct feed_belt_ctl {
    bsc::input<bool> on;           // the manual on/off switch
    bsc::input<bool> sensor;       // the photoelectric sensor at the end of the belt
    bsc::input<bool> table_ready;  // table actor: ready for feed
    bsc::output<bool> motor;
    bsc::output<bool> fed;  // to the table actor: a brick is on the table
};

inline constexpr auto feed_belt_chart = bsc::make_chart<feed_belt_ctl>(
    bsc::composite<FeedBeltActor>(bsc::initial<Off>,
                                  bsc::composite<On>(bsc::shallow_history, bsc::initial<FbRun>, bsc::state<FbWait>,
                                                     bsc::state<FbFeed>, bsc::state<FbFed>)),
    bsc::state<Off>[switched_on] = bsc::state<On>, bsc::state<On>[!switched_on] = bsc::state<Off>,
    bsc::state<On> + bsc::on_exit / bsc::named<"motor=0">([](feed_belt_ctl& c) { c.motor.set(false); }),
    bsc::state<FbRun> + bsc::on_entry / bsc::named<"motor=1">([](feed_belt_ctl& c) { c.motor.set(true); }),
    bsc::state<FbRun>[bsc::named<"sensor">([](feed_belt_ctl const& c) { return c.sensor.get(); })] = bsc::state<FbWait>,
    bsc::state<FbWait> + bsc::on_entry / bsc::named<"motor=0">([](feed_belt_ctl& c) { c.motor.set(false); }),
    bsc::state<FbWait>[bsc::named<"table_ready">([](feed_belt_ctl const& c) { return c.table_ready.get(); })] =
        bsc::state<FbFeed>,
    bsc::state<FbFeed> + bsc::on_entry / bsc::named<"motor=1">([](feed_belt_ctl& c) { c.motor.set(true); }),
    bsc::state<FbFeed>[bsc::named<"!sensor">([](feed_belt_ctl const& c) { return !c.sensor.get(); })] =
        bsc::state<FbFed>,
    bsc::state<FbFed> + bsc::on_entry / bsc::named<"motor=0, fed=1">([](feed_belt_ctl& c) {
                            c.motor.set(false);
                            c.fed.set(true);
                        }),
    bsc::state<FbFed>[bsc::named<"!table_ready">([](feed_belt_ctl const& c) { return !c.table_ready.get(); })] /
        bsc::named<"fed=0">([](feed_belt_ctl& c) { c.fed.set(false); }) = bsc::state<FbRun>);

// ==== Table actor =================================================================================

struct TableActor;
struct TbLoad;    // at the feed belt, ready for feed
struct TbRise;    // lifting to arm1's level
struct TbTurn;    // turning to arm1
struct TbUnload;  // ready for arm1
struct TbReturn;  // turning back
struct TbLower;   // lowering to the feed belt

struct table_ctl {
    bsc::input<bool> on;
    bsc::input<std::uint8_t> height;  // the vertical position sensor
    bsc::input<std::uint8_t> angle;   // the rotation sensor
    bsc::input<bool> fed;             // feed belt actor: a brick is on the table
    bsc::input<bool> taken;           // robot actor: arm1 took the brick and is clear of the table
    bsc::output<drive> lift;
    bsc::output<drive> turn;
    bsc::output<bool> ready_for_feed;    // to the feed belt actor
    bsc::output<bool> ready_for_unload;  // to the robot actor
};

inline constexpr auto table_chart = bsc::make_chart<table_ctl>(
    bsc::composite<TableActor>(bsc::initial<Off>,
                               bsc::composite<On>(bsc::shallow_history, bsc::initial<TbLoad>, bsc::state<TbRise>,
                                                  bsc::state<TbTurn>, bsc::state<TbUnload>, bsc::state<TbReturn>,
                                                  bsc::state<TbLower>)),
    bsc::state<Off>[switched_on] = bsc::state<On>, bsc::state<On>[!switched_on] = bsc::state<Off>,
    bsc::state<On> + bsc::on_exit / bsc::named<"lift=stop, turn=stop">([](table_ctl& c) {
                         c.lift.set(stop);
                         c.turn.set(stop);
                     }),
    bsc::state<TbLoad> + bsc::on_entry / bsc::named<"lift=stop">([](table_ctl& c) { c.lift.set(stop); }),
    bsc::state<TbLoad>[bsc::named<"!fed && !ready_for_feed">(
        [](table_ctl const& c) { return !c.fed.get() && !c.ready_for_feed.pending(); })] /
        bsc::named<"ready_for_feed=1">([](table_ctl& c) { c.ready_for_feed.set(true); }),
    bsc::state<TbLoad>[bsc::named<"fed && ready_for_feed">(
        [](table_ctl const& c) { return c.fed.get() && c.ready_for_feed.get(); })] /
        bsc::named<"ready_for_feed=0">([](table_ctl& c) { c.ready_for_feed.set(false); }) = bsc::state<TbRise>,
    bsc::state<TbRise> + bsc::on_entry / bsc::named<"lift=fwd">([](table_ctl& c) { c.lift.set(fwd); }),
    bsc::state<TbRise>[bsc::named<"height == table_top">(
        [](table_ctl const& c) { return c.height.get() == table_top; })] = bsc::state<TbTurn>,
    bsc::state<TbTurn> + bsc::on_entry / bsc::named<"lift=stop, turn=fwd">([](table_ctl& c) {
                             c.lift.set(stop);
                             c.turn.set(fwd);
                         }),
    bsc::state<TbTurn>[bsc::named<"angle == table_unload">(
        [](table_ctl const& c) { return c.angle.get() == table_unload; })] = bsc::state<TbUnload>,
    bsc::state<TbUnload> + bsc::on_entry / bsc::named<"turn=stop">([](table_ctl& c) { c.turn.set(stop); }),
    bsc::state<TbUnload>[bsc::named<"!taken && !ready_for_unload">(
        [](table_ctl const& c) { return !c.taken.get() && !c.ready_for_unload.pending(); })] /
        bsc::named<"ready_for_unload=1">([](table_ctl& c) { c.ready_for_unload.set(true); }),
    bsc::state<TbUnload>[bsc::named<"taken && ready_for_unload">(
        [](table_ctl const& c) { return c.taken.get() && c.ready_for_unload.get(); })] /
        bsc::named<"ready_for_unload=0">([](table_ctl& c) { c.ready_for_unload.set(false); }) = bsc::state<TbReturn>,
    bsc::state<TbReturn> + bsc::on_entry / bsc::named<"turn=rev">([](table_ctl& c) { c.turn.set(rev); }),
    bsc::state<TbReturn>[bsc::named<"angle == 0">([](table_ctl const& c) { return c.angle.get() == 0; })] =
        bsc::state<TbLower>,
    bsc::state<TbLower> + bsc::on_entry / bsc::named<"turn=stop, lift=rev">([](table_ctl& c) {
                              c.turn.set(stop);
                              c.lift.set(rev);
                          }),
    bsc::state<TbLower>[bsc::named<"height == 0">([](table_ctl const& c) { return c.height.get() == 0; })] =
        bsc::state<TbLoad>);

// ==== Robot actor =================================================================================
// Three regions: the turret chooses the next stop and turns the robot there; each arm does its
// own work cycle when the turret is parked at one of its stops. The arms are independent: arm1
// may hold a brick while arm2 carries another (the efficiency question of section V).

struct RobotActor;
struct RobotWork;
struct Turret;
struct TuIdle;  // choosing the next job
struct TuTurn;  // turning to the job's stop
struct TuPark;  // at the stop, the arm works
struct Arm1Job;
struct A1Empty;
struct A1Reach;     // extending over the table
struct A1Grip;      // magnet on
struct A1Lift;      // retracting with the brick
struct A1Handover;  // handshake with the table actor
struct A1Full;      // carrying a brick
struct A1Insert;    // extending into the press
struct A1Release;   // magnet off: the brick is in the press
struct A1Withdraw;  // retracting from the press
struct A1Loaded;    // handshake with the press actor
struct Arm2Job;
struct A2Empty;
struct A2Reach;  // extending into the press
struct A2Grip;
struct A2Withdraw;  // retracting with the forged brick
struct A2Handover;  // handshake with the press actor
struct A2Full;
struct A2Extend;  // extending over the deposit belt
struct A2Release;
struct A2Back;
struct A2Dropped;  // handshake with the deposit belt actor

/// What the robot does at its current stop.
enum class job : std::uint8_t { none, pick, unload, deposit, load };

struct robot_ctl {
    bsc::input<bool> on;
    bsc::input<std::uint8_t> angle;       // the rotation sensor
    bsc::input<std::uint8_t> ext1;        // arm1's extension sensor
    bsc::input<std::uint8_t> ext2;        // arm2's extension sensor
    bsc::input<bool> table_ready;         // table actor: a brick at arm1's level
    bsc::input<bool> press_load_ready;    // press actor: empty, plate at arm1's level
    bsc::input<bool> press_unload_ready;  // press actor: a forged brick at arm2's level
    bsc::input<bool> belt_ready;          // deposit belt actor: a brick may be dropped
    bsc::output<drive> turn;
    bsc::output<drive> arm1;
    bsc::output<drive> arm2;
    bsc::output<bool> magnet1;
    bsc::output<bool> magnet2;
    bsc::output<bool> taken;           // to the table actor: arm1 took the brick and is clear
    bsc::output<bool> press_loaded;    // to the press actor: arm1 let the brick go in the press
    bsc::output<bool> press_unloaded;  // to the press actor: arm2 took the forged brick
    bsc::output<bool> dropped;         // to the deposit belt actor: arm2 dropped a brick
    job task = job::none;              // the job at the current stop
    std::uint8_t target = arm2_to_press;
    bool parked = false;  // the turret stands at the stop of `task`
    bool arm1_full = false;
    bool arm2_full = false;

    static constexpr drive toward(std::uint8_t from, std::uint8_t to) {
        return to > from ? fwd : to < from ? rev : stop;
    }
    static constexpr bool at(robot_ctl const& c, job j) { return c.parked && c.task == j; }
};

/// An action choosing the turret's next job and stop.
template <job J, std::uint8_t Stop>
inline constexpr auto go_for = [](robot_ctl& c) {
    c.task = J;
    c.target = Stop;
};

inline constexpr auto robot_chart = bsc::make_chart<robot_ctl>(
    bsc::composite<RobotActor>(
        bsc::initial<Off>,
        bsc::composite<On>(bsc::deep_history, bsc::initial<RobotWork>,
                           bsc::parallel<RobotWork>(
                               bsc::composite<Turret>(bsc::initial<TuIdle>, bsc::state<TuTurn>, bsc::state<TuPark>),
                               bsc::composite<Arm1Job>(bsc::initial<A1Empty>, bsc::state<A1Reach>, bsc::state<A1Grip>,
                                                       bsc::state<A1Lift>, bsc::state<A1Handover>, bsc::state<A1Full>,
                                                       bsc::state<A1Insert>, bsc::state<A1Release>,
                                                       bsc::state<A1Withdraw>, bsc::state<A1Loaded>),
                               bsc::composite<Arm2Job>(bsc::initial<A2Empty>, bsc::state<A2Reach>, bsc::state<A2Grip>,
                                                       bsc::state<A2Withdraw>, bsc::state<A2Handover>,
                                                       bsc::state<A2Full>, bsc::state<A2Extend>, bsc::state<A2Release>,
                                                       bsc::state<A2Back>, bsc::state<A2Dropped>)))),
    bsc::state<Off>[switched_on] = bsc::state<On>, bsc::state<On>[!switched_on] = bsc::state<Off>,
    bsc::state<On> + bsc::on_exit / bsc::named<"turn=stop, arm1=stop, arm2=stop">([](robot_ctl& c) {
                         c.turn.set(stop);
                         c.arm1.set(stop);
                         c.arm2.set(stop);
                     }),
    // The turret: first get rid of a forged brick, then fetch one from the press, then load the
    // press, then fetch a brick from the table.
    bsc::state<TuIdle>[bsc::named<"arm2_full && belt_ready">(
        [](robot_ctl const& c) { return c.arm2_full && c.belt_ready.get(); })] /
        bsc::named<"task=deposit, target=arm2_to_belt">(go_for<job::deposit, arm2_to_belt>) = bsc::state<TuTurn>,
    bsc::state<TuIdle>[bsc::named<"!arm2_full && press_unload_ready">(
        [](robot_ctl const& c) { return !c.arm2_full && c.press_unload_ready.get(); })] /
        bsc::named<"task=unload, target=arm2_to_press">(go_for<job::unload, arm2_to_press>) = bsc::state<TuTurn>,
    bsc::state<TuIdle>[bsc::named<"arm1_full && press_load_ready">(
        [](robot_ctl const& c) { return c.arm1_full && c.press_load_ready.get(); })] /
        bsc::named<"task=load, target=arm1_to_press">(go_for<job::load, arm1_to_press>) = bsc::state<TuTurn>,
    bsc::state<TuIdle>[bsc::named<"!arm1_full && table_ready">(
        [](robot_ctl const& c) { return !c.arm1_full && c.table_ready.get(); })] /
        bsc::named<"task=pick, target=arm1_to_table">(go_for<job::pick, arm1_to_table>) = bsc::state<TuTurn>,
    bsc::state<TuTurn> + bsc::on_entry / bsc::named<"turn=toward(target)">([](robot_ctl& c) {
                             c.turn.set(robot_ctl::toward(c.angle.get(), c.target));
                         }),
    bsc::state<TuTurn>[bsc::named<"angle == target">([](robot_ctl const& c) { return c.angle.get() == c.target; })] =
        bsc::state<TuPark>,
    bsc::state<TuPark> + bsc::on_entry / bsc::named<"turn=stop, parked=1">([](robot_ctl& c) {
                             c.turn.set(stop);
                             c.parked = true;
                         }),
    bsc::state<TuPark>[bsc::named<"task == none">([](robot_ctl const& c) { return c.task == job::none; })] =
        bsc::state<TuIdle>,
    bsc::state<TuPark> + bsc::on_exit / bsc::named<"parked=0">([](robot_ctl& c) { c.parked = false; }),
    // Arm1: from the table to the press.
    bsc::state<A1Empty>[bsc::named<"at(pick)">([](robot_ctl const& c) { return robot_ctl::at(c, job::pick); })] =
        bsc::state<A1Reach>,
    bsc::state<A1Reach> + bsc::on_entry / bsc::named<"arm1=fwd">([](robot_ctl& c) { c.arm1.set(fwd); }),
    bsc::state<A1Reach>[bsc::named<"ext1 == arm1_reach_table">(
        [](robot_ctl const& c) { return c.ext1.get() == arm1_reach_table; })] = bsc::state<A1Grip>,
    bsc::state<A1Grip> + bsc::on_entry / bsc::named<"arm1=stop, magnet1=1">([](robot_ctl& c) {
                             c.arm1.set(stop);
                             c.magnet1.set(true);
                         }),
    bsc::state<A1Grip> + bsc::after(grip_time) = bsc::state<A1Lift>,
    bsc::state<A1Lift> + bsc::on_entry / bsc::named<"arm1=rev">([](robot_ctl& c) { c.arm1.set(rev); }),
    bsc::state<A1Lift>[bsc::named<"ext1 == 0">([](robot_ctl const& c) { return c.ext1.get() == 0; })] /
        bsc::named<"task=none, arm1_full=1">([](robot_ctl& c) {
            c.task = job::none;
            c.arm1_full = true;
        }) = bsc::state<A1Handover>,
    bsc::state<A1Handover> + bsc::on_entry / bsc::named<"arm1=stop, taken=1">([](robot_ctl& c) {
                                 c.arm1.set(stop);
                                 c.taken.set(true);
                             }),
    bsc::state<A1Handover>[bsc::named<"!table_ready">([](robot_ctl const& c) { return !c.table_ready.get(); })] /
        bsc::named<"taken=0">([](robot_ctl& c) { c.taken.set(false); }) = bsc::state<A1Full>,
    bsc::state<A1Full>[bsc::named<"at(load)">([](robot_ctl const& c) { return robot_ctl::at(c, job::load); })] =
        bsc::state<A1Insert>,
    bsc::state<A1Insert> + bsc::on_entry / bsc::named<"arm1=fwd">([](robot_ctl& c) { c.arm1.set(fwd); }),
    bsc::state<A1Insert>[bsc::named<"ext1 == arm1_reach_press">(
        [](robot_ctl const& c) { return c.ext1.get() == arm1_reach_press; })] = bsc::state<A1Release>,
    bsc::state<A1Release> +
        bsc::on_entry / bsc::named<"arm1=stop, magnet1=0, press_loaded=1, arm1_full=0">([](robot_ctl& c) {
            c.arm1.set(stop);
            c.magnet1.set(false);
            c.press_loaded.set(true);
            c.arm1_full = false;
        }),
    bsc::state<A1Release> + bsc::after(release_time) = bsc::state<A1Withdraw>,
    bsc::state<A1Withdraw> + bsc::on_entry / bsc::named<"arm1=rev">([](robot_ctl& c) { c.arm1.set(rev); }),
    bsc::state<A1Withdraw>[bsc::named<"ext1 == 0">([](robot_ctl const& c) { return c.ext1.get() == 0; })] /
        bsc::named<"task=none">([](robot_ctl& c) { c.task = job::none; }) = bsc::state<A1Loaded>,
    bsc::state<A1Loaded> + bsc::on_entry / bsc::named<"arm1=stop">([](robot_ctl& c) { c.arm1.set(stop); }),
    bsc::state<A1Loaded>[bsc::named<"!press_load_ready">(
        [](robot_ctl const& c) { return !c.press_load_ready.get(); })] /
        bsc::named<"press_loaded=0">([](robot_ctl& c) { c.press_loaded.set(false); }) = bsc::state<A1Empty>,
    // Arm2: from the press to the deposit belt.
    bsc::state<A2Empty>[bsc::named<"at(unload)">([](robot_ctl const& c) { return robot_ctl::at(c, job::unload); })] =
        bsc::state<A2Reach>,
    bsc::state<A2Reach> + bsc::on_entry / bsc::named<"arm2=fwd">([](robot_ctl& c) { c.arm2.set(fwd); }),
    bsc::state<A2Reach>[bsc::named<"ext2 == arm2_reach_press">(
        [](robot_ctl const& c) { return c.ext2.get() == arm2_reach_press; })] = bsc::state<A2Grip>,
    bsc::state<A2Grip> + bsc::on_entry / bsc::named<"arm2=stop, magnet2=1">([](robot_ctl& c) {
                             c.arm2.set(stop);
                             c.magnet2.set(true);
                         }),
    bsc::state<A2Grip> + bsc::after(grip_time) = bsc::state<A2Withdraw>,
    bsc::state<A2Withdraw> + bsc::on_entry / bsc::named<"arm2=rev, press_unloaded=1">([](robot_ctl& c) {
                                 c.arm2.set(rev);
                                 c.press_unloaded.set(true);
                             }),
    bsc::state<A2Withdraw>[bsc::named<"ext2 == 0">([](robot_ctl const& c) { return c.ext2.get() == 0; })] /
        bsc::named<"task=none, arm2_full=1">([](robot_ctl& c) {
            c.task = job::none;
            c.arm2_full = true;
        }) = bsc::state<A2Handover>,
    bsc::state<A2Handover> + bsc::on_entry / bsc::named<"arm2=stop">([](robot_ctl& c) { c.arm2.set(stop); }),
    bsc::state<A2Handover>[bsc::named<"!press_unload_ready">(
        [](robot_ctl const& c) { return !c.press_unload_ready.get(); })] /
        bsc::named<"press_unloaded=0">([](robot_ctl& c) { c.press_unloaded.set(false); }) = bsc::state<A2Full>,
    bsc::state<A2Full>[bsc::named<"at(deposit)">([](robot_ctl const& c) { return robot_ctl::at(c, job::deposit); })] =
        bsc::state<A2Extend>,
    bsc::state<A2Extend> + bsc::on_entry / bsc::named<"arm2=fwd">([](robot_ctl& c) { c.arm2.set(fwd); }),
    bsc::state<A2Extend>[bsc::named<"ext2 == arm2_reach_belt">(
        [](robot_ctl const& c) { return c.ext2.get() == arm2_reach_belt; })] = bsc::state<A2Release>,
    bsc::state<A2Release> +
        bsc::on_entry / bsc::named<"arm2=stop, magnet2=0, dropped=1, arm2_full=0">([](robot_ctl& c) {
            c.arm2.set(stop);
            c.magnet2.set(false);
            c.dropped.set(true);
            c.arm2_full = false;
        }),
    bsc::state<A2Release> + bsc::after(release_time) = bsc::state<A2Back>,
    bsc::state<A2Back> + bsc::on_entry / bsc::named<"arm2=rev">([](robot_ctl& c) { c.arm2.set(rev); }),
    bsc::state<A2Back>[bsc::named<"ext2 == 0">([](robot_ctl const& c) { return c.ext2.get() == 0; })] /
        bsc::named<"task=none">([](robot_ctl& c) { c.task = job::none; }) = bsc::state<A2Dropped>,
    bsc::state<A2Dropped> + bsc::on_entry / bsc::named<"arm2=stop">([](robot_ctl& c) { c.arm2.set(stop); }),
    bsc::state<A2Dropped>[bsc::named<"!belt_ready">([](robot_ctl const& c) { return !c.belt_ready.get(); })] /
        bsc::named<"dropped=0">([](robot_ctl& c) { c.dropped.set(false); }) = bsc::state<A2Empty>);

// ==== Press actor =================================================================================

struct PressActor;
struct PsWaitLoad;    // plate at arm1's level, ready to be loaded
struct PsForge;       // up to the top
struct PsDown;        // down to arm2's level
struct PsWaitUnload;  // ready to be unloaded
struct PsUp;          // back to arm1's level

struct press_ctl {
    bsc::input<bool> on;
    bsc::input<std::uint8_t> level;     // the plate's position sensor
    bsc::input<bool> loaded;            // robot actor: arm1 let a brick go in the press
    bsc::input<bool> unloaded;          // robot actor: arm2 took the forged brick
    bsc::input<std::uint8_t> arm1_ext;  // the robot's extension sensors
    bsc::input<std::uint8_t> arm2_ext;
    bsc::output<drive> plate;
    bsc::output<bool> load_ready;    // to the robot actor
    bsc::output<bool> unload_ready;  // to the robot actor
};

/// The press's guard to start forging: arm1 has let the brick go, and if WaitsForArm1, it has
/// retracted too.
template <bool WaitsForArm1>
inline constexpr auto may_forge = [] {
    auto const loaded = bsc::named<"loaded && load_ready">(
        bsc::guard([](press_ctl const& c) { return c.loaded.get() && c.load_ready.get(); }));
    if constexpr (WaitsForArm1)
        return loaded &&
               bsc::named<"arm1_ext == 0">(bsc::guard([](press_ctl const& c) { return c.arm1_ext.get() == 0; }));
    else
        return loaded;
}();

/// The press controller. `WaitsForArm1` is true in the cell: the press starts forging once
/// arm1 has let the brick go *and* retracted. The variant that does not wait for the retraction
/// differs in that one guard; the tests show that it breaks the press.
template <bool WaitsForArm1>
constexpr auto make_press_chart() {
    return bsc::make_chart<press_ctl>(
        bsc::composite<PressActor>(bsc::initial<Off>, bsc::composite<On>(bsc::shallow_history, bsc::initial<PsWaitLoad>,
                                                                         bsc::state<PsForge>, bsc::state<PsDown>,
                                                                         bsc::state<PsWaitUnload>, bsc::state<PsUp>)),
        bsc::state<Off>[switched_on] = bsc::state<On>, bsc::state<On>[!switched_on] = bsc::state<Off>,
        bsc::state<On> + bsc::on_exit / bsc::named<"plate=stop">([](press_ctl& c) { c.plate.set(stop); }),
        bsc::state<PsWaitLoad> + bsc::on_entry / bsc::named<"plate=stop">([](press_ctl& c) { c.plate.set(stop); }),
        bsc::state<PsWaitLoad>[bsc::named<"!loaded && !load_ready">(
            [](press_ctl const& c) { return !c.loaded.get() && !c.load_ready.pending(); })] /
            bsc::named<"load_ready=1">([](press_ctl& c) { c.load_ready.set(true); }),
        bsc::state<PsWaitLoad>[may_forge<WaitsForArm1>] /
            bsc::named<"load_ready=0">([](press_ctl& c) { c.load_ready.set(false); }) = bsc::state<PsForge>,
        bsc::state<PsForge> + bsc::on_entry / bsc::named<"plate=fwd">([](press_ctl& c) { c.plate.set(fwd); }),
        bsc::state<PsForge>[bsc::named<"level == press_top">(
            [](press_ctl const& c) { return c.level.get() == press_top; })] = bsc::state<PsDown>,
        bsc::state<PsDown> + bsc::on_entry / bsc::named<"plate=rev">([](press_ctl& c) { c.plate.set(rev); }),
        bsc::state<PsDown>[bsc::named<"level == press_bottom">(
            [](press_ctl const& c) { return c.level.get() == press_bottom; })] = bsc::state<PsWaitUnload>,
        bsc::state<PsWaitUnload> + bsc::on_entry / bsc::named<"plate=stop">([](press_ctl& c) { c.plate.set(stop); }),
        bsc::state<PsWaitUnload>[bsc::named<"!unloaded && !unload_ready">(
            [](press_ctl const& c) { return !c.unloaded.get() && !c.unload_ready.pending(); })] /
            bsc::named<"unload_ready=1">([](press_ctl& c) { c.unload_ready.set(true); }),
        bsc::state<PsWaitUnload>[bsc::named<"unloaded && unload_ready && arm2_ext == 0">(
            [](press_ctl const& c) { return c.unloaded.get() && c.unload_ready.get() && c.arm2_ext.get() == 0; })] /
            bsc::named<"unload_ready=0">([](press_ctl& c) { c.unload_ready.set(false); }) = bsc::state<PsUp>,
        bsc::state<PsUp> + bsc::on_entry / bsc::named<"plate=fwd">([](press_ctl& c) { c.plate.set(fwd); }),
        bsc::state<PsUp>[bsc::named<"level == press_middle">(
            [](press_ctl const& c) { return c.level.get() == press_middle; })] = bsc::state<PsWaitLoad>);
}

template <bool WaitsForArm1>
inline constexpr auto press_chart_variant = make_press_chart<WaitsForArm1>();
inline constexpr auto const& press_chart = press_chart_variant<true>;

// ==== Deposit belt actor ==========================================================================

struct DepositBeltActor;
struct DpIdle;   // stopped, a brick may be dropped
struct DpClear;  // moving the dropped brick away from the drop zone
struct DpRun;    // running until the belt is empty, a brick may be dropped

struct deposit_belt_ctl {
    bsc::input<bool> on;
    bsc::input<bool> dropped;  // robot actor: arm2 dropped a brick on the belt
    bsc::output<bool> motor;
    bsc::output<bool> ready;  // to the robot actor
};

inline constexpr auto deposit_belt_chart = bsc::make_chart<deposit_belt_ctl>(
    bsc::composite<DepositBeltActor>(bsc::initial<Off>, bsc::composite<On>(bsc::shallow_history, bsc::initial<DpIdle>,
                                                                           bsc::state<DpClear>, bsc::state<DpRun>)),
    bsc::state<Off>[switched_on] = bsc::state<On>, bsc::state<On>[!switched_on] = bsc::state<Off>,
    bsc::state<On> + bsc::on_exit / bsc::named<"motor=0">([](deposit_belt_ctl& c) { c.motor.set(false); }),
    bsc::state<DpIdle> + bsc::on_entry / bsc::named<"motor=0, ready=1">([](deposit_belt_ctl& c) {
                             c.motor.set(false);
                             c.ready.set(true);
                         }),
    bsc::state<DpIdle>[bsc::named<"dropped">([](deposit_belt_ctl const& c) { return c.dropped.get(); })] =
        bsc::state<DpClear>,
    bsc::state<DpClear> + bsc::on_entry / bsc::named<"motor=1, ready=0">([](deposit_belt_ctl& c) {
                              c.motor.set(true);
                              c.ready.set(false);
                          }),
    bsc::state<DpClear> + bsc::after(deposit_clear_time)[bsc::named<"!dropped">(
                              [](deposit_belt_ctl const& c) { return !c.dropped.get(); })] = bsc::state<DpRun>,
    bsc::state<DpRun> + bsc::on_entry / bsc::named<"motor=1, ready=1">([](deposit_belt_ctl& c) {
                            c.motor.set(true);
                            c.ready.set(true);
                        }),
    bsc::state<DpRun>[bsc::named<"dropped">([](deposit_belt_ctl const& c) { return c.dropped.get(); })] =
        bsc::state<DpClear>,
    bsc::state<DpRun> + bsc::after(deposit_run_out_time) = bsc::state<DpIdle>);

using feed_belt_actor = bsc::machine<bsc::chart_ref<feed_belt_chart>>;
using table_actor = bsc::machine<bsc::chart_ref<table_chart>>;
using robot_actor = bsc::machine<bsc::chart_ref<robot_chart>>;
template <bool WaitsForArm1>
using press_actor_variant = bsc::machine<bsc::chart_ref<press_chart_variant<WaitsForArm1>>>;
using press_actor = press_actor_variant<true>;
using deposit_belt_actor = bsc::machine<bsc::chart_ref<deposit_belt_chart>>;

}  // namespace pcell
