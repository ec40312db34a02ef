#pragma once
// The chart's second table: transition rows `source + trigger [guard] / action = target`,
// and entry/exit rows `state<S> + on_entry / action`.

#include <charconv>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <bsc/duration.hpp>
#include <bsc/detail/chrono.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/guard.hpp>
#include <bsc/events.hpp>

namespace bsc::detail {

template <class S>
struct state_ref;
template <class S>
struct local_ref;
template <class... S>
struct targets_ref;

template <class E>
struct event_trigger {
    using event = E;
};
// Deliberately not constexpr (as bsc_after_negative_delay below): in a constexpr chart, reaching
// it is the compile error, and its name says what is wrong; a chart built at run time throws.
// (The message is written into a buffer, not built as a std::string: the body of an inline
// function is compiled in every translation unit that includes it, and std::string's
// operators would be instantiated there.)
[[noreturn]] inline void bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(std::size_t row,
                                                                                        std::size_t fires_first) {
#if defined(__cpp_exceptions)
    constexpr char head[] = "bsc::make_chart: the timeout row at position ";
    constexpr char middle[] = " can never fire: the unguarded timeout row at position ";
    constexpr char tail[] =
        " leaves its state first, every time, with a shorter (or equal) delay, from the same state or "
        "from a state below it that is active whenever it is";
    char message[sizeof head + sizeof middle + sizeof tail + 40];  // each number in 20 digits at most
    char* end = message;
    auto const append = [&](char const* text) {
        while (*text != '\0') *end++ = *text++;
    };
    append(head);
    end = std::to_chars(end, message + sizeof message, row).ptr;
    append(middle);
    end = std::to_chars(end, message + sizeof message, fires_first).ptr;
    append(tail);
    *end = '\0';
    throw std::invalid_argument(message);
#else
    (void)row;
    (void)fires_first;
    std::abort();
#endif
}
// The frame the compiler shows with its arguments (Clang prints their values): the positions of
// the dead row and of the row that always fires first, counted from 1 among make_chart's rows
// (as bsc::error::at_row counts them).
// (The test keeps GCC from rejecting a constexpr function that can never be constant.)
constexpr void timeout_row_never_fires(std::size_t row, std::size_t fires_first) {
    if (row != fires_first) bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(row, fires_first);
}

/// The trigger of a state-scoped timeout: the source has been active for `delay`.
struct timeout_trigger {
    duration delay;

    // How make_chart reports a timeout row that can never fire (chart.hpp): a delay is never
    // negative (bsc::after refuses one), so make_chart writes the positions of the dead row and
    // of the row that fires first, as a negative delay, into its own copy of the dead row, the
    // parameter, once the chart is built. The parameter is destroyed after make_chart returns,
    // in the declaration of the chart, and this is the compile error: its context is the row's
    // type, where a failure inside make_chart would print make_chart's, which spells the chart.
    static constexpr long long dead_mark_base = 1LL << 24;
    static constexpr duration dead_mark(std::size_t row, std::size_t fires_first) {
        return duration{-1 - static_cast<long long>(row) * dead_mark_base - static_cast<long long>(fires_first)};
    }
    constexpr ~timeout_trigger() {
        if (std::is_constant_evaluated() && delay < duration::zero()) {
            long long const mark = -1 - static_cast<long long>(delay.count());
            timeout_row_never_fires(static_cast<std::size_t>(mark / dead_mark_base),
                                    static_cast<std::size_t>(mark % dead_mark_base));
        }
    }
};
/// The target of an internal transition: no exit, no entry.
struct no_target {};
/// The target T of a local transition (bsc::local): in a row's type, so that the row says so.
template <class T>
struct local_target {};
// A row's target state, and whether the row is local.
/// The targets of a transition with several, one in each of orthogonal regions (bsc::targets).
template <class T, class... More>
struct several_targets {};
// A row's target state (its first, where it has several), whether the row is local, and all
// its targets.
template <class T>
struct target_parts {
    using state = T;
    static constexpr bool local = false;
    using all = type_list<T>;
};
template <>
struct target_parts<no_target> {
    using state = no_target;
    static constexpr bool local = false;
    using all = type_list<>;
};
template <class T>
struct target_parts<local_target<T>> {
    using state = T;
    static constexpr bool local = true;
    using all = type_list<T>;
};
template <class T, class... More>
struct target_parts<several_targets<T, More...>> {
    using state = T;
    static constexpr bool local = false;
    using all = type_list<T, More...>;
};

// What marks a row. A base of its own for each row type: rows whose guard, action and trigger
// are empty are empty themselves, and the tuple of a chart's rows can then take no space at
// all, which it could not if every row had the same (empty) base at a distinct address.
template <class Row>
struct row_base {
    using bsc_row_type = Row;
};

template <class Trigger, class G, class A>
struct trigger_spec {
    [[no_unique_address]] Trigger trigger;
    [[no_unique_address]] G guard;
    [[no_unique_address]] A action;
    template <class A2>
        requires std::is_same_v<A, no_action>
    constexpr auto operator/(A2 a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<Trigger, G, action_t>{trigger, guard, as_action(std::move(a))};
    }
};

template <class E>
struct event_ref {
    using event = E;
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return trigger_spec<event_trigger<E>, guard_t, no_action>{{}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<event_trigger<E>, no_guard, action_t>{{}, {}, as_action(std::move(a))};
    }
};

struct timeout_ref {
    duration delay;
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return trigger_spec<timeout_trigger, guard_t, no_action>{{delay}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return trigger_spec<timeout_trigger, no_guard, action_t>{{delay}, {}, as_action(std::move(a))};
    }
};

template <class S, class Trigger, class G, class A, class T>
struct transition_row : row_base<transition_row<S, Trigger, G, A, T>> {
    using source = S;
    using trigger = Trigger;
    using target = typename target_parts<T>::state;
    /// A local transition (`= bsc::local(state<T>)`): its source stays active.
    static constexpr bool local = target_parts<T>::local;
    /// Every target: none, the one, or several (`= bsc::targets(state<A>, state<B>)`).
    using targets = typename target_parts<T>::all;
    static constexpr bool guarded = !std::is_same_v<G, no_guard>;
    /// A row that defers its event (`/ bsc::defer`).
    static constexpr bool defers = std::is_same_v<A, defer_action>;
    [[no_unique_address]] Trigger trigger_value;
    [[no_unique_address]] G guard;
    [[no_unique_address]] A action;

    template <class T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(state_ref<T2>) const {
        return transition_row<S, Trigger, G, A, T2>{{}, trigger_value, guard, action};
    }
    template <class T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(local_ref<T2>) const {
        return transition_row<S, Trigger, G, A, local_target<T2>>{{}, trigger_value, guard, action};
    }
    template <class... T2>
        requires std::is_same_v<T, no_target>
    constexpr auto operator=(targets_ref<T2...>) const {
        return transition_row<S, Trigger, G, A, several_targets<T2...>>{{}, trigger_value, guard, action};
    }
    template <class A2>
        requires(std::is_same_v<A, no_action>&& std::is_same_v<T, no_target>)
    constexpr auto operator/(A2 a) const {
        using action_t = decltype(as_action(std::move(a)));
        return transition_row<S, Trigger, G, action_t, T>{{}, trigger_value, guard, as_action(std::move(a))};
    }
};

template <class A>
struct entry_spec {
    [[no_unique_address]] A action;
};
template <class A>
struct exit_spec {
    [[no_unique_address]] A action;
};
struct entry_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return entry_spec<state_action<A>>{{std::move(a)}};
    }
};
struct exit_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return exit_spec<state_action<A>>{{std::move(a)}};
    }
};
template <class A>
struct initial_spec {
    [[no_unique_address]] A action;
};
struct initial_keyword {
    template <class A>
    constexpr auto operator/(A a) const {
        return initial_spec<state_action<A>>{{std::move(a)}};
    }
};

template <class S, class A>
struct entry_row : row_base<entry_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};
template <class S, class A>
struct exit_row : row_base<exit_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};
// The action of a composite's initial transition (SCXML's <initial><transition>).
template <class S, class A>
struct initial_row : row_base<initial_row<S, A>> {
    using source = S;
    [[no_unique_address]] A action;
};

template <class R>
inline constexpr bool is_row = requires {
    typename R::bsc_row_type;
    requires std::is_same_v<typename R::bsc_row_type, R>;
};
template <class R>
inline constexpr bool is_transition_row = false;
template <class S, class Tr, class G, class A, class T>
inline constexpr bool is_transition_row<transition_row<S, Tr, G, A, T>> = true;
template <class R>
inline constexpr bool is_timeout_row = false;
template <class S, class G, class A, class T>
inline constexpr bool is_timeout_row<transition_row<S, timeout_trigger, G, A, T>> = true;
template <class R>
inline constexpr bool is_entry_row = false;
template <class S, class A>
inline constexpr bool is_entry_row<entry_row<S, A>> = true;
template <class R>
inline constexpr bool is_exit_row = false;
template <class S, class A>
inline constexpr bool is_exit_row<exit_row<S, A>> = true;
template <class R>
inline constexpr bool is_initial_row = false;
template <class S, class A>
inline constexpr bool is_initial_row<initial_row<S, A>> = true;

// Whether a row's guard tests the configuration (bsc::in<S>), and whether any of a list of rows'
// does: a back end calls such guards with a view of the configuration (dsl/guard.hpp).
template <class R>
inline constexpr bool row_tests_configuration = false;
template <class S, class Tr, class G, class A, class T>
inline constexpr bool row_tests_configuration<transition_row<S, Tr, G, A, T>> = tests_configuration<G>;
template <class Rows>
inline constexpr bool any_row_tests_configuration = false;
template <class... Rows>
inline constexpr bool any_row_tests_configuration<type_list<Rows...>> = any_true({row_tests_configuration<Rows>...,
                                                                                  false});

}  // namespace bsc::detail

namespace bsc::detail {

// What can be an event: a complete class or enumeration type, copyable, not cv-qualified.
template <class E>
constexpr bool is_event_type() {
    if constexpr (!(std::is_class_v<E> || std::is_enum_v<E>) || !std::is_same_v<E, std::remove_cv_t<E>>)
        return false;
    else if constexpr (!requires { sizeof(E); })
        return false;
    else
        return std::is_copy_constructible_v<E> && std::is_destructible_v<E>;
}

template <class E>
constexpr event_ref<E> checked_event_ref() {
    if constexpr (!is_event_type<E>()) detail::report<error::not_an_event<E>>();
    return {};
}

}  // namespace bsc::detail

namespace bsc {

/// Names an event type as a trigger: `state<A> + event<E> = state<B>`.
/// Requirements: E is a complete, copyable class or enumeration type, not cv-qualified.
template <class E>
inline constexpr detail::event_ref<E> event = detail::checked_event_ref<E>();

/// Entry action row: `state<S> + on_entry / action`; runs each time S is entered.
inline constexpr detail::entry_keyword on_entry{};

/// Exit action row: `state<S> + on_exit / action`; runs each time S is exited.
inline constexpr detail::exit_keyword on_exit{};

/// The action of composite S's initial transition: `state<S> + on_initial / action` runs when
/// S is entered through its initial state (not through history, not by a transition to a state
/// inside S), after S's entry actions and before the initial state's (SCXML's
/// `<initial><transition>` content).
/// Requirements: S is a composite without a history marker
/// (bsc::error::initial_action_without_initial_transition).
inline constexpr detail::initial_keyword on_initial{};

namespace detail {
// Deliberately not constexpr: in a constexpr chart, reaching one of these is the compile error
// (its name says what is wrong); in a chart built at run time, it throws (or aborts without
// exceptions), so no machine ever runs with such a delay.
[[noreturn]] inline void bsc_after_negative_delay() {
#if defined(__cpp_exceptions)
    throw std::invalid_argument("bsc::after: the delay is negative");
#else
    std::abort();
#endif
}
[[noreturn]] inline void bsc_after_delay_beyond_bsc_duration() {
#if defined(__cpp_exceptions)
    throw std::out_of_range("bsc::after: the delay does not fit bsc::duration (nanoseconds: about 292 years)");
#else
    std::abort();
#endif
}

// A delay of bsc::after or bsc::raise_after as a bsc::duration, refused (the functions above)
// when it is negative or does not fit.
template <class Rep, class Period>
constexpr duration checked_delay(std::chrono::duration<Rep, Period> delay) {
    if (delay < std::chrono::duration<Rep, Period>::zero()) bsc_after_negative_delay();
    if (std::chrono::duration<long double, std::nano>(delay) >
        std::chrono::duration<long double, std::nano>(duration::max()))
        bsc_after_delay_beyond_bsc_duration();
    return std::chrono::duration_cast<duration>(delay);
}
}  // namespace detail

/// A state-scoped timeout trigger: `state<S> + after(3s) = state<T>` fires in the first cycle
/// (step) at which S has been active for at least 3 s. Armed when S is entered. Without a
/// target (`state<S> + after(500ms) / a`, an internal timeout) it fires every 500 ms while S is
/// active: each time it fires, its delay counts again from that cycle. Of several timeouts of S
/// due in one cycle whose guards hold, the one that came due first fires (then the one armed
/// first, then the first declared), so that none starves another.
/// Requirements: 0 <= delay <= bsc::duration::max(); a chart with another delay does not
/// compile (constexpr chart) or throws std::invalid_argument / std::out_of_range.
template <class Rep, class Period>
constexpr detail::timeout_ref after(std::chrono::duration<Rep, Period> delay) {
    return {detail::checked_delay(delay)};
}

}  // namespace bsc
