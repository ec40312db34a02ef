#pragma once
// Field access for plain aggregates, without macros or reflection: the number of fields is
// the largest N for which T{any, ..., any} (N times) compiles, and structured bindings give
// references to them (detail/field_bindings.hpp). Used to find the channels and timers of a
// context, at any depth of nested aggregates and std::arrays. Supports aggregates of up to
// max_fields (128) fields without base classes or C arrays (use std::array instead).

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/detail/field_bindings.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/error.hpp>

namespace bsc::detail {

struct any_field {
    template <class T>
    constexpr operator T() const;  // only used in unevaluated contexts
};

template <class T, std::size_t... I>
constexpr bool brace_constructible(std::index_sequence<I...>) {
    return requires { T{(void(I), any_field{})...}; };
}

template <class T, std::size_t N = 0>
constexpr std::size_t field_count() {
    if constexpr (N > max_fields)
        return N;
    else if constexpr (brace_constructible<T>(std::make_index_sequence<N + 1>{}))
        return field_count<T, N + 1>();
    else
        return N;
}

// A tuple of references to the fields of an aggregate.
template <class T>
constexpr auto tie_fields(T& t) {
    using type = std::remove_const_t<T>;
    constexpr std::size_t n = field_count<type>();
    if constexpr (!std::is_aggregate_v<type>) {
        detail::report<error::context_not_an_aggregate<type>>();
        return std::tuple<>{};
    } else if constexpr (n > max_fields) {
        detail::report<error::too_many_fields<type>>();
        return std::tuple<>{};
    } else {
        return bind_fields<n>(t);
    }
}

// Calls f(field) for each field of an aggregate, in declaration order.
template <class T, class F>
constexpr void for_each_field(T& t, F&& f) {
    std::apply([&](auto&... field) { (f(field), ...); }, tie_fields(t));
}

}  // namespace bsc::detail
