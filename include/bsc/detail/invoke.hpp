#pragma once
// Guards, actions and entry/exit actions are plain callables that take as many of
// (context, event, raise) as they need. These helpers call them with the longest
// argument list they accept, so users never write parameters they do not use.

#include <type_traits>
#include <utility>

#include <bsc/error.hpp>
#include <bsc/detail/meta.hpp>

namespace bsc::detail {

// Whether a callable has one of the signatures below: what make_chart checks
// (detail/checks/signatures.hpp) and what these helpers call.
template <class G, class Ctx, class E>
inline constexpr bool guard_callable = std::is_invocable_r_v<bool, G const&, Ctx const&, E const&> ||
                                       std::is_invocable_r_v<bool, G const&, Ctx const&> ||
                                       std::is_invocable_r_v<bool, G const&>;
template <class A, class Ctx, class E, class Raise>
inline constexpr bool action_callable = std::is_invocable_v<A const&, Ctx&, E const&, Raise&> ||
                                        std::is_invocable_v<A const&, Ctx&, E const&> ||
                                        std::is_invocable_v<A const&, Ctx&> || std::is_invocable_v<A const&>;
template <class A, class Ctx, class Raise>
inline constexpr bool state_action_callable = std::is_invocable_v<A const&, Ctx&, Raise&> ||
                                              std::is_invocable_v<A const&, Ctx&> || std::is_invocable_v<A const&>;

// Whether the call these helpers make cannot throw: the form they pick is noexcept. A chart
// none of whose guards and actions can throw needs no record of failures (detail/runtime/machine_data.hpp, may_throw).
template <class G, class Ctx, class E>
constexpr bool guard_nothrow() {
    if constexpr (std::is_invocable_r_v<bool, G const&, Ctx const&, E const&>)
        return std::is_nothrow_invocable_r_v<bool, G const&, Ctx const&, E const&>;
    else if constexpr (std::is_invocable_r_v<bool, G const&, Ctx const&>)
        return std::is_nothrow_invocable_r_v<bool, G const&, Ctx const&>;
    else
        return std::is_nothrow_invocable_r_v<bool, G const&>;
}
template <class A, class Ctx, class E, class Raise>
constexpr bool action_nothrow() {
    if constexpr (std::is_invocable_v<A const&, Ctx&, E const&, Raise&>)
        return std::is_nothrow_invocable_v<A const&, Ctx&, E const&, Raise&>;
    else if constexpr (std::is_invocable_v<A const&, Ctx&, E const&>)
        return std::is_nothrow_invocable_v<A const&, Ctx&, E const&>;
    else if constexpr (std::is_invocable_v<A const&, Ctx&>)
        return std::is_nothrow_invocable_v<A const&, Ctx&>;
    else
        return std::is_nothrow_invocable_v<A const&>;
}
template <class A, class Ctx, class Raise>
constexpr bool state_action_nothrow() {
    if constexpr (std::is_invocable_v<A const&, Ctx&, Raise&>)
        return std::is_nothrow_invocable_v<A const&, Ctx&, Raise&>;
    else if constexpr (std::is_invocable_v<A const&, Ctx&>)
        return std::is_nothrow_invocable_v<A const&, Ctx&>;
    else
        return std::is_nothrow_invocable_v<A const&>;
}

template <class G, class Ctx, class E>
constexpr bool call_guard(G const& g, Ctx const& ctx, E const& e) noexcept(guard_nothrow<G, Ctx, E>()) {
    if constexpr (std::is_invocable_r_v<bool, G const&, Ctx const&, E const&>)
        return static_cast<bool>(g(ctx, e));
    else if constexpr (std::is_invocable_r_v<bool, G const&, Ctx const&>)
        return static_cast<bool>(g(ctx));
    else if constexpr (std::is_invocable_r_v<bool, G const&>)
        return static_cast<bool>(g());
    else
        return report<error::guard_signature_not_supported<G>>();
}

template <class A, class Ctx, class E, class Raise>
constexpr void call_action(A const& a, Ctx& ctx, E const& e,
                           Raise& raise) noexcept(action_nothrow<A, Ctx, E, Raise>()) {
    if constexpr (std::is_invocable_v<A const&, Ctx&, E const&, Raise&>)
        a(ctx, e, raise);
    else if constexpr (std::is_invocable_v<A const&, Ctx&, E const&>)
        a(ctx, e);
    else if constexpr (std::is_invocable_v<A const&, Ctx&>)
        a(ctx);
    else if constexpr (std::is_invocable_v<A const&>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

template <class A, class Ctx, class Raise>
constexpr void call_state_action(A const& a, Ctx& ctx, Raise& raise) noexcept(state_action_nothrow<A, Ctx, Raise>()) {
    if constexpr (std::is_invocable_v<A const&, Ctx&, Raise&>)
        a(ctx, raise);
    else if constexpr (std::is_invocable_v<A const&, Ctx&>)
        a(ctx);
    else if constexpr (std::is_invocable_v<A const&>)
        a();
    else
        detail::report<error::action_signature_not_supported<A>>();
}

}  // namespace bsc::detail
