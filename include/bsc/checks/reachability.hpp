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

template <std::size_t N>
constexpr int find_unreachable(topology<N> const&, std::array<bool, N> const& reach) {
    for (std::size_t s = 1; s < N; ++s)
        if (!reach[s]) return static_cast<int>(s);
    return -1;
}

// A basic state x is left by a transition with a target whose domain is above x and whose
// source is active whenever x may be: x itself or an ancestor (then the domain is above x
// too), or a state in another region of a parallel ancestor of x, if the domain is above that
// parallel state. Computed with two flags per state, so the cost is linear in the chart.
template <std::size_t N, std::size_t R>
constexpr int find_dead_end(topology<N> const& t, row_table<R> const& r, std::array<bool, N> const& reach) {
    std::array<bool, N> leaves_from{};     // a targeted transition leaves this state
    std::array<bool, N> region_exits{};    // ... leaves, from inside this region, its parallel parent
    std::array<int, N> exiting_regions{};  // per parallel state: how many of its regions do so
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.target[i] < 0) continue;
        int const src = r.source[i];
        leaves_from[static_cast<std::size_t>(src)] = true;
        for (int a = src; t.parent[static_cast<std::size_t>(a)] >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
            int const p = t.parent[static_cast<std::size_t>(a)];
            if (t.kinds[static_cast<std::size_t>(p)] == kind::parallel && t.is_proper_ancestor(r.domain[i], p) &&
                !region_exits[static_cast<std::size_t>(a)]) {
                region_exits[static_cast<std::size_t>(a)] = true;
                ++exiting_regions[static_cast<std::size_t>(p)];
            }
        }
    }
    for (std::size_t x = 1; x < N; ++x) {
        if (t.kinds[x] != kind::basic || !reach[x]) continue;
        bool leaves = false;
        for (int a = static_cast<int>(x); a > 0 && !leaves; a = t.parent[static_cast<std::size_t>(a)]) {
            auto const ai = static_cast<std::size_t>(a);
            int const p = t.parent[ai];
            leaves = leaves_from[ai] ||
                     (t.kinds[static_cast<std::size_t>(p)] == kind::parallel &&
                      exiting_regions[static_cast<std::size_t>(p)] - int{region_exits[ai]} > 0);
        }
        if (!leaves) return static_cast<int>(x);
    }
    return -1;
}

}  // namespace bsc::detail
