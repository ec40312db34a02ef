#pragma once
// Guards, actions and entry/exit actions are plain callables that take as many of
// (context, event, raise) as they need. These helpers call them with the longest
// argument list they accept, so users never write parameters they do not use.

#include <type_traits>
#include <utility>

#include <bsc/error.hpp>
#include <bsc/detail/meta.hpp>

namespace bsc::detail {

// Whether f(args...) is a call, and one that cannot throw: what the helpers below make, asked
// as requires-expressions. (std::is_invocable answers the same for the callables bsc calls,
// through INVOKE's machinery: a dozen class templates instantiated per question, and the
// compile of a chart asks several per guard and action; docs/performance.md, rule "A question
// about a call is a requires-expression".)
template <class F, class... Args>
concept callable_with = requires(F const& f, Args&&... args) {
    f(static_cast<Args&&>(args)...);
};
template <class F, class... Args>
concept nothrow_callable_with = requires(F const& f, Args&&... args) {
    { f(static_cast<Args&&>(args)...) }
    noexcept;
};
// The implicit conversion of a guard's result (std::is_invocable_r<bool, ...> asks the same).
constexpr bool as_test(bool holds) noexcept { return holds; }
template <class F, class... Args>
concept test_with = requires(F const& f, Args&&... args) {
    detail::as_test(f(static_cast<Args&&>(args)...));
};
template <class F, class... Args>
concept nothrow_test_with = requires(F const& f, Args&&... args) {
    { detail::as_test(f(static_cast<Args&&>(args)...)) }
    noexcept;
};

// Whether a callable has one of the signatures below: what make_chart checks
// (detail/checks/signatures.hpp) and what these helpers call.
template <class G, class Ctx, class E>
inline constexpr bool guard_callable = test_with<G, Ctx const&, E const&> || test_with<G, Ctx const&> || test_with<G>;
template <class A, class Ctx, class E, class Raise>
inline constexpr bool action_callable = callable_with<A, Ctx&, E const&, Raise&> || callable_with<A, Ctx&, E const&> ||
                                        callable_with<A, Ctx&> || callable_with<A>;
template <class A, class Ctx, class Raise>
inline constexpr bool state_action_callable = callable_with<A, Ctx&, Raise&> || callable_with<A, Ctx&> ||
                                              callable_with<A>;

// Whether the call these helpers make cannot throw: the form they pick is noexcept. A chart
// none of whose guards and actions can throw needs no record of failures (detail/runtime/machine_data.hpp, may_throw).
template <class G, class Ctx, class E>
constexpr bool guard_nothrow() {
    if constexpr (test_with<G, Ctx const&, E const&>)
        return nothrow_test_with<G, Ctx const&, E const&>;
    else if constexpr (test_with<G, Ctx const&>)
        return nothrow_test_with<G, Ctx const&>;
    else
        return nothrow_test_with<G>;
}
template <class A, class Ctx, class E, class Raise>
constexpr bool action_nothrow() {
    if constexpr (callable_with<A, Ctx&, E const&, Raise&>)
        return nothrow_callable_with<A, Ctx&, E const&, Raise&>;
    else if constexpr (callable_with<A, Ctx&, E const&>)
        return nothrow_callable_with<A, Ctx&, E const&>;
    else if constexpr (callable_with<A, Ctx&>)
        return nothrow_callable_with<A, Ctx&>;
    else
        return nothrow_callable_with<A>;
}
template <class A, class Ctx, class Raise>
constexpr bool state_action_nothrow() {
    if constexpr (callable_with<A, Ctx&, Raise&>)
        return nothrow_callable_with<A, Ctx&, Raise&>;
    else if constexpr (callable_with<A, Ctx&>)
        return nothrow_callable_with<A, Ctx&>;
    else
        return nothrow_callable_with<A>;
}

template <class G, class Ctx, class E>
constexpr bool call_guard(G const& g, Ctx const& ctx, E const& e) noexcept(guard_nothrow<G, Ctx, E>()) {
    if constexpr (test_with<G, Ctx const&, E const&>)
        return static_cast<bool>(g(ctx, e));
    else if constexpr (test_with<G, Ctx const&>)
        return static_cast<bool>(g(ctx));
    else if constexpr (test_with<G>)
        return static_cast<bool>(g());
    else
        return report<error::guard_signature_not_supported<G>>();
}

template <class A, class Ctx, class E, class Raise>
constexpr void call_action(A const& a, Ctx& ctx, E const& e,
                           Raise& raise) noexcept(action_nothrow<A, Ctx, E, Raise>()) {
    if constexpr (callable_with<A, Ctx&, E const&, Raise&>)
        a(ctx, e, raise);
    else if constexpr (callable_with<A, Ctx&, E const&>)
        a(ctx, e);
    else if constexpr (callable_with<A, Ctx&>)
        a(ctx);
    else if constexpr (callable_with<A>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

template <class A, class Ctx, class Raise>
constexpr void call_state_action(A const& a, Ctx& ctx, Raise& raise) noexcept(state_action_nothrow<A, Ctx, Raise>()) {
    if constexpr (callable_with<A, Ctx&, Raise&>)
        a(ctx, raise);
    else if constexpr (callable_with<A, Ctx&>)
        a(ctx);
    else if constexpr (callable_with<A>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

}  // namespace bsc::detail
