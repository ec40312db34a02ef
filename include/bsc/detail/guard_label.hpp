#pragma once
// The label of a guard, as the exports draw it and the logger writes it: its name (bsc::named),
// a composition of named guards with their operators, or "guard"; bsc::in<S> is "In(S)". Also
// the pieces the labels of actions share (detail/export/model.hpp): has_name, expression,
// parenthesized.

#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/detail/type_name.hpp>
#include <bsc/dsl/guard.hpp>

namespace bsc::detail {

/// A guard or action that has a name (bsc::named, or any callable with a `name` member).
template <class T>
concept has_name = requires(T const& t) {
    std::string_view{t.name};
};

template <class T>
inline constexpr bool is_not_guard = false;
template <class G>
inline constexpr bool is_not_guard<not_guard<G>> = true;
template <class T>
inline constexpr bool is_and_guard = false;
template <class L, class R>
inline constexpr bool is_and_guard<and_guard<L, R>> = true;
template <class T>
inline constexpr bool is_or_guard = false;
template <class L, class R>
inline constexpr bool is_or_guard<or_guard<L, R>> = true;
template <class T>
inline constexpr bool is_guard_fn = false;
template <class F>
inline constexpr bool is_guard_fn<guard_fn<F>> = true;
template <class T>
inline constexpr bool is_in_guard = false;
template <class S>
inline constexpr bool is_in_guard<in_guard<S>> = true;

// How a label writes bsc::in<S>: "In(S)" with S's unqualified name. The exports pass their own,
// which names S as their diagrams do (detail/export/model.hpp).
struct in_by_name {
    template <class S>
    std::string operator()(std::type_identity<S>) const {
        return "In(" + std::string(name_of<S>) + ")";
    }
};

/// A label and whether any part of it was named; `precedence` places parentheses:
/// 1 for ||, 2 for &&, 3 for a name or a negation.
struct expression {
    std::string text;
    bool named = false;
    int precedence = 3;
};

inline std::string parenthesized(expression const& e, int context) {
    return e.precedence < context ? "(" + e.text + ")" : e.text;
}

template <class G, class InText = in_by_name>
expression guard_expression(G const& g, InText const& in_text = {}) {
    if constexpr (has_name<G>) {
        return {std::string(std::string_view{g.name}), true, 3};
    } else if constexpr (is_in_guard<G>) {
        return {in_text(std::type_identity<typename G::state>{}), true, 3};
    } else if constexpr (is_not_guard<G>) {
        auto const inner = guard_expression(g.g, in_text);
        return {"!" + parenthesized(inner, 3), inner.named, 3};
    } else if constexpr (is_and_guard<G> || is_or_guard<G>) {
        int const precedence = is_and_guard<G> ? 2 : 1;
        auto const l = guard_expression(g.l, in_text);
        auto const r = guard_expression(g.r, in_text);
        return {parenthesized(l, precedence) + (is_and_guard<G> ? " && " : " || ") + parenthesized(r, precedence),
                l.named || r.named, precedence};
    } else if constexpr (is_guard_fn<G>) {
        return guard_expression(g.fn, in_text);
    } else {
        return {"guard", false, 3};
    }
}

/// The label of a guard: its name, a composition of named guards ("!released && at_home", an
/// unnamed part shown as "guard"), or "guard" when no part has a name. bsc::in<S> counts as
/// named: "In(S)", or as `in_text(std::type_identity<S>{})` writes it.
template <class G, class InText = in_by_name>
std::string guard_label(G const& g, InText const& in_text = {}) {
    auto const e = guard_expression(g, in_text);
    return e.named ? e.text : "guard";
}

}  // namespace bsc::detail
