#pragma once
// Actions: what a transition, an entry or an exit does to the context.
// Wrap a callable with bsc::action to sequence it with the comma operator: / (a, b, c).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/detail/invoke.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>

namespace bsc::detail {

struct action_base {};  // marks bsc action wrappers, so operator, applies to them only

template <class A>
concept bsc_action = std::is_base_of_v<action_base, A>;

// What bsc::defer is: the "action" of a row that defers its event. The machines recognise it
// by its type and keep the event instead of calling it; it runs nothing itself.
struct defer_action {
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx&, E const&, Raise&) const noexcept {}
};

template <class F>
struct action_fn : action_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx& ctx, E const& e, Raise& raise) const
        noexcept(noexcept(call_action(fn, ctx, e, raise))) {
        call_action(fn, ctx, e, raise);
    }
};

template <class... As>
struct action_seq : action_base {
    [[no_unique_address]] std::tuple<As...> actions;
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx& ctx, E const& e, Raise& raise) const
        noexcept((nothrow_callable_with<As, Ctx&, E const&, Raise&> && ...)) {
        std::apply([&](auto const&... a) { (a(ctx, e, raise), ...); }, actions);
    }
};

template <class A>
constexpr auto as_action(A a) {
    if constexpr (bsc_action<A> || std::is_same_v<A, defer_action>)
        return a;
    else
        return action_fn<A>{{}, std::move(a)};
}

template <class A>
constexpr auto as_tuple(A a) {
    static_assert(!std::is_same_v<A, defer_action>,
                  "bsc::defer is a row's whole action: `state<S> + event<E> / bsc::defer`; it does not sequence with "
                  "other actions");
    if constexpr (requires { a.actions; })
        return a.actions;
    else
        return std::tuple{as_action(std::move(a))};
}

template <class... As>
constexpr auto make_seq(std::tuple<As...> t) {
    return action_seq<As...>{{}, std::move(t)};
}

template <class L, class R>
    requires(bsc_action<L> || bsc_action<R>)
constexpr auto operator,(L l, R r) { return make_seq(std::tuple_cat(as_tuple(std::move(l)), as_tuple(std::move(r)))); }

struct no_action {
    template <class Ctx, class E, class Raise>
    constexpr void operator()(Ctx&, E const&, Raise&) const noexcept {}
};


// The event a bsc action sees when it runs as an entry or exit action.
struct state_change {};

// Entry and exit actions see the context (and the raise queue), never an event.
template <class A>
struct state_action {
    [[no_unique_address]] A fn;
    template <class Ctx, class Raise>
    static constexpr bool nothrow() {
        if constexpr (bsc_action<A>)
            return nothrow_callable_with<A, Ctx&, state_change const&, Raise&>;
        else
            return state_action_nothrow<A, Ctx, Raise>();
    }
    template <class Ctx, class Raise>
    constexpr void operator()(Ctx& ctx, Raise& raise) const noexcept(nothrow<Ctx, Raise>()) {
        if constexpr (bsc_action<A>)
            fn(ctx, state_change{}, raise);
        else
            call_state_action(fn, ctx, raise);
    }
};

// What the chart's analysis hands an action as its raise argument, to learn whether it takes one
// (may_raise below) and whether it can be called at all (detail/checks/signatures.hpp): callable with
// any event, as a machine's queue is with the chart's events (an event the chart does not take
// is reported where the machine calls the action: bsc::error::raised_event_not_in_chart). Not a
// machine's queue, whose type spells every event of the chart and holds a std::variant of
// them: each question would instantiate it and make a symbol named after it.
// (It answers what a machine's queue answers besides the call, as an empty queue of the
// default capacity would, so that an action that asks is judged as before.)
struct raise_stand_in {
    template <class E>
    constexpr bool operator()(E const&) noexcept {
        return true;
    }
    constexpr bool empty() const noexcept { return true; }
    constexpr std::size_t size() const noexcept { return 0; }
    static constexpr std::size_t capacity() noexcept { return default_policy::queue_capacity; }
    constexpr bool overflowed() const noexcept { return false; }
    constexpr void clear_overflow() noexcept {}
    constexpr void clear() noexcept {}
};

// Whether an action can raise an event, i.e. whether it is ever handed the raise argument
// (an action that does not accept it is called without it). A chart none of whose actions
// can raise needs no event queue. Unknown action types are assumed to raise.
template <class Ctx, class E, class Raise>
constexpr bool may_raise(void const*) {
    return true;
}
template <class Ctx, class E, class Raise>
constexpr bool may_raise(no_action const*) {
    return false;
}
template <class Ctx, class E, class Raise>
constexpr bool may_raise(defer_action const*) {
    return false;
}
template <class Ctx, class E, class Raise, class F>
constexpr bool may_raise(action_fn<F> const*) {
    return callable_with<F, Ctx&, E const&, Raise&>;
}
template <class Ctx, class E, class Raise, class A>
constexpr bool may_raise(state_action<A> const*) {  // a plain callable of an entry or exit row
    return callable_with<A, Ctx&, Raise&>;
}

// The callable of bsc::raise(e): a type of its own, so that the machine knows which event such an
// action raises (detail::raised_by) and its queue holds only the events that can be raised.
template <class E>
struct raise_fn {
    E event;
    template <class Ctx, class Ev, class Queue>
    constexpr void operator()(Ctx&, Ev const&, Queue& queue) const noexcept(noexcept(queue(event))) {
        queue(event);
    }
};

// What an action can raise: a type_list of the event types, or raises_anything for an action
// that is handed the raise argument and may raise whatever it likes. Joined by join_raised,
// raises_anything absorbing the rest.
struct raises_anything {};
template <bool Anything, class... Lists>
struct join_raised_of {
    using type = raises_anything;
};
template <class... Lists>
struct join_raised_of<false, Lists...> {
    using type = concat_t<Lists...>;
};
template <class... Lists>
using join_raised =
    typename join_raised_of<any_true({std::is_same_v<Lists, raises_anything>..., false}), Lists...>::type;

// (A sequence, and an entry or exit action wrapping one of bsc's, are looked into; any other
// action raises anything if may_raise says it can raise at all.)
template <class Ctx, class E, class Raise, class A>
auto raised_by(A const*)
    -> std::conditional_t<may_raise<Ctx, E, Raise>(static_cast<A const*>(nullptr)), raises_anything, type_list<>>;
template <class Ctx, class E, class Raise, class Ev>
auto raised_by(action_fn<raise_fn<Ev>> const*) -> type_list<Ev>;
template <class Ctx, class E, class Raise, class... As>
auto raised_by(action_seq<As...> const*)
    -> join_raised<decltype(raised_by<Ctx, E, Raise>(static_cast<As const*>(nullptr)))...>;
template <class Ctx, class E, class Raise, class A>
    requires bsc_action<A>
auto raised_by(state_action<A> const*) -> decltype(raised_by<Ctx, state_change, Raise>(static_cast<A const*>(nullptr)));

}  // namespace bsc::detail

namespace bsc {

/// Wraps a callable as an action that sequences with others: `/ (bsc::action(a), b)`.
template <class F>
constexpr auto action(F f) {
    return detail::action_fn<F>{{}, std::move(f)};
}

/// Runs the given actions in order.
template <class... Fs>
constexpr auto seq(Fs... fs) {
    return detail::make_seq(std::tuple_cat(detail::as_tuple(std::move(fs))...));
}

/// The action of a row that defers its event (UML's deferred events, Boost.SML's `defer`):
/// `state<S> + event<E> / bsc::defer`. Selected like any row (the deepest source first, then
/// declaration order), it keeps the event, unless another region takes it with a transition in
/// the same microstep; kept events are dispatched again, in the order they came, after the next
/// transition that changes the configuration (docs/semantics.md, "Deferred events").
/// Requirements: the row has an event trigger other than bsc::any_event and no target
/// (bsc::error::invalid_deferral).
inline constexpr detail::defer_action defer{};

/// An action that raises `e` into the machine's internal queue; it is processed after
/// the current step, before dispatch returns.
template <class E>
constexpr auto raise(E e) {
    return action(detail::raise_fn<E>{std::move(e)});
}

}  // namespace bsc
