#pragma once
// Guards: conditions on the context (and the event) that enable a transition.
// Wrap a callable with bsc::guard to compose it with !, && and ||.

#include <type_traits>
#include <utility>

#include <bsc/detail/invoke.hpp>

namespace bsc::detail {

struct guard_base {};  // marks bsc guard wrappers, so the operators below apply to them only

template <class G>
concept bsc_guard = std::is_base_of_v<guard_base, G>;

template <class F>
struct guard_fn : guard_base {
    [[no_unique_address]] F fn;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(call_guard(fn, ctx, e))) {
        return call_guard(fn, ctx, e);
    }
};

template <class G>
struct not_guard : guard_base {
    [[no_unique_address]] G g;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(!g(ctx, e))) {
        return !g(ctx, e);
    }
};

template <class L, class R>
struct and_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) && r(ctx, e))) {
        return l(ctx, e) && r(ctx, e);
    }
};

template <class L, class R>
struct or_guard : guard_base {
    [[no_unique_address]] L l;
    [[no_unique_address]] R r;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& ctx, E const& e) const noexcept(noexcept(l(ctx, e) || r(ctx, e))) {
        return l(ctx, e) || r(ctx, e);
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

}  // namespace bsc
