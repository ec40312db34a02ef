#pragma once
// Every error bsc reports at compile time, in one place. Each is a class template whose
// arguments are the culprits (states, events, callables), so the compiler's "in instantiation
// of" line names them; its static_assert says what is wrong and how to fix it.
// docs/checks.md lists them all with an example each.

#include <bsc/detail/meta.hpp>

namespace bsc::error {

// ---- the static checks of a chart (bsc::make_chart) ----------------------------------------

template <class State>
struct unreachable_state {
    static_assert(detail::dependent_false<State>,
                  "bsc: unreachable state: no initial entry, history or transition can activate this state "
                  "from the initial configuration; add a transition to it (or make it an initial child), or "
                  "remove it");
    static constexpr bool value = false;
};

template <class State>
struct dead_end_state {
    static_assert(detail::dependent_false<State>,
                  "bsc: dead end: no transition leaves this non-final state (neither from it, nor from an "
                  "ancestor, nor from an orthogonal region); add one, or declare it with bsc::final_state");
    static constexpr bool value = false;
};

template <class Source, class Trigger>
struct conflicting_transitions {
    static_assert(detail::dependent_false<Source>,
                  "bsc: conflicting transitions: two unguarded transitions leave this state on the same "
                  "trigger, so the chart is nondeterministic; guard one of them or remove one");
    static constexpr bool value = false;
};

template <class Source, class Trigger, class Target>
struct shadowed_transition {
    static_assert(detail::dependent_false<Source>,
                  "bsc: shadowed transition: an earlier unguarded transition from this state on the same "
                  "trigger always wins, so the transition to Target can never fire; guard the earlier one or "
                  "move this one before it");
    static constexpr bool value = false;
};

template <class Source, class Target>
struct transition_between_orthogonal_regions {
    static_assert(detail::dependent_false<Source>,
                  "bsc: transition between orthogonal regions: the source and the target lie in different "
                  "regions of the same parallel state, which are always active together; target a state "
                  "outside the parallel state instead");
    static constexpr bool value = false;
};

template <class State>
struct state_not_in_chart {
    static_assert(detail::dependent_false<State>,
                  "bsc: a row names a state that the state tree does not declare; declare it in the tree "
                  "(bsc::state, bsc::composite, bsc::parallel or bsc::final_state) or fix the row");
    static constexpr bool value = false;
};

template <class State>
struct duplicate_state {
    static_assert(detail::dependent_false<State>,
                  "bsc: this state is declared twice in the state tree; every state type may appear once");
    static constexpr bool value = false;
};

template <class Composite>
struct missing_initial_state {
    static_assert(detail::dependent_false<Composite>,
                  "bsc: this composite state has no initial child; add bsc::initial<Child> to its declaration");
    static constexpr bool value = false;
};

template <class Composite>
struct multiple_initial_states {
    static_assert(detail::dependent_false<Composite>,
                  "bsc: this composite state has more than one bsc::initial marker; keep exactly one");
    static constexpr bool value = false;
};

template <class Composite, class Initial>
struct initial_not_a_child {
    static_assert(detail::dependent_false<Composite>,
                  "bsc: the initial state named by this composite is declared elsewhere in the tree, not as "
                  "one of its children; name one of its own children in bsc::initial<...>");
    static constexpr bool value = false;
};

template <class Composite>
struct too_many_children {
    static_assert(detail::dependent_false<Composite>,
                  "bsc: a composite state may have at most 255 children (its active child is kept in one "
                  "byte); group some of them into a nested composite");
    static constexpr bool value = false;
};

template <class State>
struct eventless_livelock {
    static_assert(detail::dependent_false<State>,
                  "bsc: eventless livelock: unguarded eventless transitions from this state lead back to it "
                  "(or it has an unguarded eventless internal transition), so a dispatch would never settle; "
                  "guard one of the transitions on the cycle or give it an event");
    static constexpr bool value = false;
};

template <class Event>
struct unhandled_event {
    static_assert(detail::dependent_false<Event>,
                  "bsc: no transition of this chart is triggered by the dispatched event type; add one, fix "
                  "the event type, or dispatch with bsc::allow_unhandled to ignore it on purpose");
    static constexpr bool value = false;
};

template <class Type>
struct not_an_event {
    static_assert(detail::dependent_false<Type>,
                  "bsc: bsc::event<E> needs E to be a complete, copyable class or enumeration type without "
                  "const or volatile (events are copied into the queue and handed to guards and actions); "
                  "void, references, arrays, functions and pointers are not events. For a transition without "
                  "an event, leave the trigger out: state<S> [guard] = state<T>");
    static constexpr bool value = false;
};

template <class Event>
struct raised_event_not_in_chart {
    static_assert(detail::dependent_false<Event>,
                  "bsc: an action raises an event type that no transition of this chart handles");
    static constexpr bool value = false;
};

// ---- the arguments of bsc::make_chart ----------------------------------------------------

template <class Argument>
struct not_a_row {
    static_assert(detail::dependent_false<Argument>,
                  "bsc: after the state tree, every argument of make_chart must be a row: "
                  "state<S> + event<E> [guard] / action = state<T>, state<S> [guard] = state<T>, "
                  "state<S> + on_entry / action, or state<S> + on_exit / action");
    static constexpr bool value = false;
};

template <class Root>
struct root_must_be_composite {
    static_assert(detail::dependent_false<Root>,
                  "bsc: the first argument of make_chart is the root of the state tree and must be a "
                  "bsc::composite<...>(...) or bsc::parallel<...>(...)");
    static constexpr bool value = false;
};

// ---- the state tree -------------------------------------------------------------------------

template <class State, class Argument>
struct not_a_state_declaration {
    static_assert(detail::dependent_false<State>,
                  "bsc: an argument of this state's declaration is not a state or marker; a composite takes "
                  "bsc::state, bsc::final_state, bsc::composite, bsc::parallel, bsc::initial, "
                  "bsc::shallow_history and bsc::deep_history; a parallel state takes states only");
    static constexpr bool value = false;
};

template <class State>
struct conflicting_history_markers {
    static_assert(detail::dependent_false<State>,
                  "bsc: this composite state has more than one history marker; keep one of "
                  "bsc::shallow_history or bsc::deep_history");
    static constexpr bool value = false;
};

// ---- the context -----------------------------------------------------------------------------

template <class Type>
struct context_not_an_aggregate {
    static_assert(detail::dependent_false<Type>,
                  "bsc: the machine looks for channels and timers in the context and in its members: this "
                  "one must be an aggregate (a struct with public members, no constructors, no virtual "
                  "functions, no base classes)");
    static constexpr bool value = false;
};

template <class Type>
struct too_many_fields {
    static_assert(detail::dependent_false<Type>,
                  "bsc: this struct of the context has more than 128 fields; group some of them into nested "
                  "structs or std::arrays (channels and timers are found at any depth)");
    static constexpr bool value = false;
};

// ---- guards and actions ----------------------------------------------------------------------

template <class Callable>
struct guard_signature_not_supported {
    static_assert(detail::dependent_false<Callable>,
                  "bsc: a guard must be callable as g(context const&, event const&), g(context const&) or g(), "
                  "and return something convertible to bool; see the Callable type in this error");
    static constexpr bool value = false;
};

template <class Callable>
struct action_signature_not_supported {
    static_assert(detail::dependent_false<Callable>,
                  "bsc: an action must be callable as a(context&, event const&, raise&), a(context&, event const&), "
                  "a(context&) or a(); an entry/exit action as a(context&, raise&), a(context&) or a(); see the "
                  "Callable type in this error");
    static constexpr bool value = false;
};

}  // namespace bsc::error
