#pragma once
// The controller of a bottle-filling station, a PLC that scans its inputs: a bottle arrives under
// the nozzle, the valve pours until the level sensor says full, a capping head screws the cap on,
// and the bottle leaves. An emergency-stop button, wired as an input, stops the station from any
// state; the operator resets it once the button is released.
//
// The chart is written once, as a function of the priority among nested transitions
// (bsc/priority.hpp), because that choice is what this example is about. The e-stop is one row
// on the outer state Normal, `Normal [estop] = EStop`; the rows of the automatic cycle inside it
// read other inputs of the same scan. When the e-stop is pressed in the very scan that a bottle
// arrives (or that the bottle is full), two condition-driven rows are enabled at once, and a
// scan fires one of them:
//
//   child first (SCXML, UML: the inner row wins)  Idle [bottle] = Filling fires: the valve
//                                                 opens while the e-stop is pressed, and the
//                                                 station stops only one scan later
//   parent first (Stateflow, STATEMATE, a PLC     Normal [estop] = EStop fires: the valve stays
//     program that scans its interlocks first)    closed
//
// The controller of the example (filling::controller) is the parent-first chart. main.cpp has
// the explorer prove it safe and find the counterexample of the child-first one;
// docs/examples/filling_station.md tells the story.
//
// Where industrial practice is silent, the choices made are marked "Choice:" below.

#include <chrono>

#include <bsc/bsc.hpp>

namespace filling {

using namespace std::chrono_literals;

/// How long the capping head takes to screw a cap on.
inline constexpr bsc::duration capping_time = 300ms;

// ---- States ------------------------------------------------------------------------------------

struct Station;    // the controller
struct Normal;     //   not stopped: everything the station does between two e-stops
struct Clearing;   //     waiting for the nozzle to be clear before the automatic cycle starts
struct Operating;  //     the automatic cycle
struct Idle;       //       waiting for a bottle
struct Filling;    //       the valve pours (the only state with the valve open)
struct Capping;    //       the capping head screws the cap on
struct Capped;     //       waiting for the capped bottle to leave
struct EStop;      //   emergency stop: every output off until the operator resets

// ---- The context: the I/O image ----------------------------------------------------------------

/// The inputs and outputs of the station, as the PLC's I/O image has them.
struct io {
    // Inputs: latched at the start of each scan.
    bsc::input<bool> estop;   ///< the emergency-stop button is pressed (it stays down until pulled)
    bsc::input<bool> bottle;  ///< a bottle stands under the nozzle
    bsc::input<bool> full;    ///< the level sensor: the bottle is full
    bsc::input<bool> reset;   ///< the operator's reset button
    // Outputs: published at the end of each scan.
    bsc::output<bool> valve;   ///< the filling valve
    bsc::output<bool> capper;  ///< the capping head
};

// ---- Guards and actions ------------------------------------------------------------------------
// Named (bsc::named) for the diagrams.

inline constexpr auto estop = bsc::named<"estop">(bsc::guard([](io const& d) { return d.estop.get(); }));
inline constexpr auto bottle = bsc::named<"bottle">(bsc::guard([](io const& d) { return d.bottle.get(); }));
inline constexpr auto full = bsc::named<"full">(bsc::guard([](io const& d) { return d.full.get(); }));
inline constexpr auto reset = bsc::named<"reset">(bsc::guard([](io const& d) { return d.reset.get(); }));

inline constexpr auto open_valve = bsc::named<"ValveOpen">(bsc::action([](io& d) { d.valve.set(true); }));
inline constexpr auto close_valve = bsc::named<"ValveClose">(bsc::action([](io& d) { d.valve.set(false); }));
inline constexpr auto capper_on = bsc::named<"CapperOn">(bsc::action([](io& d) { d.capper.set(true); }));
inline constexpr auto capper_off = bsc::named<"CapperOff">(bsc::action([](io& d) { d.capper.set(false); }));

// ---- The chart ---------------------------------------------------------------------------------

inline constexpr auto tree = bsc::composite<Station>(
    bsc::initial<Normal>,
    // Choice: the station starts in Clearing, and so does every restart after an e-stop. A bottle
    // found under the nozzle then may be half filled: the operator takes it away by hand before
    // the automatic cycle starts.
    bsc::composite<Normal>(bsc::initial<Clearing>, bsc::state<Clearing>,
                           bsc::composite<Operating>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Filling>,
                                                     bsc::state<Capping>, bsc::state<Capped>)),
    bsc::state<EStop>);

/// The station's chart under priority P. Every row but the first reads inputs of the same scan
/// as the e-stop's row, which is on the outermost state below the root: which of two enabled
/// rows a scan fires is P's to say.
template <bsc::priority P>
constexpr auto station_chart() {
    return bsc::make_chart<io, P>(
        tree,
        // The interlock: from any state of Normal.
        bsc::state<Normal>[estop] = bsc::state<EStop>,
        // Choice: reset is accepted once the e-stop button is released (IEC 60204-1: releasing
        // the button alone restarts nothing).
        bsc::state<EStop>[reset && !estop] = bsc::state<Normal>,
        // The nozzle is clear: the automatic cycle starts.
        bsc::state<Clearing>[!bottle] = bsc::state<Operating>,
        // The automatic cycle.
        bsc::state<Idle>[bottle] = bsc::state<Filling>,
        bsc::state<Filling>[!bottle] = bsc::state<Idle>,  // the bottle was taken away: stop pouring
        bsc::state<Filling>[full] = bsc::state<Capping>,
        bsc::state<Capping> + bsc::after(capping_time) = bsc::state<Capped>,
        bsc::state<Capped>[!bottle] = bsc::state<Idle>,
        // The outputs follow the states: the valve is open exactly in Filling, the capper runs
        // exactly in Capping.
        bsc::state<Filling> + bsc::on_entry / open_valve, bsc::state<Filling> + bsc::on_exit / close_valve,
        bsc::state<Capping> + bsc::on_entry / capper_on, bsc::state<Capping> + bsc::on_exit / capper_off);
}

/// The chart under each priority.
template <bsc::priority P>
inline constexpr auto chart = station_chart<P>();

/// A station scanned by a PLC: condition-driven rows fire only in step(), one per scan.
template <bsc::priority P>
using machine = bsc::machine<bsc::chart_ref<chart<P>>, bsc::scan_policy>;

/// The example's controller: the e-stop's row is tried before every row below it.
inline constexpr auto const& controller_chart = chart<bsc::parent_first>;
using controller = machine<bsc::parent_first>;

/// The PLC's scan period.
inline constexpr bsc::duration scan_period = 100ms;

}  // namespace filling
