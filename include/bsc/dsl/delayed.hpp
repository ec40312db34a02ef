#pragma once
// Delayed events to self: the actions bsc::raise_after and bsc::cancel_delayed. They reach the
// machine's pending events (detail/runtime/delayed_events.hpp) through the raise argument that every
// action receives; a chart that uses them gets a queue with slots for them (detail/runtime/queue_for.hpp).

#include <cstdlib>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <bsc/detail/chrono.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/duration.hpp>

namespace bsc::detail {

// bsc::raise_after and bsc::cancel_delayed: actions that reach the machine's delayed events
// (detail/runtime/delayed_events.hpp) through the raise argument.
template <class E>
struct delayed_raise : action_base {
    duration delay;
    E event;
    int id;
    template <class Ctx, class Ev, class Raise>
    constexpr void operator()(Ctx&, Ev const&, Raise& raise) const noexcept(std::is_nothrow_copy_constructible_v<E>) {
        (void)raise.schedule(delay, event, id);
    }
};
struct cancel_delayed_action : action_base {
    int id;
    template <class Ctx, class Ev, class Raise>
    constexpr void operator()(Ctx&, Ev const&, Raise& raise) const noexcept {
        raise.cancel(id);
    }
};

// Deliberately not constexpr (as bsc_after_negative_delay in dsl/row.hpp): in a constexpr chart,
// reaching it is the compile error, and its name says what is wrong; a chart built at run time
// throws (or aborts without exceptions). 0 is "no id": bsc::raise_after without an id sends
// under it, and nothing can be cancelled by it.
[[noreturn]] inline void bsc_cancel_delayed_id_zero_names_no_delayed_event() {
#if defined(__cpp_exceptions)
    throw std::invalid_argument(
        "bsc::cancel_delayed: id 0 names no delayed event (it is the id of none); send with "
        "bsc::raise_after(delay, e, id) and cancel with the same nonzero id");
#else
    std::abort();
#endif
}

template <class A>
inline constexpr bool is_delayed_raise = false;
template <class E>
inline constexpr bool is_delayed_raise<delayed_raise<E>> = true;

// Whether an action sends or cancels delayed events: then the machine keeps slots for them.
template <class A>
inline constexpr bool sends_delayed = false;
template <class E>
inline constexpr bool sends_delayed<delayed_raise<E>> = true;
template <>
inline constexpr bool sends_delayed<cancel_delayed_action> = true;
template <class... As>
inline constexpr bool sends_delayed<action_seq<As...>> = (sends_delayed<As> || ...);
template <class A>
inline constexpr bool sends_delayed<state_action<A>> = sends_delayed<A>;

}  // namespace bsc::detail

namespace bsc {

/// An action that raises `e` to the machine after `delay` (SCXML's `<send delay>` to itself):
/// the first `step(now)` whose time is at least the machine's clock when the action ran plus
/// `delay` processes it, after the components' turns, as a raised event. It is not tied to the
/// state that sent it; `bsc::cancel_delayed(id)` cancels it while it is pending (an id of 0 is
/// none). The machine keeps `Policy::delayed_capacity` pending events; one more is dropped and
/// the run reports `outcome::queue_overflow`. An event whose due time would lie past
/// bsc::duration::max() never comes due, and is not kept (detail/runtime/delayed_events.hpp).
/// Requirements: `e` is an event of the chart (or of a family of one); 0 <= delay <=
/// bsc::duration::max() (as for bsc::after: otherwise a constexpr chart does not compile, and
/// one built at run time throws std::invalid_argument / std::out_of_range).
template <class Rep, class Period, class E>
constexpr auto raise_after(std::chrono::duration<Rep, Period> delay, E e, int id = 0) {
    return detail::delayed_raise<E>{{}, detail::checked_delay(delay), std::move(e), id};
}

/// An action that cancels the delayed events still pending under `id` (bsc::raise_after).
/// Requirements: id != 0 (0 is no id; a constexpr chart with cancel_delayed(0) does not compile,
/// the error naming bsc_cancel_delayed_id_zero_names_no_delayed_event, and one built at run time
/// throws std::invalid_argument).
constexpr auto cancel_delayed(int id) {
    if (id == 0) detail::bsc_cancel_delayed_id_zero_names_no_delayed_event();
    return detail::cancel_delayed_action{{}, id};
}

}  // namespace bsc
