#pragma once
// Eventless livelock: a cycle of unguarded eventless transitions, which dispatch would
// follow forever. Nodes are basic states; u -> v when an unguarded eventless transition
// enabled in u (its source is u or an ancestor) enters v.

#include <bsc/checks/reachability.hpp>

namespace bsc::detail {

template <std::size_t N, std::size_t R>
constexpr int find_eventless_cycle(topology<N> const& t, row_table<R> const& r) {
    std::array<std::array<bool, N>, N> edge{};
    std::array<int, N> source_of{};
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.guarded[i] || r.trigger[i] != eventless_id)
            continue;
        int const s = r.source[i];
        std::array<bool, N> entered{};
        if (r.target[i] < 0)
            entered = {};  // internal: stays in the same states, and fires again
        else
            mark_entry(t, entered, r.domain[i], r.target[i]);
        for (std::size_t u = 0; u < N; ++u) {
            if (!t.is_leaf(static_cast<int>(u)) || !t.contains(s, static_cast<int>(u)))
                continue;
            if (r.target[i] < 0) {
                edge[u][u] = true;
                source_of[u] = s;
            }
            for (std::size_t v = 0; v < N; ++v)
                if (entered[v] && t.is_leaf(static_cast<int>(v))) {
                    edge[u][v] = true;
                    source_of[u] = s;
                }
        }
    }
    // Peel off states that no edge enters; what stays with an outgoing edge lies on a cycle.
    std::array<bool, N> removed{};
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t v = 0; v < N; ++v) {
            if (removed[v])
                continue;
            bool entered_by_edge = false;
            for (std::size_t u = 0; u < N && !entered_by_edge; ++u) entered_by_edge = !removed[u] && edge[u][v];
            if (!entered_by_edge)
                removed[v] = changed = true;
        }
    }
    for (std::size_t u = 0; u < N; ++u)
        if (!removed[u])
            return source_of[u];
    return -1;
}

}  // namespace bsc::detail
