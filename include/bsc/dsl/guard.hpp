#pragma once
// Guards: conditions on the context (and the event) that enable a transition.
// Wrap a callable with bsc::guard to compose it with !, && and ||. bsc::in<S>, SCXML's In(S),
// is a guard on the machine's configuration: whether state S is active.

#include <type_traits>
#include <utility>

#include <bsc/detail/invoke.hpp>

namespace bsc::detail {

struct guard_base {};  // marks bsc guard wrappers, so the operators below apply to them only

template <class G>
concept bsc_guard = std::is_base_of_v<guard_base, G>;

// Whether a guard tests the configuration: it is, or has a part that is, a bsc::in<S>. Such a
// guard is called as g(ctx, e, active), where `active` answers active.is_active<S>() (a
// configuration view of the back end, detail/model/configuration_view.hpp); every other guard
// as before, g(ctx, e), so that a chart without bsc::in compiles and runs as it did. (A member
// of the guard types, reads_configuration, so that a named guard inherits it from its guard.)
template <class G>
inline constexpr bool tests_configuration = false;
template <class G>
    requires(G::reads_configuration)
inline constexpr bool tests_configuration<G> = true;

// What the checks hand a guard that tests the configuration: a view whose every state is active.
struct any_configuration {
    template <class S>
    constexpr bool is_active() const noexcept {
        return true;
    }
};

template <class F>
struct guard_fn : guard_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(call_guard(fn, ctx, e))) {
        return call_guard(fn, ctx, e);
    }
    // Called so when another part of the guard tests the configuration, which this one ignores.
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const&) const
        noexcept(noexcept(call_guard(fn, ctx, e))) {
        return call_guard(fn, ctx, e);
    }
};

/// bsc::in<S>: whether state S is active (SCXML's In). Only callable with a configuration view.
template <class S>
struct in_guard : guard_base {
    using state = S;
    static constexpr bool reads_configuration = true;
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const&, E const&, Active const& active) const
        noexcept(noexcept(active.template is_active<S>())) {
        return active.template is_active<S>();
    }
};

template <class G>
struct not_guard : guard_base {
    [[no_unique_address]] G g;
    static constexpr bool reads_configuration = tests_configuration<G>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(!g(ctx, e))) {
        return !g(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(!g(ctx, e, active))) {
        return !g(ctx, e, active);
    }
};

template <class L, class R>
struct and_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    static constexpr bool reads_configuration = tests_configuration<L> || tests_configuration<R>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) && r(ctx, e))) {
        return l(ctx, e) && r(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(l(ctx, e, active) && r(ctx, e, active))) {
        return l(ctx, e, active) && r(ctx, e, active);
    }
};

template <class L, class R>
struct or_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    static constexpr bool reads_configuration = tests_configuration<L> || tests_configuration<R>;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) || r(ctx, e))) {
        return l(ctx, e) || r(ctx, e);
    }
    template <class Ctx, class E, class Active>
    constexpr bool operator()(Ctx const& ctx, E const& e, Active const& active) const
        noexcept(noexcept(l(ctx, e, active) || r(ctx, e, active))) {
        return l(ctx, e, active) || r(ctx, e, active);
    }
};

// The guard stored in a transition: always callable as g(ctx, event).
template <class G>
constexpr auto as_guard(G g) {
    if constexpr (bsc_guard<G>)
        return g;
    else
        return guard_fn<G>{{}, std::move(g)};
}

struct no_guard {
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const&, E const&) const noexcept {
        return true;
    }
};

template <bsc_guard G>
constexpr auto operator!(G g) {
    return not_guard<G>{{}, std::move(g)};
}
template <bsc_guard L, class R>
constexpr auto operator&&(L l, R r) {
    using RG = decltype(as_guard(std::move(r)));
    return and_guard<L, RG>{{}, std::move(l), as_guard(std::move(r))};
}
template <class L, bsc_guard R>
    requires(!bsc_guard<L>)
constexpr auto operator&&(L l, R r) {
    using LG = decltype(as_guard(std::move(l)));
    return and_guard<LG, R>{{}, as_guard(std::move(l)), std::move(r)};
}
template <bsc_guard L, class R>
constexpr auto operator||(L l, R r) {
    using RG = decltype(as_guard(std::move(r)));
    return or_guard<L, RG>{{}, std::move(l), as_guard(std::move(r))};
}
template <class L, bsc_guard R>
    requires(!bsc_guard<L>)
constexpr auto operator||(L l, R r) {
    using LG = decltype(as_guard(std::move(l)));
    return or_guard<LG, R>{{}, as_guard(std::move(l)), std::move(r)};
}

}  // namespace bsc::detail

namespace bsc {

/// Wraps a callable as a guard that composes with `!`, `&&` and `||`.
/// The callable is `g(context const&, event const&)`, `g(context const&)` or `g()`, returning bool.
template <class F>
constexpr auto guard(F f) {
    return detail::guard_fn<F>{{}, std::move(f)};
}

/// SCXML's In(S): a guard that holds while state S is active, as the configuration is when the
/// guard is evaluated (before the exits of the microstep it selects for). Composes with `!`,
/// `&&`, `||` like any bsc guard: `state<B1> + event<go> [bsc::in<A2>] = state<B2>`,
/// `[!bsc::in<A2> && ready]`.
/// Requirements: S is a state of the chart's tree (bsc::error::in_of_state_not_in_chart), not a
/// history pseudo-state (bsc::error::in_of_history_state), which is never active.
template <class S>
inline constexpr detail::in_guard<S> in{};

}  // namespace bsc
