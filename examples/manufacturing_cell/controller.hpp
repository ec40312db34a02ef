#pragma once
// The controller of the manufacturing cell of the Basic Statechart paper ([BSC] in
// docs/references.md; section IV, Fig. 4 to 6 and Table I): a belt brings pieces from an input
// buffer to position P1 of a rotary table; a drill works at P2, a test station at P3, and a robot
// takes the piece at P4 and stores it. A single-acting cylinder turns the table by 90 degrees
// (P1 -> P2 -> P3 -> P4) on each full advance of its arm. The four devices work in parallel; the
// table turns only once all of them have finished (the synchronisation point of Fig. 5).
//
// How the paper maps to this file:
//
//   Paper                                   Code
//   --------------------------------------  ---------------------------------------------------
//   the controller of Fig. 6 (a BSC)        cell::chart, run by cell::machine
//   its components, in the paper's order    the regions of the parallel root cell::Cell:
//     belt (three states)                     cell::Belt: BeltOff, BeltOn, BeltDone
//     drill (two states)                      cell::Drill: DrillOff, DrillOn
//     test (two states)                       cell::Test: TestOff, TestOn
//     robot (two states)                      cell::Robot: RobotOff, RobotOn
//     table cylinder (three states)           cell::Table: CylinderReturned, CylinderAdvancing,
//                                               CylinderReturning
//   the data model area (not drawn)         cell::data, the chart's context
//   sensors IN, P1, P2, P3, P4, S1          input channels data::IN ... data::S1
//     (IN: a piece in the input buffer;       (bsc::input<bool>, latched at the start of each
//     S1: the cylinder arm fully advanced)    execution cycle)
//   actuators BeltOn/Off, DrillOn/Off,      output channels data::belt, drill, test, robot, valve
//     TestOn/Off, RobotOn/Off, ValveOn/Off    (bsc::output<bool>, published at the end of a cycle)
//   variables E1..E4 ("end of operation"    plain members data::E1 ... data::E4
//     of belt, drill, test, robot)
//   timers timerT1..T3, "tmNOn", "tmN.tm"   bsc::timer members data::T1, T2, T3: start() and
//     (drilling, testing, robot)              tm(); limits cell::drill_time, test_time, robot_time
//   the if-then clauses of section IV       the transition rows of cell::chart, one block per
//                                             component
//   Table I, guards g1 ... g15              cell::g1 ... cell::g15, one bsc::guard each, written
//                                             as the table's formula and named as in the table
//   the actions of the if-then clauses      cell::belt_on ... cell::new_phase, named as in the
//     (BeltOn, DrillOn & tm1On, ...)          clauses ("DrillOn & tm1On") for the diagrams
//   constraint 1 (each device at most once  the variables E1..E4: a device acts only while its
//     before a table rotation)                Ei is false (g1, g3, g4, g6, g7, g9, g10, g12) and
//                                             sets it when it ends; only the table resets them
//   constraint 2 (no device on without a    g1 needs IN, g4 P2, g7 P3, g10 P4; without a piece
//     piece)                                  g3, g6, g9, g12 end the phase at once (Ei := true)
//   constraint 3 (rotate only with a piece  g13 needs P1 | P2 | P3; g15 (none of them) resets
//     at P1, P2 or P3)                        E1..E4 without rotating
//   synchronisation point (Fig. 5)          g13 and g15 both need E1 & E2 & E3 & E4
//
// The execution cycle is bsc's (docs/semantics.md, "The execution cycle"): each cycle updates
// the timers, latches the inputs, runs the components in the order above (each takes at most
// one transition; a variable written by one is seen at once by the components after it) and
// publishes the outputs. Drive it with machine::step(now) at a fixed scan period.
//
// Where the paper is silent, the choices made are marked "Paper silent:" below and listed in
// docs/examples/manufacturing_cell.md.

#include <chrono>
#include <type_traits>

#include <bsc/bsc.hpp>

namespace cell {

using namespace std::chrono_literals;

// ---- Timer limits ------------------------------------------------------------------------------
// Paper silent: the paper gives no durations. These are the times each operation is given.

inline constexpr bsc::duration drill_time = 3s;      ///< T1: drilling
inline constexpr bsc::duration test_time = 2s;       ///< T2: testing
inline constexpr bsc::duration robot_time = 2500ms;  ///< T3: the robot takes the piece and stores it

// ---- States ----------------------------------------------------------------------------------

struct Cell;  // the controller: an AND state whose regions are the five components

struct Belt;      // component 1: the belt
struct BeltOff;   //   motor off, the phase still open (E1 false)
struct BeltOn;    //   motor on, carrying a piece from the input buffer to P1
struct BeltDone;  //   motor off, the belt has ended its phase (E1 set)
struct Drill;     // component 2: the drill
struct DrillOff;
struct DrillOn;
struct Test;  // component 3: the test station
struct TestOff;
struct TestOn;
struct Robot;  // component 4: the robot
struct RobotOff;
struct RobotOn;
struct Table;              // component 5: the cylinder that turns the table
struct CylinderReturned;   //   valve off, arm returned: the table stands still
struct CylinderAdvancing;  //   valve on: the arm advances and turns the table by 90 degrees
struct CylinderReturning;  //   valve off after the full advance (S1): the arm returns

// ---- The data model area: channels, variables, timers -----------------------------------------

/// The context of the chart (the paper's data model area). Member names follow the paper.
struct data {
    // Input channels: the sensors of the plant, written by the plant between cycles.
    bsc::input<bool> IN;  ///< a piece in the input buffer (the start of the belt)
    bsc::input<bool> P1;  ///< a piece at position P1 of the table (the end of the belt)
    bsc::input<bool> P2;  ///< a piece at P2, under the drill
    bsc::input<bool> P3;  ///< a piece at P3, under the test station
    bsc::input<bool> P4;  ///< a piece at P4, where the robot takes it
    bsc::input<bool> S1;  ///< the cylinder arm is fully advanced (the table has turned)

    // Output channels: the actuators.
    bsc::output<bool> belt;   ///< belt motor (BeltOn / BeltOff)
    bsc::output<bool> drill;  ///< drill (DrillOn / DrillOff)
    bsc::output<bool> test;   ///< test station (TestOn / TestOff)
    bsc::output<bool> robot;  ///< robot (RobotOn / RobotOff)
    bsc::output<bool> valve;  ///< the cylinder's valve (ValveOn / ValveOff)

    // Internal variables: "end of operation" of belt, drill, test and robot in this phase
    // (a phase runs from one reset of E1..E4 to the next).
    bool E1 = false;
    bool E2 = false;
    bool E3 = false;
    bool E4 = false;

    // Timers ([BSC], III.C): started by an action, timing from the next cycle on.
    bsc::timer T1{drill_time};  ///< timerT1, "tm1"
    bsc::timer T2{test_time};   ///< timerT2, "tm2"
    bsc::timer T3{robot_time};  ///< timerT3, "tm3"
};

// ---- Table I: the guard conditions ---------------------------------------------------------------
// The paper writes ¬ for NOT, & for AND and ∥ for OR; the channels are read as latched at the
// start of the cycle, the variables as the components before have left them in this cycle. Each
// guard has its name in Table I (bsc::named), which the diagrams of the chart show.

// g1: ¬P1 & ¬E1 & IN
inline constexpr auto g1 = bsc::named<"g1">(bsc::guard([](data const& d) { return !d.P1 && !d.E1 && d.IN; }));
// g2: P1
inline constexpr auto g2 = bsc::named<"g2">(bsc::guard([](data const& d) { return d.P1.get(); }));
// g3: ¬P1 & ¬E1 & ¬IN
inline constexpr auto g3 = bsc::named<"g3">(bsc::guard([](data const& d) { return !d.P1 && !d.E1 && !d.IN; }));
// g4: P2 & ¬E2
inline constexpr auto g4 = bsc::named<"g4">(bsc::guard([](data const& d) { return d.P2 && !d.E2; }));
// g5: tm1.tm
inline constexpr auto g5 = bsc::named<"g5">(bsc::guard([](data const& d) { return d.T1.tm(); }));
// g6: ¬P2 & ¬E2
inline constexpr auto g6 = bsc::named<"g6">(bsc::guard([](data const& d) { return !d.P2 && !d.E2; }));
// g7: P3 & ¬E3
inline constexpr auto g7 = bsc::named<"g7">(bsc::guard([](data const& d) { return d.P3 && !d.E3; }));
// g8: tm2.tm
inline constexpr auto g8 = bsc::named<"g8">(bsc::guard([](data const& d) { return d.T2.tm(); }));
// g9: ¬P3 & ¬E3
inline constexpr auto g9 = bsc::named<"g9">(bsc::guard([](data const& d) { return !d.P3 && !d.E3; }));
// g10: P4 & ¬E4
inline constexpr auto g10 = bsc::named<"g10">(bsc::guard([](data const& d) { return d.P4 && !d.E4; }));
// g11: tm3.tm
inline constexpr auto g11 = bsc::named<"g11">(bsc::guard([](data const& d) { return d.T3.tm(); }));
// g12: ¬P4 & ¬E4
inline constexpr auto g12 = bsc::named<"g12">(bsc::guard([](data const& d) { return !d.P4 && !d.E4; }));
// g13: E1 & E2 & E3 & E4 & (P1 ∥ P2 ∥ P3)
inline constexpr auto g13 = bsc::named<"g13">(
    bsc::guard([](data const& d) { return d.E1 && d.E2 && d.E3 && d.E4 && (d.P1 || d.P2 || d.P3); }));
// g14: S1
inline constexpr auto g14 = bsc::named<"g14">(bsc::guard([](data const& d) { return d.S1.get(); }));
// g15: E1 & E2 & E3 & E4 & ¬P1 & ¬P2 & ¬P3
inline constexpr auto g15 = bsc::named<"g15">(
    bsc::guard([](data const& d) { return d.E1 && d.E2 && d.E3 && d.E4 && !d.P1 && !d.P2 && !d.P3; }));

// Paper silent: two conditions that Table I does not list, for the transitions that close the
// belt's third state and the table's third state (see the rows below). Named by their formula.
// ¬E1: the table has reset E1, a new phase begins.
inline constexpr auto new_phase_begun = bsc::named<"!E1">(bsc::guard([](data const& d) { return !d.E1; }));
// ¬S1: the arm has left its fully advanced position: the valve is off and the turn is over.
inline constexpr auto arm_left_end = bsc::named<"!S1">(bsc::guard([](data const& d) { return !d.S1; }));

// ---- Actions ---------------------------------------------------------------------------------
// Named as in the if-then clauses of section IV ("DrillOn & tm1On"); `& E2` (or `E2` alone) is
// the end of operation, E2 := true, and "reset E1-E4" the start of a new phase.

inline constexpr auto belt_on = bsc::named<"BeltOn">([](data& d) { d.belt.set(true); });
inline constexpr auto belt_off = bsc::named<"BeltOff & E1">([](data& d) {  // end of operation
    d.belt.set(false);
    d.E1 = true;
});
inline constexpr auto belt_nothing_to_do = bsc::named<"E1">([](data& d) { d.E1 = true; });

inline constexpr auto drill_on = bsc::named<"DrillOn & tm1On">([](data& d) {
    d.drill.set(true);
    d.T1.start();
});
inline constexpr auto drill_off = bsc::named<"DrillOff & E2">([](data& d) {  // end of operation
    d.drill.set(false);
    d.T1.reset();  // Paper silent: the timer is stopped with the drill (its tm cleared)
    d.E2 = true;
});
inline constexpr auto drill_nothing_to_do = bsc::named<"E2">([](data& d) { d.E2 = true; });

inline constexpr auto test_on = bsc::named<"TestOn & tm2On">([](data& d) {
    d.test.set(true);
    d.T2.start();
});
inline constexpr auto test_off = bsc::named<"TestOff & E3">([](data& d) {  // end of operation
    d.test.set(false);
    d.T2.reset();
    d.E3 = true;
});
inline constexpr auto test_nothing_to_do = bsc::named<"E3">([](data& d) { d.E3 = true; });

inline constexpr auto robot_on = bsc::named<"RobotOn & tm3On">([](data& d) {
    d.robot.set(true);
    d.T3.start();
});
inline constexpr auto robot_off = bsc::named<"RobotOff & E4">([](data& d) {  // end of operation
    d.robot.set(false);
    d.T3.reset();
    d.E4 = true;
});
inline constexpr auto robot_nothing_to_do = bsc::named<"E4">([](data& d) { d.E4 = true; });

inline constexpr auto valve_on = bsc::named<"ValveOn">([](data& d) { d.valve.set(true); });
inline constexpr auto valve_off = bsc::named<"ValveOff">([](data& d) { d.valve.set(false); });
/// "E1, E2, E3, and E4 must be set to false to allow new operations in the devices".
inline constexpr auto new_phase = bsc::named<"reset E1-E4">([](data& d) { d.E1 = d.E2 = d.E3 = d.E4 = false; });

// ---- The chart (Fig. 6) ----------------------------------------------------------------------

/// The chart, with g4 and g13 as parameters so that tests can build variants that break
/// constraints 2 and 3 from the same rows; `chart` is the paper's.
template <class G4, class G13>
constexpr auto make_controller(G4 guard4, G13 guard13) {
    return bsc::make_chart<data>(
        // The components, in the paper's order: the order in which they run in each cycle.
        bsc::parallel<Cell>(bsc::composite<Belt>(bsc::initial<BeltOff>, bsc::state<BeltOn>, bsc::state<BeltDone>),
                            bsc::composite<Drill>(bsc::initial<DrillOff>, bsc::state<DrillOn>),
                            bsc::composite<Test>(bsc::initial<TestOff>, bsc::state<TestOn>),
                            bsc::composite<Robot>(bsc::initial<RobotOff>, bsc::state<RobotOn>),
                            bsc::composite<Table>(bsc::initial<CylinderReturned>, bsc::state<CylinderAdvancing>,
                                                  bsc::state<CylinderReturning>)),

        // BELT: "If inputbuffer & ¬P1 then BeltOn; If P1 then BeltOff".
        // Paper silent: the belt's third state. The paper gives the belt three states but the
        // devices two; BeltDone is the belt's end of operation made a state: entered when E1 is set
        // (a piece delivered to P1, or nothing to carry), left when the table resets E1. So the belt
        // is in BeltDone whenever the table turns, and the three states combine freely with the
        // devices' while the table stands still (the paper's 3 x 2 x 2 x 2 = 24 configurations).
        bsc::state<BeltOff>[g1] / belt_on = bsc::state<BeltOn>,
        bsc::state<BeltOn>[g2] / belt_off = bsc::state<BeltDone>,
        bsc::state<BeltOff>[g3] / belt_nothing_to_do = bsc::state<BeltDone>,  // constraint 2
        bsc::state<BeltDone>[new_phase_begun] = bsc::state<BeltOff>,

        // DRILL: "If P2 then DrillOn & tm1On; If tm1.tm then DrillOff".
        // Paper silent: without a piece the drill stays Off and only sets E2 (an internal
        // transition: nothing is exited or entered).
        bsc::state<DrillOff>[guard4] / drill_on = bsc::state<DrillOn>,
        bsc::state<DrillOn>[g5] / drill_off = bsc::state<DrillOff>,
        bsc::state<DrillOff>[g6] / drill_nothing_to_do,  // constraint 2

        // TEST: "If P3 then TestOn & tm2On; If tm2.tm then TestOff".
        bsc::state<TestOff>[g7] / test_on = bsc::state<TestOn>, bsc::state<TestOn>[g8] / test_off = bsc::state<TestOff>,
        bsc::state<TestOff>[g9] / test_nothing_to_do,  // constraint 2

        // ROBOT: "If P4 then RobotOn & tm3On; If tm3.tm then RobotOff".
        bsc::state<RobotOff>[g10] / robot_on = bsc::state<RobotOn>,
        bsc::state<RobotOn>[g11] / robot_off = bsc::state<RobotOff>,
        bsc::state<RobotOff>[g12] / robot_nothing_to_do,  // constraint 2

        // TABLE: "If BeltEnd & DrillEnd & TestEnd & RobotEnd then ValveOn; If SensorOn then
        // ValveOff"; with constraint 3 and the reset of E1..E4 after each turn.
        // Paper silent: when E1..E4 are reset after a turn. S1 (the full advance) means the table
        // has turned; the valve goes off (g14) and, once the arm has left its end position (the
        // cycle after, in practice), the phase ends: CylinderReturning resets E1..E4. The devices
        // therefore stay off for the whole turn and see the pieces at their new positions.
        // Paper silent: under g15 the table does not move: an internal transition resets E1..E4.
        bsc::state<CylinderReturned>[guard13] / valve_on = bsc::state<CylinderAdvancing>,  // constraint 3
        bsc::state<CylinderAdvancing>[g14] / valve_off = bsc::state<CylinderReturning>,
        bsc::state<CylinderReturning>[arm_left_end] / new_phase = bsc::state<CylinderReturned>,
        bsc::state<CylinderReturned>[g15] / new_phase);  // constraint 3
}

inline constexpr auto chart = make_controller(g4, g13);

/// The controller: the chart running over its data model area.
using machine = bsc::machine<bsc::chart_ref<chart>, bsc::scan_policy>;

// ---- The controller's interface to the plant ---------------------------------------------------

/// The sensor values the plant presents to the controller.
struct sensors {
    bool IN = false, P1 = false, P2 = false, P3 = false, P4 = false, S1 = false;
    friend constexpr bool operator==(sensors const&, sensors const&) = default;
};

/// The actuator values the controller publishes.
struct actuators {
    bool belt = false, drill = false, test = false, robot = false, valve = false;
    friend constexpr bool operator==(actuators const&, actuators const&) = default;
};

/// Writes the sensors into the input channels of the machine's context (the plant's view of it,
/// `m.context()`, is const: it sets inputs and reads outputs); the next cycle latches them.
constexpr void write_inputs(data const& d, sensors const& s) {
    d.IN.set(s.IN);
    d.P1.set(s.P1);
    d.P2.set(s.P2);
    d.P3.set(s.P3);
    d.P4.set(s.P4);
    d.S1.set(s.S1);
}

/// The published values of the output channels.
constexpr actuators read_outputs(data const& d) {
    return {d.belt.get(), d.drill.get(), d.test.get(), d.robot.get(), d.valve.get()};
}

}  // namespace cell
