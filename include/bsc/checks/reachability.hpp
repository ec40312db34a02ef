#pragma once
// Reachability (structure only, guards ignored) and dead ends.

#include <bsc/detail/topology.hpp>

namespace bsc::detail {

// Marks s and the states its default entry activates (initial children, all regions).
template <std::size_t N>
constexpr void mark_default_entry(topology<N> const& t, std::array<bool, N>& m, int s) {
    m[static_cast<std::size_t>(s)] = true;
    auto const i = static_cast<std::size_t>(s);
    if (t.is_compound(s)) {
        if (t.initial[i] >= 0)
            mark_default_entry(t, m, t.initial[i]);
    } else if (t.kinds[i] == kind::parallel) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            mark_default_entry(t, m, c);
    }
}

// Marks the states a transition into `target` enters below `domain`: the path, the default
// entries of parallel siblings on the path, and the default entry of the target.
template <std::size_t N>
constexpr void mark_entry(topology<N> const& t, std::array<bool, N>& m, int domain, int target) {
    for (int a = target; a != domain && a >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
        m[static_cast<std::size_t>(a)] = true;
        int const p = t.parent[static_cast<std::size_t>(a)];
        if (p >= 0 && p != domain && t.kinds[static_cast<std::size_t>(p)] == kind::parallel)
            for (int c = t.first_child[static_cast<std::size_t>(p)]; c >= 0;
                 c = t.next_sibling[static_cast<std::size_t>(c)])
                if (c != a)
                    mark_default_entry(t, m, c);
    }
    mark_default_entry(t, m, target);
}

template <std::size_t N, std::size_t R>
constexpr std::array<bool, N> reachable_states(topology<N> const& t, row_table<R> const& r) {
    std::array<bool, N> reach{};
    std::array<bool, R> applied{};
    mark_default_entry(t, reach, 0);
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t i = 0; i < R; ++i) {
            if (applied[i] || r.kinds[i] != row_kind::transition || r.target[i] < 0)
                continue;
            if (!reach[static_cast<std::size_t>(r.source[i])])
                continue;
            applied[i] = changed = true;
            mark_entry(t, reach, -1, r.target[i]);
        }
    }
    return reach;
}

template <std::size_t N, std::size_t R>
constexpr int find_unreachable(topology<N> const& t, row_table<R> const& r) {
    auto const reach = reachable_states(t, r);
    for (std::size_t s = 1; s < N; ++s)
        if (!reach[s])
            return static_cast<int>(s);
    return -1;
}

// A transition can exit leaf x if it has a target, its domain is above x, and its source is
// active whenever x may be: x itself, an ancestor of x, or a state in an orthogonal region.
template <std::size_t N, std::size_t R>
constexpr bool can_leave(topology<N> const& t, row_table<R> const& r, int x) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.target[i] < 0)
            continue;
        int const s = r.source[i];
        if (!t.is_proper_ancestor(r.domain[i], x))
            continue;
        if (t.contains(s, x) || t.kinds[static_cast<std::size_t>(t.lca(s, x))] == kind::parallel)
            return true;
    }
    return false;
}

template <std::size_t N, std::size_t R>
constexpr int find_dead_end(topology<N> const& t, row_table<R> const& r) {
    auto const reach = reachable_states(t, r);
    for (std::size_t s = 1; s < N; ++s)
        if (t.kinds[s] == kind::basic && reach[s] && !can_leave(t, r, static_cast<int>(s)))
            return static_cast<int>(s);
    return -1;
}

}  // namespace bsc::detail
