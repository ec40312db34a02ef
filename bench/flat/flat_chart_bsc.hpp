#pragma once
// The flat chart of bench/flat/flat_workload.hpp for bsc, for any number of states N.

#include <bsc/bsc.hpp>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "../bsc_variant.hpp"

namespace flat_bsc {

template <std::size_t N>
struct Root {};
template <std::size_t I>
struct S {};
template <std::size_t I>
struct E {};

struct counter {
    std::uint64_t count = 0;
};

// The actions' noexcept: bench/bsc_variant.hpp.
template <std::size_t I>
inline constexpr auto count_action = [](counter& c) noexcept(BENCH_NOEXCEPT_ACTIONS) { c.count += I + 1; };

constexpr std::size_t handled_by(std::size_t i, std::size_t n) { return (7 * i + 3) % n; }

template <std::size_t N, std::size_t... Others, std::size_t... I>
constexpr auto make_chart(std::index_sequence<Others...>, std::index_sequence<I...>) {
    return bsc::make_chart<counter>(
        bsc::composite<Root<N>>(bsc::initial<S<0>>, bsc::state<S<Others + 1>>...),
        (bsc::state<S<I>> + bsc::event<E<handled_by(I, N)>> / count_action<I> = bsc::state<S<(I + 1) % N>>)...);
}

/// The chart of N states, N events and N transitions.
template <std::size_t N>
inline constexpr auto chart = make_chart<N>(std::make_index_sequence<N - 1>{}, std::make_index_sequence<N>{});

}  // namespace flat_bsc
