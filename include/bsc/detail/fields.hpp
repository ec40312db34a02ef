#pragma once
// Field access for plain aggregates, without macros or reflection: the number of fields is
// the largest N for which T{any, ..., any} (N times) compiles (any converts to a value or, for a
// reference member, to an lvalue), and structured bindings give
// references to them (detail/field_bindings.hpp). Used to find the channels and timers of a
// context, at any depth of nested aggregates and std::arrays. Supports aggregates of up to
// max_fields (128) fields without base classes or C arrays (use std::array instead).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/detail/config.hpp>
#include <bsc/detail/field_bindings.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>

namespace bsc::detail {

// What a probe's conversion returns: the probes are only used in unevaluated contexts, but a
// member's constructor template that takes one (std::optional's) has its body instantiated, and
// an operator without a definition would then be "used but never defined".
template <class T>
inline T* never_read = nullptr;

// Converts to any member type, so that T{any_field{}...} initialises T's members one by one:
// - a type that can be moved, as an xvalue: a member whose constructor template takes anything
//   (std::optional, std::any) then takes the probe itself, an exact match, rather than being
//   left between that constructor and a conversion;
// - a type that cannot be moved (std::atomic), as a prvalue, which initialises it in place;
// - a member that is a reference, as an lvalue.
struct any_field {
    template <class T>
        requires(!std::is_same_v<T, any_field> && std::is_move_constructible_v<T>)
    constexpr operator T&&() const&& { return static_cast<T&&>(*never_read<T>); }
    template <class T>
        requires(!std::is_same_v<T, any_field> && !std::is_move_constructible_v<T>)
    constexpr operator T() &&;  // (nothing instantiates it: such a member has no constructor template to)
    template <class T>
        requires(!std::is_same_v<T, any_field>)
    constexpr operator T&() const& { return *never_read<T>; }
};
// As any_field, but to values only: it cannot initialise a member that is a non-const reference.
struct any_value_field {
    template <class T>
        requires(!std::is_same_v<T, any_value_field> && std::is_move_constructible_v<T>)
    constexpr operator T&&() const&& { return static_cast<T&&>(*never_read<T>); }
    template <class T>
        requires(!std::is_same_v<T, any_value_field> && !std::is_move_constructible_v<T>)
    constexpr operator T() &&;
};

template <class T, class Probe, std::size_t... I>
constexpr bool brace_constructible(std::index_sequence<I...>) {
    return requires { T{(void(I), Probe{})...}; };
}

// The members initialised one by one: exact for an aggregate that is default-constructible (any
// shorter list of initialisers is valid too).
template <class T, class Probe, std::size_t N = 0>
constexpr std::size_t leading_field_count() {
    if constexpr (N > max_fields)
        return N;
    else if constexpr (brace_constructible<T, Probe>(std::make_index_sequence<N + 1>{}))
        return leading_field_count<T, Probe, N + 1>();
    else
        return N;
}

// The largest count in [From, To] that initialises every member: an aggregate with a reference
// member and no default initialiser for it cannot be initialised by a shorter list, so the count
// is searched up to its size (each member takes at least a byte).
template <class T, class Probe, std::size_t From, std::size_t To>
constexpr std::size_t largest_field_count(std::size_t found) {
    if constexpr (From > To)
        return found;
    else
        return largest_field_count<T, Probe, From + 1, To>(
            brace_constructible<T, Probe>(std::make_index_sequence<From>{}) ? From : found);
}

template <class T, class Probe>
constexpr std::size_t field_count_by() {
    constexpr std::size_t leading = leading_field_count<T, Probe>();
    if constexpr (leading > max_fields || std::is_default_constructible_v<T>)
        return leading;
    else
        return largest_field_count<T, Probe, leading + 1, (sizeof(T) < max_fields ? sizeof(T) : max_fields)>(leading);
}

template <class T>
constexpr std::size_t field_count() {
    return field_count_by<T, any_field>();
}

/// Whether an aggregate has a member that is a non-const lvalue reference (a const one binds a
/// value, and shows as a const field): the retentive state refuses both, since what lies behind
/// a reference is not the machine's.
template <class T>
inline constexpr bool has_reference_field = !brace_constructible<T, any_value_field>(
    std::make_index_sequence<field_count<T>()>{});

// f(fields...) for the fields of an aggregate, each an lvalue; f() for a type that is not one
// (after the error that says so). Clang 14 leaves the visit of a context's timers out of line
// unless told, with a call and its spills in every cycle; GCC 12 inlines it where that pays
// (bench/manufacturing_cell_bench.cpp: forced, its cycle took more instructions, not fewer;
// docs/performance.md, rule "Fields visited without a tuple").
template <class T, class F>
BSC_DETAIL_VISIT_INLINE constexpr decltype(auto) apply_to_fields(T& t, F&& f) {
    using type = std::remove_const_t<T>;
    constexpr std::size_t n = field_count<type>();
    if constexpr (!std::is_aggregate_v<type>) {
        detail::report<error::context_not_an_aggregate<type>>();
        return f();
    } else if constexpr (n > max_fields) {
        detail::report<error::too_many_fields<type>>();
        return f();
    } else {
        return field_binder<n>::apply(t, f);
    }
}

// A tuple of references to the fields of an aggregate (for their types and for std::get: a
// visit of every field is for_each_field, which builds no tuple).
template <class T>
constexpr auto tie_fields(T& t) {
    return detail::apply_to_fields(t, [](auto&... field) { return std::tie(field...); });
}

// Calls f(field) for each field of an aggregate, in declaration order.
template <class T, class F>
BSC_DETAIL_VISIT_INLINE  // as apply_to_fields
    constexpr void
    for_each_field(T& t, F&& f) {
    detail::apply_to_fields(t, [&](auto&... field) { (f(field), ...); });
}

}  // namespace bsc::detail
