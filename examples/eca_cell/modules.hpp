#pragma once
// A modular finite state machine (MFSM) controller built as an Event-Condition-Action (ECA)
// system, from the paper "Modular finite state machines implemented as event-condition-action
// systems" (IFAC 2005). The plant is a push button, a robot and a light: pressing the button
// lights the light and has the robot pick and place a part; releasing the button, or pressing
// it while the robot is busy, has no effect; the light goes out when the robot has finished
// (section 2.1). This file is the ECA MFSM controller of the paper's Figure 5: a Main module
// that holds the ECA rules and two Peripheral modules that only keep state. pause.hpp adds the
// Pause module of section 4 without changing anything here.
//
// How the paper maps to this file:
//
//   Paper                                    Code
//   ---------------------------------------  ---------------------------------------------------
//   input events Σin: button rise and fall,  eca::in::press, in::release, in::done
//     the robot's end of job
//   output events Σout: pick and place,      eca::out::start, out::light_on, out::light_off,
//     light on, light off                      received by eca::environment (the plant's side)
//   Peripheral module keeping the button's   eca::button::chart: Button (Released, Pressed)
//     state (as User in Figure 1)
//   Peripheral module keeping the robot's    eca::robot::chart: Robot (Idle, Busy)
//     state (as Controller in Figure 1)
//   updating events Σu (Main -> Peripheral)  button::set_pressed, set_released,
//                                            robot::set_busy, set_idle
//   modular query Q = c {d1..dn}             a guard reading the Peripheral module's state:
//     (Definition 2)                           robot_is<robot::Idle>, robot_is<robot::Busy>
//   Main, its stable state IDLE              eca::Main, eca::Idle
//   one transient state per modular query    eca::QueryRobotOnPress (Figure 5's only query)
//   ECA rule t c {(da)1, (da)2 ...}          eca::rule_press, rule_release, rule_done: each
//     (Definition 6)                           returns the rule's rows, given its trigger t
//   control transaction (Definition 8)       one dispatch of an input event to Main: the
//                                              rows from Idle back to Idle
//   the ECA MFSM system (Definition 9)       eca::controller: Main's machine; its context
//                                              eca::main_connections holds the Peripheral
//                                              modules and the environment
//   one scan of the PLC                      eca::scan(controller, input event)
//
// The paper's figures are drawings; the rules here are written from its prose and from the
// counts it gives: Figure 5's Main has 4 control transactions, and the extension of section 4
// adds the transient states 2 to 5 (so Figure 5 has one query, transient state 1). Where the
// prose is silent the choice is marked "Paper silent:".
//
// Paper silent: what the two Peripheral modules keep. They "perform the same state tracking
// as the modules in Figure 1", User and Controller: the button's state and the robot's. The
// light is not a module: light on and light off are Main's output events, and a Peripheral
// module may not talk to the environment (section 3.1). No rule of Figure 5 needs to ask
// Button anything (a release has no effect); Main keeps it up to date.
//
// How an ECA rule maps to bsc. Main is one chart. Its only stable state is Idle; each modular
// query is a transient state. A rule is the rows of one query:
//
//   trigger = state<Query>                                       t: an input event in Idle,
//                                                                   or a response of an
//                                                                   earlier query
//   state<Query> [robot_is<robot::Idle>] / (actions) = state<Idle>  c d1 a1
//   state<Query> [robot_is<robot::Busy>] / (actions) = state<Idle>  c d2 a2
//
// The event is a bsc event dispatched to Main. The condition is the query: an eventless row
// out of the transient state, guarded by the Peripheral module's answer, that is its active
// state (a query does not change the module, Definition 1, and a guard may not change
// anything). The actions are updating events dispatched to the Peripheral modules, which
// process them at once, and output events sent to the environment. A rule may also lead to
// the next query's transient state instead of Idle: that response is the next rule's trigger.
// Since dispatch runs to completion, taking eventless transitions until none is enabled, Main
// is back in Idle when the dispatch returns: the transient states are never seen between
// scans (Definition 3), and the whole transaction, queries included, happens in one scan.
//
// Why events and not bsc::system. The paper's modules talk by events, and a trigger cascades
// through them before the next external event. A bsc::system links output channels to input
// channels: values, published at the end of a cycle, read in the next one. An updating event
// would have to be a value that Main holds from one scan to the next (Main would keep state,
// against Definition 4). And a component takes at most one condition-driven transition per
// cycle, so a transaction through transient states would last several cycles, leaving Main in
// a transient state at the start of a scan (against Definition 3).
// So the composition here is explicit: Main's context holds its Peripheral modules, which
// nothing else can reach (Definition 5: one connection, to Main), and its rows dispatch to
// them.
//
// Reuse. A rule is a function of its trigger, and Main's tree and context are parameters, so
// that pause.hpp can build a second Main from these same rules: the paper extends the
// controller "without altering pre-existing rules (other than changing the triggering event of
// some rules), and without altering the logic in the pre-existing modules". The guards and
// actions accept any Main context with members `button`, `robot` and `env`.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>

#include <bsc/bsc.hpp>

namespace eca {

// ---- External events -----------------------------------------------------------------------

/// Σin, the input events from the plant. `name` is how the example prints them.
namespace in {
struct press {  // the push button's rise
    static constexpr std::string_view name = "press";
};
struct release {  // the push button's fall
    static constexpr std::string_view name = "release";
};
struct done {  // the robot has finished picking and placing a part
    static constexpr std::string_view name = "done";
};
}  // namespace in

/// Σout, the output events to the plant.
namespace out {
struct start {  // the robot: pick and place a part
    static constexpr std::string_view name = "start";
};
struct light_on {
    static constexpr std::string_view name = "light_on";
};
struct light_off {
    static constexpr std::string_view name = "light_off";
};
}  // namespace out

/// The output events of one scan, in the order Main sent them (at most 2 in this model).
struct output_list {
    std::array<std::string_view, 4> names{};
    std::size_t size = 0;
    constexpr void push(std::string_view name) {
        if (size < names.size()) names[size++] = name;
    }
    /// This list and then `name`.
    constexpr output_list and_then(std::string_view name) const {
        output_list longer = *this;
        longer.push(name);
        return longer;
    }
    constexpr bool empty() const { return size == 0; }
    /// "start light_on", or "" when the scan sent nothing.
    std::string joined() const {
        std::string s;
        for (std::size_t i = 0; i < size; ++i) {
            if (i) s += ' ';
            s += names[i];
        }
        return s;
    }
};

/// The environment's end of Σout: what the plant does with Main's output events.
struct environment {
    bool light = false;  ///< the light: lit by light_on, put out by light_off
    int jobs = 0;        ///< pick-and-place jobs the robot has been told to do
    /// The output events of the current scan: Main's actions append to it, the environment
    /// empties it before each scan (scan()), so both write it: a bsc::inout channel, read once
    /// the scan has published it (sent.get()).
    bsc::inout<output_list> sent{};
    constexpr void receive(out::start) {
        ++jobs;
        sent.set(sent.pending().and_then(out::start::name));
    }
    constexpr void receive(out::light_on) {
        light = true;
        sent.set(sent.pending().and_then(out::light_on::name));
    }
    constexpr void receive(out::light_off) {
        light = false;
        sent.set(sent.pending().and_then(out::light_off::name));
    }
};

// ---- Peripheral modules: they keep state and nothing else ----------------------------------
// Their only triggers are Main's updating events; their state is read by Main's queries. They
// know nothing of Main, of the plant or of each other (section 3.5).

/// A Peripheral module has no data: its state is its active configuration.
struct no_data {};

namespace button {
struct Button;
struct Released;
struct Pressed;
struct set_pressed {};  // Σu
struct set_released {};
inline constexpr auto chart = bsc::make_chart<no_data>(
    bsc::composite<Button>(bsc::initial<Released>, bsc::state<Pressed>),
    bsc::state<Released> + bsc::event<set_pressed> = bsc::state<Pressed>,
    bsc::state<Pressed> + bsc::event<set_released> = bsc::state<Released>);
using module = bsc::machine<bsc::chart_ref<chart>>;
}  // namespace button

namespace robot {
struct Robot;
struct Idle;
struct Busy;
struct set_busy {};  // Σu
struct set_idle {};
inline constexpr auto chart = bsc::make_chart<no_data>(bsc::composite<Robot>(bsc::initial<Idle>, bsc::state<Busy>),
                                                       bsc::state<Idle> + bsc::event<set_busy> = bsc::state<Busy>,
                                                       bsc::state<Busy> + bsc::event<set_idle> = bsc::state<Idle>);
using module = bsc::machine<bsc::chart_ref<chart>>;
}  // namespace robot

// ---- Main's vocabulary: queries, updates, outputs ------------------------------------------
// Each guard and action is named (bsc::named) in the paper's terms, which the diagrams of Main
// show: a query by its module and answer ("Robot?Idle"), an update by its updating event
// ("set_busy"), an output by its output event ("light_on").

/// The concatenation of Parts, as a character array that bsc::named<...> takes: the names
/// below are computed from the types, and kept in the types (no storage at run time).
template <std::size_t N>
struct name_text {
    char text[N];
};
template <std::string_view const&... Parts>
inline constexpr auto joined_name = [] {
    name_text<(Parts.size() + ... + 1)> out{};
    std::size_t at = 0;
    for (std::string_view const part : {Parts...})
        for (char const c : part) out.text[at++] = c;
    return out;
}();

inline constexpr std::string_view robot_query = "Robot?";

/// The modular query "Robot?" answered S (a guard: it reads the module, never changes it).
template <class S>
inline constexpr auto robot_is = bsc::named<joined_name<robot_query, bsc::name_of<S>>.text>(
    bsc::guard([](auto const& main) { return main.robot.template is<S>(); }));

/// The updating event U, sent to the Robot module and processed by it at once.
template <class U>
inline constexpr auto update_robot = bsc::named<joined_name<bsc::name_of<U>>.text>(bsc::action([](auto& main) {
    main.robot.dispatch(U{});
}));
/// The updating event U, sent to the Button module and processed by it at once.
template <class U>
inline constexpr auto update_button = bsc::named<joined_name<bsc::name_of<U>>.text>(bsc::action([](auto& main) {
    main.button.dispatch(U{});
}));

/// The output event O, sent to the environment.
template <class O>
inline constexpr auto emit = bsc::named<joined_name<O::name>.text>(bsc::action([](auto& main) {
    main.env.receive(O{});
}));

// ---- Main ----------------------------------------------------------------------------------

struct Main;
struct Idle;               // IDLE: the only stable state (Definition 4)
struct QueryRobotOnPress;  // transient state 1: "Robot?" after press

/// Main's state tree: Idle, then one transient state per modular query. `added` are the
/// transient states of an extension's rules.
constexpr auto main_tree(auto... added) {
    return bsc::composite<Main>(bsc::initial<Idle>, bsc::state<QueryRobotOnPress>, added...);
}

/// The trigger "input event E, in Idle": how a control transaction starts.
template <class E>
inline constexpr auto on = bsc::state<Idle> + bsc::event<E>;

// The ECA rules of Figure 5, one function each: given the rule's trigger, the rule's rows.
// Rule 1 and rule 3 are the ones whose trigger the extension changes.

/// Rule 1. Event: press. Query: Robot?
///   Idle -> Button pressed, Robot busy; start the robot, light on.
///   Busy -> Button pressed; nothing else: a press while the robot is busy has no effect.
constexpr auto rule_press(auto trigger) {
    return std::tuple{
        trigger = bsc::state<QueryRobotOnPress>,
        bsc::state<QueryRobotOnPress>[robot_is<robot::Idle>] / (update_button<button::set_pressed>,
                                                                update_robot<robot::set_busy>, emit<out::start>,
                                                                emit<out::light_on>) = bsc::state<Idle>,
        bsc::state<QueryRobotOnPress>[robot_is<robot::Busy>] / update_button<button::set_pressed> = bsc::state<Idle>,
    };
}

/// Rule 2. Event: release. No query.
///   -> Button released; nothing else: releasing the button has no effect.
constexpr auto rule_release(auto trigger) {
    return std::tuple{trigger / update_button<button::set_released> = bsc::state<Idle>};
}

/// Rule 3. Event: done. No query (Paper silent: done comes only from a busy robot, so the
/// answer of "Robot?" would be known).
///   -> Robot idle; light off.
constexpr auto rule_done(auto trigger) {
    return std::tuple{trigger / (update_robot<robot::set_idle>, emit<out::light_off>) = bsc::state<Idle>};
}

/// Main's chart from its tree and its rows (a tuple of rows, such as the rules above return,
/// joined with std::tuple_cat). The static checks run as for any chart: a rule given no
/// trigger leaves its transient state unreachable (bsc::error::unreachable_state), and a rule
/// left on its old input event beside the new rule that takes that event makes Idle
/// nondeterministic (bsc::error::conflicting_transitions). A query that forgets one of its
/// responses is not a static error: Main would stay in the transient state; the tests check
/// that Main is back in Idle after every scan.
template <class Context, class Tree, class Rows>
constexpr auto make_main(Tree tree, Rows rows) {
    return std::apply([tree](auto... row) { return bsc::make_chart<Context>(tree, row...); }, rows);
}

/// Main's connections (Definition 4): one to each Peripheral module and one to the
/// environment. The Peripheral modules live here, so Main is the only module that reaches them.
struct main_connections {
    button::module button{button::chart};
    robot::module robot{robot::chart};
    environment env{};
};

/// The rules of Figure 5, each triggered by its input event in Idle.
inline constexpr auto main_rules = std::tuple_cat(rule_press(on<in::press>), rule_release(on<in::release>),
                                                  rule_done(on<in::done>));

inline constexpr auto main_chart = make_main<main_connections>(main_tree(), main_rules);

/// The ECA MFSM controller of Figure 5: Main, and through its context the Peripheral modules.
using controller = bsc::machine<bsc::chart_ref<main_chart>>;

/// One scan: Main processes the input event e to completion, the Peripheral modules process
/// the updating events it sends them as it goes, and `env.sent.get()` lists the output events
/// of this scan. Returns Main's outcome (consumed: a rule fired).
template <class Controller, class E>
constexpr bsc::outcome scan(Controller& c, E const& e) {
    c.context().env.sent.set({});
    return c.dispatch(e);
}

}  // namespace eca
