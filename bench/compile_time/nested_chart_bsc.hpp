#pragma once
// A deep and parallel chart of about N states for the compile-time curves
// (scripts/compile_curves.py): the root is a parallel state of two regions; each region holds
// G = N / 22 composite groups (the first initial) of ten basic states. Basic state k of a group
// takes its own event to state k + 1 of the same group (state 9 back to 0); a group takes its
// region's `next` to the next group of the region. So 22 G + 3 states, 20 G + 2 events and as
// many rows, 20 G of them from basic states three levels down.

#include <bsc/bsc.hpp>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace nested_bsc {

struct Root;
template <int R>
struct Region {};
template <int R, int G>
struct Group {};
template <int R, int G, int K>
struct Leaf {};
template <std::size_t I>
struct E {};  // the event of basic state k of group g of region r: (r * G + g) * 10 + k
template <int R>
struct next {};

struct counter {
    std::uint64_t count = 0;
};

template <std::size_t I>
inline constexpr auto count_action = [](counter& c) { c.count += I + 1; };

/// The number of groups per region, and of events with an index, for about N states.
constexpr int groups(std::size_t n) { return n < 44 ? 1 : static_cast<int>(n / 22); }
template <std::size_t N>
inline constexpr std::size_t event_count = static_cast<std::size_t>(20 * groups(N));

template <int R, int G, int... K>
constexpr auto group(std::integer_sequence<int, K...>) {
    return bsc::composite<Group<R, G>>(bsc::initial<Leaf<R, G, 0>>, bsc::state<Leaf<R, G, K + 1>>...);
}
template <int R, int... G>
constexpr auto region(std::integer_sequence<int, G...>) {
    return bsc::composite<Region<R>>(bsc::initial<Group<R, 0>>, group<R, G>(std::make_integer_sequence<int, 9>{})...);
}

template <int Gs, int R, int G, int K>
constexpr auto leaf_row() {
    constexpr std::size_t e = static_cast<std::size_t>((R * Gs + G) * 10 + K);
    return bsc::state<Leaf<R, G, K>> + bsc::event<E<e>> / count_action<e> = bsc::state<Leaf<R, G, (K + 1) % 10>>;
}
template <int Gs, int R, int G>
constexpr auto group_rows() {
    return bsc::rows(leaf_row<Gs, R, G, 0>(), leaf_row<Gs, R, G, 1>(), leaf_row<Gs, R, G, 2>(), leaf_row<Gs, R, G, 3>(),
                     leaf_row<Gs, R, G, 4>(), leaf_row<Gs, R, G, 5>(), leaf_row<Gs, R, G, 6>(), leaf_row<Gs, R, G, 7>(),
                     leaf_row<Gs, R, G, 8>(), leaf_row<Gs, R, G, 9>(),
                     bsc::state<Group<R, G>> + bsc::event<next<R>> = bsc::state<Group<R, (G + 1) % Gs>>);
}

template <int Gs, int... G>
constexpr auto make_chart(std::integer_sequence<int, G...>) {
    return bsc::make_chart<counter>(bsc::parallel<Root>(region<0>(std::integer_sequence<int, G...>{}),
                                                        region<1>(std::integer_sequence<int, G...>{})),
                                    group_rows<Gs, 0, G>()..., group_rows<Gs, 1, G>()...);
}

/// The chart of about N states.
template <std::size_t N>
inline constexpr auto chart = make_chart<groups(N)>(std::make_integer_sequence<int, groups(N)>{});

}  // namespace nested_bsc
