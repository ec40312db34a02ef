#pragma once
// The extension of section 4 of the ECA MFSM paper: a Pause button is added to the push
// button / robot / light controller of modules.hpp. Its rise and fall are the input events
// pause and continue, which alternate. After a pause the light stays on once the robot has
// finished its job, and further requests are ignored: the light tells that the robot is
// effectively still busy, since it is paused. Continue brings the system back to normal mode.
//
// The paper adds a Peripheral module Pause and ECA rules, "without altering pre-existing rules
// (other than changing the triggering event of some rules), and without altering the logic in
// the pre-existing modules"; the transactions are "simply elongated by more queries", which
// are the new transient states 2 to 5 of its Figure 7b. Here:
//
//   - modules.hpp is included as it is. The Button and Robot modules are the same charts
//     (button::chart, robot::chart); Main's rules 1, 2 and 3 are the same functions
//     (rule_press, rule_release, rule_done), given other triggers for rules 1 and 3.
//   - The new module is eca::pause::chart: Pause (Running, Paused).
//   - The new rules are rule_pause_on_press, rule_pause_on_done, rule_pause, rule_continue,
//     with the transient states 2 to 5 below.
//   - The extended Main is a second chart, built by make_main from Main's tree with the new
//     transient states added and from the old and new rules; its context,
//     extended_connections, adds the connection to Pause. A bsc chart is closed once declared,
//     so an extension cannot add rows to main_chart itself; it declares a new Main from the
//     same parts, and the original controller stays available, unchanged, beside it.
//
// The transactions of the extended Main (each from Idle back to Idle, in one scan):
//
//   press     Pause? Paused  -> Button pressed (the request is ignored)             rule 4
//                    Running -> Robot? ... as before                                 rule 1
//   release   Button released                                                        rule 2
//   done      Pause? Paused  -> Robot idle (the light stays on)                      rule 5
//                    Running -> Robot idle, light off, as before                     rule 3
//   pause     Robot? Idle    -> Pause paused, light on                               rule 6
//                    Busy    -> Pause paused (the light is on already)
//   continue  Robot? Idle    -> Pause running, light off                             rule 7
//                    Busy    -> Pause running (done will put the light out)
//
// Paper silent: what pause does while the robot is idle. Since "the light in this case
// indicates that the robot is effectively still busy since it is in a paused state", the
// light is on whenever the cell is paused; rules 6 and 7 make it so, and they are the queries
// that make up the count of four new transient states (with those of rules 4 and 5).

#include <string_view>
#include <tuple>

#include "modules.hpp"

namespace eca {

/// The new input events: the Pause button's rise and fall.
namespace in {
struct pause {
    static constexpr std::string_view name = "pause";
};
struct continue_ {  // the paper's "continue", a C++ keyword
    static constexpr std::string_view name = "continue";
};
}  // namespace in

// ---- The new Peripheral module -------------------------------------------------------------

namespace pause {
struct Pause;
struct Running;
struct Paused;
struct set_paused {};  // Σu
struct set_running {};
inline constexpr auto chart = bsc::make_chart<no_data>(
    bsc::composite<Pause>(bsc::initial<Running>, bsc::state<Paused>),
    bsc::state<Running> + bsc::event<set_paused> = bsc::state<Paused>,
    bsc::state<Paused> + bsc::event<set_running> = bsc::state<Running>);
using module = bsc::machine<bsc::chart_ref<chart>>;
}  // namespace pause

inline constexpr std::string_view pause_query = "Pause?";

/// The modular query "Pause?" answered S.
template <class S>
inline constexpr auto pause_is = bsc::named<joined_name<pause_query, bsc::name_of<S>>.text>(
    bsc::guard([](auto const& main) { return main.pause.template is<S>(); }));
/// The updating event U, sent to the Pause module.
template <class U>
inline constexpr auto update_pause = bsc::named<joined_name<bsc::name_of<U>>.text>(bsc::action([](auto& main) {
    main.pause.dispatch(U{});
}));

// ---- The new transient states and rules ----------------------------------------------------

struct QueryPauseOnPress;     // transient state 2: "Pause?" after press
struct QueryPauseOnDone;      // transient state 3: "Pause?" after done
struct QueryRobotOnPause;     // transient state 4: "Robot?" after pause
struct QueryRobotOnContinue;  // transient state 5: "Robot?" after continue

/// Rule 4. Event: press. Query: Pause?
///   Paused  -> Button pressed; the request is ignored.
///   Running -> the trigger of rule 1 (given in extended_rules).
constexpr auto rule_pause_on_press(auto trigger) {
    return std::tuple{
        trigger = bsc::state<QueryPauseOnPress>,
        bsc::state<QueryPauseOnPress>[pause_is<pause::Paused>] / update_button<button::set_pressed> = bsc::state<Idle>,
    };
}

/// Rule 5. Event: done. Query: Pause?
///   Paused  -> Robot idle; the light stays on.
///   Running -> the trigger of rule 3 (given in extended_rules).
constexpr auto rule_pause_on_done(auto trigger) {
    return std::tuple{
        trigger = bsc::state<QueryPauseOnDone>,
        bsc::state<QueryPauseOnDone>[pause_is<pause::Paused>] / update_robot<robot::set_idle> = bsc::state<Idle>,
    };
}

/// Rule 6. Event: pause. Query: Robot?
///   Idle -> Pause paused; light on.
///   Busy -> Pause paused.
constexpr auto rule_pause(auto trigger) {
    return std::tuple{
        trigger = bsc::state<QueryRobotOnPause>,
        bsc::state<QueryRobotOnPause>[robot_is<robot::Idle>] /
            (update_pause<pause::set_paused>, emit<out::light_on>) = bsc::state<Idle>,
        bsc::state<QueryRobotOnPause>[robot_is<robot::Busy>] / update_pause<pause::set_paused> = bsc::state<Idle>,
    };
}

/// Rule 7. Event: continue. Query: Robot?
///   Idle -> Pause running; light off.
///   Busy -> Pause running.
constexpr auto rule_continue(auto trigger) {
    return std::tuple{
        trigger = bsc::state<QueryRobotOnContinue>,
        bsc::state<QueryRobotOnContinue>[robot_is<robot::Idle>] /
            (update_pause<pause::set_running>, emit<out::light_off>) = bsc::state<Idle>,
        bsc::state<QueryRobotOnContinue>[robot_is<robot::Busy>] / update_pause<pause::set_running> = bsc::state<Idle>,
    };
}

// ---- The extended controller ---------------------------------------------------------------

/// Main's connections, with one more Peripheral module.
struct extended_connections {
    button::module button{button::chart};
    robot::module robot{robot::chart};
    pause::module pause{pause::chart};
    environment env{};
};

/// The rules of the extended Main: the new ones, then those of Figure 5 with the triggers of
/// rules 1 and 3 changed from an input event to a response of Pause.
inline constexpr auto extended_rules = std::tuple_cat(
    rule_pause_on_press(on<in::press>),                                   // rule 4
    rule_pause_on_done(on<in::done>),                                     // rule 5
    rule_pause(on<in::pause>),                                            // rule 6
    rule_continue(on<in::continue_>),                                     // rule 7
    rule_press(bsc::state<QueryPauseOnPress>[pause_is<pause::Running>]),  // rule 1, new trigger
    rule_release(on<in::release>),                                        // rule 2
    rule_done(bsc::state<QueryPauseOnDone>[pause_is<pause::Running>]));   // rule 3, new trigger

inline constexpr auto extended_main_chart = make_main<extended_connections>(
    main_tree(bsc::state<QueryPauseOnPress>, bsc::state<QueryPauseOnDone>, bsc::state<QueryRobotOnPause>,
              bsc::state<QueryRobotOnContinue>),
    extended_rules);

/// The controller of Figure 7b: the extended Main with Button, Robot and Pause.
using extended_controller = bsc::machine<bsc::chart_ref<extended_main_chart>>;

}  // namespace eca
