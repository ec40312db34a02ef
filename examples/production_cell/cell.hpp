#pragma once
// The simplified Production Cell of the COMDES-II paper ([COMDES] in docs/references.md): five
// machines process metal bricks, fed by a feed belt, lifted and turned by an elevating rotary
// table, carried by a robot with two arms into a press and out of it, and carried away by a
// deposit belt. Each machine has a controller actor and a plant model; the actor diagram below
// wires them.
//
// How the paper maps to the code:
//
//   Paper                                    Code
//   ---------------------------------------  -------------------------------------------------------
//   the five actors (Fig. 3.1): Feed Belt,   the controller charts of controllers.hpp:
//     Table, Robot, Press, Deposit Belt        feed_belt_chart, table_chart, robot_chart,
//     Actor                                    press_chart, deposit_belt_chart; the members
//                                              feed_belt, table, robot, press, deposit_belt of Actors
//   the Table actor's hierarchical control   every controller: a root with the states Off and On
//     unit (Fig. 3.2, 3.3): top-level SSM     (pcell::Off, pcell::On), switched by the input `on`;
//     and MFB (mode 0: motors off, mode 1:     On's exit action switches the motors off; On has
//     run SSM2), second-level SSM2 and MFB2    history, so work resumes where it stopped; inside On
//                                              the second-level controller, whose states set the
//                                              outputs in their entry actions (the MFB2's modes)
//   the manual on/off switch                 the input channel `on` of each controller
//   the robot actor's second version         robot_chart's parallel state RobotWork: the regions
//     (section V: arm1 and arm2 carry          Turret, Arm1Job and Arm2Job; each arm does its own
//     bricks at the same time)                 work cycle
//   environment units Env_FeedBelt,          the plant charts of plants.hpp: env_feed_belt_chart,
//     Env_Table, Env_Robot, Env_Press          env_table_chart, env_robot_chart, env_press_chart,
//     (Uppaal processes), and the deposit      env_deposit_belt_chart; the members env_feed_belt ...
//     belt                                     env_deposit_belt of Actors
//   a pair (Fig. 4.1): an actor and its      a controller member and its env_ member, linked by
//     environment                              sensor and control signals below
//   sensor signal (plant to actor; Uppaal    a link from a plant's output channel to a controller's
//     int variable, read in guards)            input channel, read in guards: env_table.height_sensor
//                                              -> table.height
//   control signal (actor to plant; Uppaal   a link from a controller's output channel to a plant's
//     urgent broadcast chan)                   input channel: table.lift -> env_table.lift
//   global signal (actor to actor; Uppaal    a link between controllers: table.ready_for_feed ->
//     urgent chan ready_for_feed, a            feed_belt.table_ready; the rendezvous is a four-phase
//     rendezvous)                              handshake of levels (ready up, done up, ready down,
//                                              done down)
//   the actor diagram                        cell_system's list of links, grouped by actor in the
//                                              paper's order (feed belt, table, robot, press,
//                                              deposit belt), then the plant-to-plant signals
//   controllers have higher priority than    bsc::order: the five controllers step first, then the
//     the environment (system Env_... <        five plant models. In each step a controller sees the
//     FeedBeltController, ...)                 sensors of the previous step and a plant the commands
//                                              of this one; every movement takes at least two
//                                              periods (parts.hpp), so no sensor change is missed
//   the Brick process                        pcell::brick, data held by the plant models (feed belt
//                                              slots, table, arm1, press, arm2, deposit belt slots);
//                                              a transfer is a one-step signal from plant to plant:
//                                              to_table, to_arm1, to_press, to_arm2, to_belt
//   Damage locations (Env_Table.Damage)      the final state pcell::Damage of each plant model:
//                                              s.actors.env_table.is<pcell::Damage>()
//   R1: keep bricks apart (one brick on the  a plant model enters Damage when a brick arrives where
//     table at a time)                         one already is (feed belt start, table, arms, press,
//                                              deposit belt start); the tests also count the bricks
//                                              at every place in every step
//   R2: avoid collisions (arm1 not in the    collision_rows (parts.hpp): the table moving with arm1
//     press area while the press moves;        over it, the robot turning with an arm out, the plate
//     arm1 extended too far towards the        moving with an arm in the press; the Arm1Out timeout
//     press)                                   row of env_robot_chart; the tests check
//                                              arm_in_press_area(s, 1) && press_moving(s) every step
//   R3: mobility limits (the robot would     axis_rows (parts.hpp): driving an axis past either end
//     destroy itself if turned too far)        enters Damage; A[] not Env_Table.Damage is checked
//                                              with no_damage(s) in every step and with
//                                              bsc::verify::always in the exploration test
//   liveness: every brick is forged and      tests/unit/production_cell_test.cpp: every brick put on
//     deposited                                the feed belt leaves forged within a bound
//   efficiency: a brick with arm1 while      the same test: some step has a brick on each arm
//     another moves with arm2
//   hardware-in-the-loop simulation          main.cpp: the closed loop stepped with a fixed period
//
// Where the paper is silent (it gives no geometry, timing or signal list), the choices are:
// positions are small integers (parts.hpp), every movement is a fixed time per unit, the robot
// stops in the order arm1-to-table, arm2-to-press (its default), arm2-to-belt, arm1-to-press,
// the actors' handshakes are four-phase, the press controller reads the robot's arm extension
// sensors (it starts the plate only once the arm that served it is retracted), and a brick falls
// (Damage) when let go where nothing can take it.

#include "controllers.hpp"
#include "plants.hpp"

namespace pcell {

/// The actors of the cell: five controllers and five plant models. `PressWaitsForArm1` selects
/// the press controller (false: the broken variant of the tests).
template <bool PressWaitsForArm1>
struct basic_actors {
    // The controller actors.
    feed_belt_actor feed_belt{feed_belt_chart};
    table_actor table{table_chart};
    robot_actor robot{robot_chart};
    press_actor_variant<PressWaitsForArm1> press{press_chart_variant<PressWaitsForArm1>};
    deposit_belt_actor deposit_belt{deposit_belt_chart};
    // The plant models (the environment).
    feed_belt_plant env_feed_belt{env_feed_belt_chart};
    table_plant env_table{env_table_chart};
    robot_plant env_robot{env_robot_chart};
    press_plant env_press{env_press_chart};
    deposit_belt_plant env_deposit_belt{env_deposit_belt_chart};
};

using Actors = basic_actors<true>;

/// The actor diagram: every signal, who sends what to whom, for actors `A` stepped in `Order`,
/// with the `Extra` entries of a larger system (supervised.hpp's links) or of the cell alone
/// (the inputs the operator sets, bsc::from_outside).
///
/// What a consumer reads when the cell is distributed and a publisher falls silent (in one
/// process nothing is ever stale and these policies change nothing): a motor command reads
/// "stop" (bsc::fail_safe), as a drive whose controller is lost stops; a magnet keeps its last
/// command (letting go would drop the brick); sensors and handshakes keep their last level
/// (bsc::hold_last), so a peer waits rather than misreads; the plant models' couplings, which
/// are physics (a brick handed from one machine to the next), are bsc::lossless.
template <class A, class Order, class... Extra>
using cell_system = bsc::system<
    A, Order,
    // Feed belt actor
    bsc::link<&A::env_feed_belt, &feed_belt_io::sensor, &A::feed_belt, &feed_belt_ctl::sensor>,
    bsc::link<&A::feed_belt, &feed_belt_ctl::motor, &A::env_feed_belt, &feed_belt_io::motor, bsc::fail_safe<false>>,
    bsc::link<&A::table, &table_ctl::ready_for_feed, &A::feed_belt, &feed_belt_ctl::table_ready>,
    bsc::link<&A::feed_belt, &feed_belt_ctl::fed, &A::table, &table_ctl::fed>,
    // Table actor
    bsc::link<&A::env_table, &table_io::height_sensor, &A::table, &table_ctl::height>,
    bsc::link<&A::env_table, &table_io::angle_sensor, &A::table, &table_ctl::angle>,
    bsc::link<&A::table, &table_ctl::lift, &A::env_table, &table_io::lift, bsc::fail_safe<stop>>,
    bsc::link<&A::table, &table_ctl::turn, &A::env_table, &table_io::turn, bsc::fail_safe<stop>>,
    bsc::link<&A::table, &table_ctl::ready_for_unload, &A::robot, &robot_ctl::table_ready>,
    bsc::link<&A::robot, &robot_ctl::taken, &A::table, &table_ctl::taken>,
    // Robot actor
    bsc::link<&A::env_robot, &robot_io::angle_sensor, &A::robot, &robot_ctl::angle>,
    bsc::link<&A::env_robot, &robot_io::arm1_sensor, &A::robot, &robot_ctl::ext1>,
    bsc::link<&A::env_robot, &robot_io::arm2_sensor, &A::robot, &robot_ctl::ext2>,
    bsc::link<&A::robot, &robot_ctl::turn, &A::env_robot, &robot_io::turn, bsc::fail_safe<stop>>,
    bsc::link<&A::robot, &robot_ctl::arm1, &A::env_robot, &robot_io::arm1, bsc::fail_safe<stop>>,
    bsc::link<&A::robot, &robot_ctl::arm2, &A::env_robot, &robot_io::arm2, bsc::fail_safe<stop>>,
    bsc::link<&A::robot, &robot_ctl::magnet1, &A::env_robot, &robot_io::magnet1>,
    bsc::link<&A::robot, &robot_ctl::magnet2, &A::env_robot, &robot_io::magnet2>,
    bsc::link<&A::press, &press_ctl::load_ready, &A::robot, &robot_ctl::press_load_ready>,
    bsc::link<&A::press, &press_ctl::unload_ready, &A::robot, &robot_ctl::press_unload_ready>,
    bsc::link<&A::robot, &robot_ctl::press_loaded, &A::press, &press_ctl::loaded>,
    bsc::link<&A::robot, &robot_ctl::press_unloaded, &A::press, &press_ctl::unloaded>,
    bsc::link<&A::deposit_belt, &deposit_belt_ctl::ready, &A::robot, &robot_ctl::belt_ready>,
    bsc::link<&A::robot, &robot_ctl::dropped, &A::deposit_belt, &deposit_belt_ctl::dropped>,
    // Press actor
    bsc::link<&A::env_press, &press_io::plate_sensor, &A::press, &press_ctl::level>,
    bsc::link<&A::env_robot, &robot_io::arm1_sensor, &A::press, &press_ctl::arm1_ext>,
    bsc::link<&A::env_robot, &robot_io::arm2_sensor, &A::press, &press_ctl::arm2_ext>,
    bsc::link<&A::press, &press_ctl::plate, &A::env_press, &press_io::plate, bsc::fail_safe<stop>>,
    // Deposit belt actor
    bsc::link<&A::deposit_belt, &deposit_belt_ctl::motor, &A::env_deposit_belt, &deposit_belt_io::motor,
              bsc::fail_safe<false>>,
    // Plant to plant: the bricks, and where the robot's arms are
    bsc::link<&A::env_feed_belt, &feed_belt_io::to_table, &A::env_table, &table_io::from_belt, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::arm1_over_table, &A::env_table, &table_io::arm1_over, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::arm1_grips, &A::env_table, &table_io::arm1_grips, bsc::lossless>,
    bsc::link<&A::env_table, &table_io::to_arm1, &A::env_robot, &robot_io::from_table, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::arm1_in_press, &A::env_press, &press_io::arm1_in, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::arm2_in_press, &A::env_press, &press_io::arm2_in, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::to_press, &A::env_press, &press_io::from_arm1, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::arm2_grips, &A::env_press, &press_io::arm2_grips, bsc::lossless>,
    bsc::link<&A::env_press, &press_io::to_arm2, &A::env_robot, &robot_io::from_press, bsc::lossless>,
    bsc::link<&A::env_robot, &robot_io::to_belt, &A::env_deposit_belt, &deposit_belt_io::from_arm2, bsc::lossless>,
    Extra...>;

/// The cell's own diagram: the controllers step first, then the plant models. The operator
/// (operation.hpp) sets the five manual switches and puts the bricks on the feed belt: those
/// inputs are driven from outside the system.
template <class A>
using system_of =
    cell_system<A,
                bsc::order<&A::feed_belt, &A::table, &A::robot, &A::press, &A::deposit_belt, &A::env_feed_belt,
                           &A::env_table, &A::env_robot, &A::env_press, &A::env_deposit_belt>,
                bsc::from_outside<&A::feed_belt, &feed_belt_ctl::on>, bsc::from_outside<&A::table, &table_ctl::on>,
                bsc::from_outside<&A::robot, &robot_ctl::on>, bsc::from_outside<&A::press, &press_ctl::on>,
                bsc::from_outside<&A::deposit_belt, &deposit_belt_ctl::on>,
                bsc::from_outside<&A::env_feed_belt, &feed_belt_io::put>>;

/// The production cell.
using cell = system_of<Actors>;

}  // namespace pcell
