#pragma once
// Every error bsc reports at compile time, in one place. Each is a class template whose
// arguments are the culprits (states, events, callables); the static_assert in its destructor
// says what is wrong and how to fix it, and its condition, dependent_false<the error type>,
// makes the compiler print the error's name with the culprits. The assertion sits in the
// destructor so that it fires where an error object is destroyed, not where the class is
// named: make_chart returns its findings as an object (detail::rejected_chart) whose
// destructor raises them from a function the compiler instantiates at the end of the
// translation unit, so the error's context is not make_chart<...the whole chart type...>.
// detail::report<E>() raises one anywhere else. docs/checks.md lists them all with an example
// each.

#include <cstddef>
#include <type_traits>

#include <bsc/detail/fixed_string.hpp>
#include <bsc/detail/meta.hpp>

namespace bsc::error {

// ---- the static checks of a chart (bsc::make_chart) ----------------------------------------

template <class State>
struct unreachable_state {
    constexpr ~unreachable_state() {
        static_assert(detail::dependent_false<unreachable_state>,
                      "bsc: unreachable state: no initial entry, history or transition can activate this state "
                      "from the initial configuration; add a transition to it (or make it an initial child), or "
                      "remove it");
    }
};

template <class State>
struct dead_end_state {
    constexpr ~dead_end_state() {
        static_assert(detail::dependent_false<dead_end_state>,
                      "bsc: dead end: no transition leaves this non-final state (neither from it, nor from an "
                      "ancestor, nor from an orthogonal region); add one, or declare it with bsc::final_state");
    }
};

template <class Source, class Trigger>
struct conflicting_transitions {
    constexpr ~conflicting_transitions() {
        static_assert(detail::dependent_false<conflicting_transitions>,
                      "bsc: conflicting transitions: two unguarded transitions leave this state on the same "
                      "trigger, so the chart is nondeterministic; guard one of them or remove one");
    }
};

template <class Source, class Trigger, class Target>
struct shadowed_transition {
    constexpr ~shadowed_transition() {
        static_assert(detail::dependent_false<shadowed_transition>,
                      "bsc: shadowed transition: an earlier unguarded transition from this state on the same "
                      "trigger (or on a family of it: a base class, or bsc::any_event) always wins, so the "
                      "transition to Target can never fire; guard the earlier one or move this one before it");
    }
};

template <class Source, class Trigger, class Target>
struct dead_transition {
    constexpr ~dead_transition() {
        static_assert(detail::dependent_false<dead_transition>,
                      "bsc: dead transition: this row can never fire: its source is a final child of the root "
                      "(the machine has halted there), or every state below its source takes the same event "
                      "first with an unguarded row of its own; remove the row, guard the rows below, or move it "
                      "(Target is bsc::detail::no_target for an internal row)");
    }
};

template <class Source, class Trigger, class Target, class Outer>
struct dead_transition_behind_outer {
    constexpr ~dead_transition_behind_outer() {
        static_assert(detail::dependent_false<dead_transition_behind_outer>,
                      "bsc: dead transition under parent-first priority: Outer, an ancestor of this row's source, "
                      "has an unguarded row on the same event (or on a family of it), which is tried first "
                      "whenever the source is active; remove the row, guard the outer row, or declare the chart "
                      "child-first (Target is bsc::detail::no_target for an internal row)");
    }
};

template <class Event>
struct event_in_two_families {
    constexpr ~event_in_two_families() {
        static_assert(detail::dependent_false<event_in_two_families>,
                      "bsc: event in two families: two triggers of the chart that do not derive from one another "
                      "are both base classes of this event, so it is unclear which rows take it; an event's "
                      "families (its base classes among the chart's triggers, and bsc::any_event) must form one "
                      "chain: derive one family from the other, or trigger no row with one of them");
    }
};

template <class HistoryState>
struct invalid_history_state {
    constexpr ~invalid_history_state() {
        static_assert(detail::dependent_false<invalid_history_state>,
                      "bsc: invalid history state: a history state (shallow_history_state<H, Default>, "
                      "deep_history_state<H, Default>) must be declared in a composite, its Default must be a "
                      "state inside that composite (not a history state), and it takes no rows but on_initial "
                      "(the action of its default transition); it is never active, so no transition leaves it");
    }
};

template <class Composite>
struct initial_states_not_orthogonal {
    constexpr ~initial_states_not_orthogonal() {
        static_assert(detail::dependent_false<initial_states_not_orthogonal>,
                      "bsc: initial states not orthogonal: the states named by bsc::initial<A, B, ...> must lie "
                      "below this composite, one in each of several regions of a parallel state (none containing "
                      "another); name one state per region");
    }
};

/// The states of a transition with several targets, as an error names them.
template <class... States>
struct target_states {};

template <class Source, class Targets>
struct targets_not_orthogonal {
    constexpr ~targets_not_orthogonal() {
        static_assert(detail::dependent_false<targets_not_orthogonal>,
                      "bsc: targets not orthogonal: a transition with several targets (bsc::targets) enters one "
                      "state in each of several regions of a parallel state, so no target may contain another, "
                      "and any two must lie in different regions of a parallel state; keep one target per "
                      "region");
    }
};

template <class Chart, class Event>
struct pending_events_not_encoded {
    constexpr ~pending_events_not_encoded() {
        static_assert(detail::dependent_false<pending_events_not_encoded>,
                      "bsc: a machine of this Chart keeps events from one call to the next (deferred by / "
                      "bsc::defer, or sent by bsc::raise_after), and the explorer (bsc::verify), bsc::save / "
                      "bsc::restore and bsc::net encode them with the rest of its state; this Event cannot be "
                      "encoded: it must be default-constructible, and each of its members (at any depth) bool, "
                      "an integer, an enum with a fixed underlying type, float, double, a std::chrono::duration, "
                      "or a std::array or struct of them (a std::string cannot); change the event, or leave the "
                      "chart's machine out of what is saved and explored");
    }
};

template <class Source, class Trigger>
struct invalid_deferral {
    constexpr ~invalid_deferral() {
        static_assert(detail::dependent_false<invalid_deferral>,
                      "bsc: invalid deferral: a row that defers (/ bsc::defer) keeps its event for later, so it "
                      "needs an event trigger (not eventless, not a timeout, not bsc::any_event, which would keep "
                      "only its tag) and no target; defer the events by name, one row each");
    }
};

template <class State>
struct initial_action_without_initial_transition {
    constexpr ~initial_action_without_initial_transition() {
        static_assert(detail::dependent_false<initial_action_without_initial_transition>,
                      "bsc: initial action of a state without an initial transition: an on_initial row runs when "
                      "a composite is entered through its initial state, and this state is not a composite, or "
                      "has a history marker (it is entered through its history instead); use on_entry, or remove "
                      "the history marker");
    }
};

template <class Source, class Target>
struct local_target_outside_source {
    constexpr ~local_target_outside_source() {
        static_assert(detail::dependent_false<local_target_outside_source>,
                      "bsc: local transition to a state outside its source: a local transition "
                      "(= bsc::local(state<Target>)) keeps its source active, so its target must lie below the "
                      "source; target a descendant, or make it an ordinary transition (= state<Target>)");
    }
};

template <class Source, class Target>
struct transition_between_orthogonal_regions {
    constexpr ~transition_between_orthogonal_regions() {
        static_assert(detail::dependent_false<transition_between_orthogonal_regions>,
                      "bsc: transition between orthogonal regions: the source and the target lie in different "
                      "regions of the same parallel state, which are always active together; target a state "
                      "outside the parallel state instead");
    }
};

template <class State>
struct state_not_in_chart {
    constexpr ~state_not_in_chart() {
        static_assert(detail::dependent_false<state_not_in_chart>,
                      "bsc: a row names a state that the state tree does not declare; declare it in the tree "
                      "(bsc::state, bsc::composite, bsc::parallel or bsc::final_state) or fix the row");
    }
};

// bsc::in<S> in a row's guard: S must be a state the tree declares, and one that can be active.
template <class State>
struct in_of_state_not_in_chart {
    constexpr ~in_of_state_not_in_chart() {
        static_assert(detail::dependent_false<in_of_state_not_in_chart>,
                      "bsc: a row's guard tests bsc::in<State>, but State is not a state of this chart (a misspelt "
                      "name, or a state of another chart), so whether it is active means nothing; name a state "
                      "that the tree declares");
    }
};

template <class State>
struct in_of_history_state {
    constexpr ~in_of_history_state() {
        static_assert(detail::dependent_false<in_of_history_state>,
                      "bsc: a row's guard tests bsc::in<State>, but State is a history pseudo-state "
                      "(shallow_history_state, deep_history_state), which is never active, so the test would "
                      "always be false; test the composite the history state belongs to, or one of its children");
    }
};

// machine.is<S>() of a state the tree does not declare (the row errors above are about rows).
template <class State>
struct queried_state_not_in_chart {
    constexpr ~queried_state_not_in_chart() {
        static_assert(detail::dependent_false<queried_state_not_in_chart>,
                      "bsc: is<State>() asks about a state that the chart's tree does not declare (a misspelt "
                      "name, or a state of another chart); name one of this chart's states");
    }
};

// ---- completion events (bsc::done<S>) --------------------------------------------------------

template <class State>
struct done_of_state_not_in_chart {
    constexpr ~done_of_state_not_in_chart() {
        static_assert(detail::dependent_false<done_of_state_not_in_chart>,
                      "bsc: a row takes bsc::done<State>, but State is not a state of this chart (a misspelt "
                      "name?), so the event is never raised and the row never fires; name a composite or "
                      "parallel state of the chart that has a final child");
    }
};

template <class State>
struct done_never_raised {
    constexpr ~done_never_raised() {
        static_assert(detail::dependent_false<done_never_raised>,
                      "bsc: a row takes bsc::done<State>, but State never completes, so the row never fires: "
                      "bsc::done<S> is raised when a composite S enters a final child (bsc::final_state), or "
                      "when every region of a parallel S is in a final state; never for a basic or final "
                      "state, a composite without a final child, a parallel state with a region that has "
                      "none, or the root (the machine halts); give State a final child, or take another event");
    }
};

template <class Source, class State>
struct done_source_inactive {
    constexpr ~done_source_inactive() {
        static_assert(detail::dependent_false<done_source_inactive>,
                      "bsc: a row on bsc::done<State> leaves Source, a state inside State that is no longer "
                      "active when State completes (then only State's final child is, and for a parallel "
                      "State its regions and their final children), so the row never fires; move the row to "
                      "State, to an ancestor of State, or to a state orthogonal to it");
    }
};

template <class State>
struct duplicate_state {
    constexpr ~duplicate_state() {
        static_assert(detail::dependent_false<duplicate_state>,
                      "bsc: this state is declared twice in the state tree; every state type may appear once");
    }
};

template <class Composite>
struct missing_initial_state {
    constexpr ~missing_initial_state() {
        static_assert(detail::dependent_false<missing_initial_state>,
                      "bsc: this composite state has no initial child; add bsc::initial<Child> to its declaration");
    }
};

template <class Composite>
struct multiple_initial_states {
    constexpr ~multiple_initial_states() {
        static_assert(detail::dependent_false<multiple_initial_states>,
                      "bsc: this composite state has more than one bsc::initial marker; keep exactly one");
    }
};

template <class Composite, class Initial>
struct initial_not_a_child {
    constexpr ~initial_not_a_child() {
        static_assert(detail::dependent_false<initial_not_a_child>,
                      "bsc: the initial state named by this composite is declared elsewhere in the tree, not inside "
                      "it; name one of its own children, or a state below it, in bsc::initial<...>");
    }
};

template <class State>
struct eventless_livelock {
    constexpr ~eventless_livelock() {
        static_assert(detail::dependent_false<eventless_livelock>,
                      "bsc: eventless livelock: unguarded eventless transitions from this state lead back to it "
                      "(or it has an unguarded eventless internal transition), so a dispatch would never settle; "
                      "guard one of the transitions on the cycle or give it an event");
    }
};

template <class Event>
struct unhandled_event {
    constexpr ~unhandled_event() {
        static_assert(detail::dependent_false<unhandled_event>,
                      "bsc: no transition of this chart is triggered by the dispatched event type; add one, fix "
                      "the event type, or dispatch with bsc::allow_unhandled to ignore it on purpose");
    }
};

template <class Policy>
struct last_outcome_not_kept {
    constexpr ~last_outcome_not_kept() {
        static_assert(detail::dependent_false<last_outcome_not_kept>,
                      "bsc: this machine's policy has keep_last_outcome = false, so it keeps no outcome: read the "
                      "outcome dispatch or step returns, or use a policy that keeps it (bsc::default_policy)");
    }
};

template <class Policy>
struct clock_not_kept {
    constexpr ~clock_not_kept() {
        static_assert(detail::dependent_false<clock_not_kept>,
                      "bsc: this machine keeps no clock: its policy has keep_clock = false and its chart has no "
                      "timeout, timer or delayed event, so nothing it does depends on time; keep the time of the "
                      "last step() yourself, or use a policy with keep_clock = true (bsc::default_policy)");
    }
};

template <class First, class Second>
struct duplicate_event_name {
    constexpr ~duplicate_event_name() {
        static_assert(detail::dependent_false<duplicate_event_name>,
                      "bsc: two events of this chart have the same name, so bsc::event_set cannot tell them apart by "
                      "name; give one of them a static member `name` of its own (static constexpr std::string_view "
                      "name = \"...\";)");
    }
};

template <class Event>
struct not_an_event_of_the_chart {
    constexpr ~not_an_event_of_the_chart() {
        static_assert(detail::dependent_false<not_an_event_of_the_chart>,
                      "bsc: bsc::event_set<Chart>::number_of<Event>: Event is none of the chart's events (the "
                      "trigger events of its rows, without bsc::done<S>, bsc::action_failed and bsc::any_event, "
                      "which the environment cannot send); see bsc::event_set<Chart>::events");
    }
};

template <class Event>
struct event_not_constructible {
    constexpr ~event_not_constructible() {
        static_assert(detail::dependent_false<event_not_constructible>,
                      "bsc: dispatch_by_name and dispatch_by_number build the event they dispatch: this event has no "
                      "default constructor, so pass a decoder that builds it, callable as "
                      "decode(std::type_identity<Event>{}) and returning the event");
    }
};

template <class Type>
struct not_an_event {
    constexpr ~not_an_event() {
        static_assert(detail::dependent_false<not_an_event>,
                      "bsc: bsc::event<E> needs E to be a complete, copyable class or enumeration type without "
                      "const or volatile (events are copied into the queue and handed to guards and actions); "
                      "void, references, arrays, functions and pointers are not events. For a transition without "
                      "an event, leave the trigger out: state<S> [guard] = state<T>");
    }
};

template <class Event>
struct raised_event_not_in_chart {
    constexpr ~raised_event_not_in_chart() {
        static_assert(detail::dependent_false<raised_event_not_in_chart>,
                      "bsc: an action raises an event type that no transition of this chart handles");
    }
};

// ---- events the environment cannot send ----------------------------------------------------

// machine.dispatch(e) of an event only the machine raises, or of the tag of a row on any event
// (detail::reserved_event in event_set.hpp).
template <class Event>
struct event_not_dispatchable {
    constexpr ~event_not_dispatchable() {
        static_assert(detail::dependent_false<event_not_dispatchable>,
                      "bsc: dispatch(e) of an event the environment cannot send: the machine raises "
                      "bsc::done<S> itself when S completes, and bsc::action_failed when one of its guards or "
                      "actions throws; bsc::any_event is the tag a row on every event receives, not an event. "
                      "Dispatch one of the chart's other events (bsc::event_set<Chart>::events), or reach the "
                      "state the done event would lead to with an event of your own");
    }
};

// ---- the arguments of bsc::make_chart ----------------------------------------------------

template <class Allowance>
struct finding_not_allowable {
    constexpr ~finding_not_allowable() {
        static_assert(detail::dependent_false<finding_not_allowable>,
                      "bsc: make_chart's third argument must be bsc::allow<...> of findings a chart may allow: "
                      "unreachable_state, dead_end_state, shadowed_transition, dead_transition, "
                      "dead_transition_behind_outer, conflicting_transitions, done_never_raised, "
                      "eventless_livelock (bsc::error::...); a malformed tree or an error in a row is never "
                      "allowed");
    }
};

template <class Argument>
struct not_a_row {
    constexpr ~not_a_row() {
        static_assert(detail::dependent_false<not_a_row>,
                      "bsc: after the state tree, every argument of make_chart must be a row: "
                      "state<S> + event<E> [guard] / action = state<T>, state<S> [guard] = state<T>, "
                      "state<S> + on_entry / action, or state<S> + on_exit / action");
    }
};

template <class Root>
struct root_must_be_composite {
    constexpr ~root_must_be_composite() {
        static_assert(detail::dependent_false<root_must_be_composite>,
                      "bsc: the first argument of make_chart is the root of the state tree and must be a "
                      "bsc::composite<...>(...) or bsc::parallel<...>(...)");
    }
};

// ---- the state tree -------------------------------------------------------------------------

template <class State, class Argument>
struct not_a_state_declaration {
    constexpr ~not_a_state_declaration() {
        static_assert(detail::dependent_false<not_a_state_declaration>,
                      "bsc: an argument of this state's declaration is not a state or marker; a composite takes "
                      "bsc::state, bsc::final_state, bsc::composite, bsc::parallel, bsc::initial, "
                      "bsc::shallow_history and bsc::deep_history; a parallel state takes states only");
    }
};

template <class State>
struct empty_parallel_state {
    constexpr ~empty_parallel_state() {
        static_assert(detail::dependent_false<empty_parallel_state>,
                      "bsc: this parallel state has no regions; give it at least one child state (a parallel "
                      "state's children are its regions), or declare it with bsc::state");
    }
};

template <class State>
struct conflicting_history_markers {
    constexpr ~conflicting_history_markers() {
        static_assert(detail::dependent_false<conflicting_history_markers>,
                      "bsc: this composite state has more than one history marker; keep one of "
                      "bsc::shallow_history or bsc::deep_history");
    }
};

// ---- the row of an error ---------------------------------------------------------------------

/// The row an error belongs to: `state<Source> + Trigger = state<Target>` (Trigger is the event,
/// bsc::detail::eventless_trigger, bsc::detail::timeout_trigger, or the entry_keyword /
/// exit_keyword of an `on_entry` / `on_exit` row; Target is bsc::detail::no_target for a row
/// without one). make_chart reports a guard or an action that cannot be called wrapped in it,
/// so that the error names its row.
template <class Source, class Trigger, class Target, class Error>
struct in_row {
    Error error;  // destroying it raises Error
};

/// The row as written, e.g. `as_written<"Idle + go [ready] = Busy">`: states and events by
/// their unqualified names, guards and actions by their bsc::named names ("guard" and "action"
/// when unnamed), a timeout as "after(...)".
template <detail::fixed_string Text>
struct as_written {};

/// Where a row's error is: the row's Position among make_chart's rows, counted from 1 with
/// bsc::rows groups expanded in place and entry/exit rows counted, and the row as_written. Every
/// error that concerns one row (a dead, shadowed or conflicting transition, a transition between
/// orthogonal regions, a state not in the chart, a guard or action that cannot be called) is
/// reported wrapped in it. Clang prints a string template argument as character codes, so with
/// Clang AsWritten is void and the row is identified by its position and the error's culprits.
template <std::size_t Position, class Error, class AsWritten = void>
struct at_row {
    Error error;  // destroying it raises Error
};

// ---- the context -----------------------------------------------------------------------------

template <class Type>
struct context_not_an_aggregate {
    constexpr ~context_not_an_aggregate() {
        static_assert(detail::dependent_false<context_not_an_aggregate>,
                      "bsc: the members of this type of the context cannot be found: it is not an aggregate (it has "
                      "private members, constructors or virtual functions); adapt it with Boost.Hana "
                      "(<bsc/adapt/hana.hpp>, BOOST_HANA_DEFINE_STRUCT) or specialise bsc::fields<Type>");
    }
};

template <class Type>
struct too_many_fields {
    constexpr ~too_many_fields() {
        static_assert(detail::dependent_false<too_many_fields>,
                      "bsc: this struct of the context has more than 128 fields; group some of them into nested "
                      "structs or std::arrays (channels and timers are found at any depth), or adapt it with "
                      "Boost.Hana (<bsc/adapt/hana.hpp>) or bsc::fields<Type>");
    }
};

template <class Type>
struct context_type_has_base_class {
    constexpr ~context_type_has_base_class() {
        static_assert(detail::dependent_false<context_type_has_base_class>,
                      "bsc: this struct of the context has a base class, whose members bsc cannot find by "
                      "itself; adapt it with Boost.Hana (<bsc/adapt/hana.hpp>) or specialise bsc::fields<Type> "
                      "to list every member, the base's included, or hold the base as a member");
    }
};

template <class Type>
struct context_type_has_c_array {
    constexpr ~context_type_has_c_array() {
        static_assert(detail::dependent_false<context_type_has_c_array>,
                      "bsc: this struct of the context has a C array member (T name[N]), which bsc cannot walk; "
                      "make it a std::array<T, N>, or adapt the struct with Boost.Hana (<bsc/adapt/hana.hpp>) or "
                      "bsc::fields<Type>");
    }
};

template <class Type>
struct hana_adapter_not_included {
    constexpr ~hana_adapter_not_included() {
        static_assert(detail::dependent_false<hana_adapter_not_included>,
                      "bsc: this Type of the context is adapted with BOOST_HANA_DEFINE_STRUCT, but bsc does not "
                      "see its members: #include <bsc/adapt/hana.hpp> before the machine is declared");
    }
};

/// The position of a member among its owner's, in declaration order from 0.
template <std::size_t Index>
struct member_number {};

template <class Owner, class Member, class Type>
struct state_out_of_reach {
    constexpr ~state_out_of_reach() {
        static_assert(detail::dependent_false<state_out_of_reach>,
                      "bsc: member Member of Owner (the context, or a struct in it) has a Type that may hold a "
                      "channel, a timer or a machine where bsc cannot reach it (inside std::optional, "
                      "std::variant, a container, a union, behind a pointer), so the machine would neither drive "
                      "it nor save, explore or record it; hold it directly, in a std::array or in a struct, or "
                      "say that it is not part of the machine's state: declare the member "
                      "bsc::transient_member<Type>, or specialise bsc::transient<Type> as true");
    }
};

template <class Type>
struct member_not_explorable {
    constexpr ~member_not_explorable() {
        static_assert(detail::dependent_false<member_not_explorable>,
                      "bsc: the explorer (bsc::verify) encodes scalars, enums, channels, timers, machines and "
                      "std::arrays and structs of them, and copies other members byte for byte when they are "
                      "trivially copyable; this Type is neither: make it one, or leave it out of the explored "
                      "state by specialising bsc::transient<Type> as true or declaring the member "
                      "bsc::transient_member<Type>");
    }
};

// ---- retentive state (bsc/retain.hpp) --------------------------------------------------------

template <class Type>
struct member_not_retainable {
    constexpr ~member_not_retainable() {
        static_assert(detail::dependent_false<member_not_retainable>,
                      "bsc: bsc::save and bsc::restore store bool, integers of up to 64 bits, enums with a fixed "
                      "underlying type, float, double, std::chrono::duration, channels, timers, machines, and "
                      "std::arrays and structs of them, none of whose members is const or a reference; the Type "
                      "in this error is none of those: make it one, or leave it out of the machine's state by "
                      "specialising bsc::transient<Type> as true or declaring the member "
                      "bsc::transient_member<Type> (a restored machine then keeps its own value of it)");
    }
};

// ---- guards and actions ----------------------------------------------------------------------

template <class Callable>
struct guard_signature_not_supported {
    constexpr ~guard_signature_not_supported() {
        static_assert(detail::dependent_false<guard_signature_not_supported>,
                      "bsc: a guard must be callable as g(context const&, event const&), g(context const&) or g(), "
                      "and return something convertible to bool; the Callable type in this error is the guard, "
                      "bsc::error::in_row<Source, Trigger, Target, ...> the row it belongs to, and "
                      "bsc::error::at_row<Position, ...> where that row is among make_chart's rows");
    }
};

// A guard that is a bool value: `!`, `&&` or `||` applied to plain lambdas converts them to
// function pointers and those to true, so the row gets the constant, not a condition.
template <class Value>
struct guard_is_a_bool_value {
    constexpr ~guard_is_a_bool_value() {
        static_assert(detail::dependent_false<guard_is_a_bool_value>,
                      "bsc: this row's guard is a bool value, not a condition: `!`, `&&` or `||` applied to a "
                      "plain lambda converts the lambda to a function pointer and that to true; wrap the lambda "
                      "in bsc::guard(...) so that the operators combine guards (bsc::guard(f) && g, "
                      "!bsc::guard(f)), or write the whole condition in one lambda");
    }
};

template <class Callable>
struct action_signature_not_supported {
    constexpr ~action_signature_not_supported() {
        static_assert(
            detail::dependent_false<action_signature_not_supported>,
            "bsc: an action must be callable as a(context&, event const&, raise&), a(context&, event const&), "
            "a(context&) or a(); an entry/exit action as a(context&, raise&), a(context&) or a(); see the "
            "Callable type in this error, in bsc::error::in_row<Source, Trigger, Target, ...> its row, and in "
            "bsc::error::at_row<Position, ...> where that row is among make_chart's rows");
    }
};

// ---- channels and systems (bsc/data/channel.hpp, bsc/system.hpp) ----------------------------
// Inputs are the environment's, outputs the chart's ([BSC]); a system's wiring is checked where
// the system type is instantiated. Actors and channels are named by their pointers to members.

template <class T>
struct input_written_by_the_chart {
    constexpr ~input_written_by_the_chart() {
        static_assert(detail::dependent_false<input_written_by_the_chart>,
                      "bsc: an action writes an input channel (bsc::input<T>::set on the context it receives as "
                      "Context&): inputs are the environment's, set between cycles through the machine's const "
                      "context() or by a system's links; publish the value through a bsc::output<T>, or make "
                      "the channel a bsc::inout<T> if both sides write it. A context built outside a machine "
                      "is not the environment's view either: give a channel its initial value in its "
                      "constructor (bsc::input<bool> start{true})");
    }
};

template <class T>
struct output_written_from_outside {
    constexpr ~output_written_from_outside() {
        static_assert(detail::dependent_false<output_written_from_outside>,
                      "bsc: an output channel is written from outside its chart (bsc::output<T>::set on the "
                      "const context a machine's context() returns, the environment's view): outputs are the "
                      "chart's, written by its actions; set one of the chart's inputs instead (bsc::input<T>, "
                      "or bsc::inout<T> if both sides write it), or give the output its initial value in its "
                      "constructor (bsc::output<bool> lamp{true})");
    }
};

template <class Entry>
struct not_a_link {
    constexpr ~not_a_link() {
        static_assert(detail::dependent_false<not_a_link>,
                      "bsc: after the actors and the order, every argument of bsc::system must be a "
                      "bsc::link<&Actors::from, &FromContext::output, &Actors::to, &ToContext::input, options...> "
                      "or a bsc::from_outside<&Actors::actor, &Context::input>; remove or fix this Entry");
    }
};

template <class Option>
struct invalid_link_option {
    constexpr ~invalid_link_option() {
        static_assert(detail::dependent_false<invalid_link_option>,
                      "bsc: this Option of a bsc::link is none of bsc::hold_last, bsc::fail_safe<V>, "
                      "bsc::lossless and bsc::convert<F>, or it is a second one of a kind: a link takes at "
                      "most one staleness policy (hold_last, fail_safe<V> or lossless) and at most one "
                      "bsc::convert; remove it, or fix it");
    }
};

template <auto Actor>
struct actor_twice_in_order {
    constexpr ~actor_twice_in_order() {
        static_assert(detail::dependent_false<actor_twice_in_order>,
                      "bsc: this Actor is named twice in the system's bsc::order, so every system step would "
                      "step it twice; name it once");
    }
};

template <auto Actor>
struct actor_not_in_order {
    constexpr ~actor_not_in_order() {
        static_assert(detail::dependent_false<actor_not_in_order>,
                      "bsc: a bsc::link or bsc::from_outside of the system names this Actor, but the system's "
                      "bsc::order does not, so it would never step and its links would never carry anything; "
                      "add it to the order (or remove the entries that name it)");
    }
};

template <auto Actor, auto Channel>
struct link_source_not_an_output {
    constexpr ~link_source_not_an_output() {
        static_assert(detail::dependent_false<link_source_not_an_output>,
                      "bsc: the source of a bsc::link must be an output of its actor: Channel must name a "
                      "bsc::output<T> or bsc::inout<T> member of the context of Actor's machine (a link carries "
                      "what its source publishes; an input is what the source reads, a plain member its "
                      "internal variable); link from an output, or make the member one");
    }
};

template <auto Actor, auto Channel>
struct link_target_not_an_input {
    constexpr ~link_target_not_an_input() {
        static_assert(detail::dependent_false<link_target_not_an_input>,
                      "bsc: the target of a bsc::link must be an input of its actor: Channel must name a "
                      "bsc::input<T> or bsc::inout<T> member of the context of Actor's machine (a link writes "
                      "what its target reads from outside; an output is the target's own to write, a plain "
                      "member its internal variable); link to an input, or make the member one");
    }
};

template <auto FromChannel, auto ToChannel, class From, class To>
struct link_value_types_differ {
    constexpr ~link_value_types_differ() {
        static_assert(detail::dependent_false<link_value_types_differ>,
                      "bsc: this bsc::link carries a From into a channel of To, a conversion that would "
                      "happen in silence (300 to true, 2.7 to 2); give both channels the same value type, or "
                      "make the conversion explicit with the option bsc::convert<F> (the target then reads "
                      "F(value))");
    }
};

template <class Convert, class From, class To>
struct link_conversion_not_applicable {
    constexpr ~link_conversion_not_applicable() {
        static_assert(detail::dependent_false<link_conversion_not_applicable>,
                      "bsc: the bsc::convert<F> of a link cannot convert its value: F must be callable with "
                      "the source's value (a From const&) and return something that converts to the target's "
                      "value type (To); fix F, or link channels of the types it converts");
    }
};

template <auto Actor, auto Channel>
struct input_driven_twice {
    constexpr ~input_driven_twice() {
        static_assert(detail::dependent_false<input_driven_twice>,
                      "bsc: two links of the system drive this input (Channel of Actor), and in every step the "
                      "later would overwrite the earlier in silence; keep one link into it (give the actor an "
                      "input for each signal, and combine them in its guards)");
    }
};

template <auto Actor, class Member, detail::fixed_string Name>
struct input_not_driven {
    constexpr ~input_not_driven() {
        static_assert(detail::dependent_false<input_not_driven>,
                      "bsc: no link of the system drives this input of Actor (member Member of its context, "
                      "named Name), so it would keep whatever it was given; link an output to it, or, if the "
                      "environment sets it between steps (a switch, a sensor outside the system), declare it "
                      "among the system's links with bsc::from_outside<&Actors::actor, &Context::channel>");
    }
};

template <auto Actor, auto Channel>
struct from_outside_not_an_input {
    constexpr ~from_outside_not_an_input() {
        static_assert(detail::dependent_false<from_outside_not_an_input>,
                      "bsc: bsc::from_outside must name an input of its actor: Channel must name a "
                      "bsc::input<T> or bsc::inout<T> member of the context of Actor's machine (the "
                      "environment sets inputs; an output is the chart's to write, a plain member its internal "
                      "variable); name an input, or remove the entry");
    }
};

template <auto Actor, auto Channel>
struct input_linked_and_from_outside {
    constexpr ~input_linked_and_from_outside() {
        static_assert(detail::dependent_false<input_linked_and_from_outside>,
                      "bsc: this input (Channel of Actor) is declared bsc::from_outside, but a link of the "
                      "system drives it too, and would overwrite in every step what the environment set; "
                      "remove the bsc::from_outside entry, or the link");
    }
};

}  // namespace bsc::error

namespace bsc::detail {

/// Raises the error E: the temporary's destruction instantiates E's destructor, whose
/// static_assert is the error. Returns false, for the checks that go on after reporting.
template <class Error>
constexpr bool report() {
    [[maybe_unused]] Error const error{};
    return false;
}

// Raises Error from a function that is not constexpr: compilers instantiate such a function
// at the end of the translation unit, outside the instantiation of make_chart, so the error's
// context is this function alone and not the chain of templates that spell the whole chart.
template <class Error>
void raise_deferred() {
    [[maybe_unused]] Error const error{};
}

/// What make_chart returns for a chart that fails its checks: the errors found, raised when
/// the object is destroyed outside constant evaluation (the destructor is instantiated
/// whenever a chart variable is declared, so every error is reported once), and the context
/// type, so that a machine declared on it (detail/runtime/rejected.hpp) stays silent instead of
/// adding errors of its own.
template <class Context, class... Errors>
struct rejected_chart {
    using context_type = Context;
    constexpr ~rejected_chart() {
        if (!std::is_constant_evaluated()) (raise_deferred<Errors>(), ...);
    }
};

template <class T>
inline constexpr bool is_rejected_chart = false;
template <class Context, class... Errors>
inline constexpr bool is_rejected_chart<rejected_chart<Context, Errors...>> = true;

}  // namespace bsc::detail
