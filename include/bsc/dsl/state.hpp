#pragma once
// bsc::state<S>: names state S, in the tree (as a basic state) and in the transition rows,
// where it is the left-hand side of `state<S> + event<E> [guard] / action = state<T>`.

#include <utility>

#include <bsc/dsl/row.hpp>

namespace bsc::detail {

template <class S>
struct state_ref {
    using tag = S;

    template <class E>
    constexpr auto operator+(event_ref<E>) const {
        return transition_row<S, event_trigger<E>, no_guard, no_action, no_target>{};
    }
    template <class Tr, class G, class A>
    constexpr auto operator+(trigger_spec<Tr, G, A> spec) const {
        return transition_row<S, Tr, G, A, no_target>{{}, spec.trigger, std::move(spec.guard), std::move(spec.action)};
    }
    constexpr auto operator+(timeout_ref t) const {
        return transition_row<S, timeout_trigger, no_guard, no_action, no_target>{{}, {t.delay}, {}, {}};
    }
    template <class A>
    constexpr auto operator+(entry_spec<A> spec) const {
        return entry_row<S, A>{{}, std::move(spec.action)};
    }
    template <class A>
    constexpr auto operator+(exit_spec<A> spec) const {
        return exit_row<S, A>{{}, std::move(spec.action)};
    }
    template <class A>
    constexpr auto operator+(initial_spec<A> spec) const {
        return initial_row<S, A>{{}, std::move(spec.action)};
    }
    // Eventless transitions: state<S> [guard] / action = state<T>.
    template <class G>
    constexpr auto operator[](G g) const {
        using guard_t = decltype(as_guard(std::move(g)));
        return transition_row<S, eventless_trigger, guard_t, no_action, no_target>{{}, {}, as_guard(std::move(g)), {}};
    }
    template <class A>
    constexpr auto operator/(A a) const {
        using action_t = decltype(as_action(std::move(a)));
        return transition_row<S, eventless_trigger, no_guard, action_t, no_target>{{}, {}, {}, as_action(std::move(a))};
    }
    template <class T>
    constexpr auto operator=(state_ref<T>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, T>{};
    }
    template <class T>
    constexpr auto operator=(local_ref<T>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, local_target<T>>{};
    }
    template <class... T>
    constexpr auto operator=(targets_ref<T...>) const {
        return transition_row<S, eventless_trigger, no_guard, no_action, several_targets<T...>>{};
    }
};

// What bsc::targets returns: the targets of a transition with several.
template <class... S>
struct targets_ref {};

// What bsc::local returns: the target of a local transition.
template <class S>
struct local_ref {
    using tag = S;
};

}  // namespace bsc::detail

namespace bsc {

/// Names the state S: a basic state in the tree, a source or target in a transition row.
template <class S>
inline constexpr detail::state_ref<S> state{};

/// The target of a local transition (UML's kind = local, SCXML's type="internal"):
/// `state<Work> + event<restart> = local(state<Step1>)` goes from composite Work to its
/// descendant Step1 without leaving Work: only the active states below Work are exited, Work's
/// own exit and entry actions do not run, and its timeouts keep counting.
/// Requirements: the target is a proper descendant of the row's source (else the chart is
/// rejected: bsc::error::local_target_outside_source). From a parallel source the transition
/// is an ordinary one, as in SCXML, where only a compound state can keep itself active.
template <class S>
constexpr detail::local_ref<S> local(detail::state_ref<S>) {
    return {};
}

/// The targets of a transition that enters a chosen state in each of several orthogonal
/// regions (SCXML's `target="a b"`): `state<Idle> + event<go> = targets(state<A2>, state<B3>)`.
/// The transition's domain is the nearest composite above its source and all its targets; the
/// regions of a parallel state on the way that hold no target are entered by default.
/// Requirements: 2 to 4 targets, each pair in different regions of a parallel state
/// (bsc::error::targets_not_orthogonal).
template <class... S>
constexpr detail::targets_ref<S...> targets(detail::state_ref<S>...) {
    static_assert(sizeof...(S) >= 2 && sizeof...(S) <= 4,
                  "bsc::targets takes 2 to 4 states (one transition's targets in orthogonal regions)");
    return {};
}

}  // namespace bsc
