#pragma once
// Eventless livelock: a cycle of unguarded eventless transitions, which dispatch would
// follow forever. Nodes are basic states; u -> v when an unguarded eventless transition
// enabled in u (its source is u or an ancestor) enters v, and no other unguarded eventless
// transition enabled in u is tried before it (bsc/priority.hpp): with child-first priority,
// one whose source lies between u and the row's; with parent-first, one of an ancestor of the
// row's source.

#include <bsc/detail/checks/reachability.hpp>
#include <bsc/priority.hpp>

namespace bsc::detail {

template <std::size_t R>
constexpr bool has_unguarded_eventless(row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] == row_kind::transition && !r.guarded[i] && r.trigger[i] == eventless_id) return true;
    return false;
}

// Calls f(u, v, source) for each edge u -> v between basic states that an unguarded eventless
// transition (from `source`, enabled in u) makes.
template <std::size_t N, std::size_t R, class F>
constexpr void for_each_eventless_edge(topology<N> const& t, row_table<R> const& r, priority order, F&& f) {
    std::array<bool, N> has_unguarded{};  // the states with an unguarded eventless row
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] == row_kind::transition && !r.guarded[i] && r.trigger[i] == eventless_id)
            has_unguarded[static_cast<std::size_t>(r.source[i])] = true;
    // Whether a state from `below` up to `above` (exclusive) has one.
    auto const taken_between = [&](int below, int above) {
        for (int a = below; a != above && a >= 0; a = t.parent[static_cast<std::size_t>(a)])
            if (has_unguarded[static_cast<std::size_t>(a)]) return true;
        return false;
    };
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.guarded[i] || r.trigger[i] != eventless_id) continue;
        int const s = r.source[i];
        if (order == priority::parent_first && taken_between(t.parent[static_cast<std::size_t>(s)], -1)) continue;
        std::array<bool, N> entered{};
        if (r.target[i] >= 0) mark_entry(t, entered, r.domain[i], r.target[i]);
        for (int u = s; u < t.end[static_cast<std::size_t>(s)]; ++u) {
            if (!t.is_leaf(u)) continue;
            if (order == priority::child_first && taken_between(u, s)) continue;
            if (r.target[i] < 0) {
                f(u, u, s);  // internal: it stays in the same states and fires again
                continue;
            }
            for (int v = 0; v < static_cast<int>(N); ++v)
                if (entered[static_cast<std::size_t>(v)] && t.is_leaf(v)) f(u, v, s);
        }
    }
}

template <std::size_t N, std::size_t R>
constexpr std::size_t count_eventless_edges(topology<N> const& t, row_table<R> const& r, priority order) {
    std::size_t n = 0;
    if (has_unguarded_eventless(r)) for_each_eventless_edge(t, r, order, [&](int, int, int) { ++n; });
    return n;
}

// Returns the source of an unguarded eventless transition on a cycle, or -1. E is the number
// of edges (count_eventless_edges); zero in the common case, which then costs nothing more.
template <std::size_t E, std::size_t N, std::size_t R>
constexpr int find_eventless_cycle(topology<N> const& t, row_table<R> const& r, priority order) {
    if constexpr (E == 0) {
        return -1;
    } else {
        struct edge {
            int from, to, source;
        };
        std::array<edge, E> edges{};
        std::size_t count = 0;
        for_each_eventless_edge(t, r, order, [&](int u, int v, int s) { edges[count++] = {u, v, s}; });
        // Peel off states without incoming or without outgoing edges among the rest: what remains
        // is the union of the cycles.
        std::array<bool, N> removed{};
        for (bool changed = true; changed;) {
            changed = false;
            std::array<int, N> in{}, out{};
            for (std::size_t e = 0; e < count; ++e)
                if (!removed[static_cast<std::size_t>(edges[e].from)] &&
                    !removed[static_cast<std::size_t>(edges[e].to)]) {
                    ++out[static_cast<std::size_t>(edges[e].from)];
                    ++in[static_cast<std::size_t>(edges[e].to)];
                }
            for (std::size_t v = 0; v < N; ++v)
                if (!removed[v] && (in[v] == 0 || out[v] == 0)) removed[v] = changed = true;
        }
        for (std::size_t e = 0; e < count; ++e)
            if (!removed[static_cast<std::size_t>(edges[e].from)] && !removed[static_cast<std::size_t>(edges[e].to)])
                return edges[e].source;
        return -1;
    }
}

}  // namespace bsc::detail
