#pragma once
// The events bsc itself defines: the tag of an eventless transition, the trigger every event
// matches, a state's completion event, the event of a failed guard or action, and what an
// observer receives for a timeout.

#include <exception>

#include <bsc/duration.hpp>

namespace bsc {

namespace detail {
// The trigger of a transition taken without an event, when its guard holds.
struct eventless_trigger {};
}  // namespace detail

/// The tag used in diagnostics and observers for a transition without an event.
using eventless = detail::eventless_trigger;

/// The trigger every event matches: `state<S> + event<bsc::any_event> = state<T>` takes any
/// event that no deeper state and no earlier row of S takes first (SCXML's event="*",
/// Boost.SML's event<_>). Its guard and action receive this tag, not the event.
struct any_event {};

/// The completion event of state S (SCXML's done.state.S): raised when a final child of the
/// composite S is entered, or, for a parallel S, when every region of S has entered a final
/// state. A row takes it like any event: `state<Work> + event<bsc::done<Work>> = state<Next>`.
/// (A final child of the root raises nothing: the machine halts.)
template <class S>
struct done {
    using state = S;
};

/// What a machine puts on its internal queue when a guard, an action, an entry or an exit
/// action throws (W3C SCXML's error.execution): the rest of that callable is skipped, the
/// microstep completes, and this event carries the exception. A chart handles it with
/// ordinary rows, e.g. `state<Running> + event<bsc::action_failed> = state<Fault>`. A failure
/// that no transition takes is the caller's: dispatch() or step() rethrows it once the machine
/// is consistent (or reports outcome::failed, as the policy says).
struct action_failed {
    std::exception_ptr error;
};

/// What on_transition receives as the event of a timeout row (`after(delay)`): its delay. An
/// eventless row's transition receives bsc::eventless, an event's transition the event.
struct timeout_elapsed {
    duration delay;
};

}  // namespace bsc
