#pragma once
// Reachability (structure only, guards ignored) and dead ends. Both follow only the rows
// that can fire: `dead` marks the ones that never do (dead_transitions.hpp).

#include <bsc/detail/checks/rows_by_source.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

// The states marked: flags, or flags and the list of the states in the order they were first
// marked (reachable_states works through that list).
template <std::size_t N>
constexpr void set_mark(std::array<bool, N>& m, int s) {
    m[static_cast<std::size_t>(s)] = true;
}
template <std::size_t N>
struct marked_states {
    std::array<bool, N> flag{};
    std::array<int, N> in_order{};
    std::size_t count = 0;
};
template <std::size_t N>
constexpr void set_mark(marked_states<N>& m, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (m.flag[i]) return;
    m.flag[i] = true;
    m.in_order[m.count++] = s;
}

template <std::size_t N, class Marks>
constexpr void mark_entry(topology<N> const& t, Marks& m, int domain, int target);

// Marks s and the states its default entry activates (initial states, all regions, a
// history state's default).
template <std::size_t N, class Marks>
constexpr void mark_default_entry(topology<N> const& t, Marks& m, int s) {
    set_mark(m, s);
    auto const i = static_cast<std::size_t>(s);
    if (t.is_compound(s)) {
        if (t.initial_target[i] >= 0 && t.initial_target[i] != t.initial[i])
            mark_entry(t, m, s, t.initial_target[i]);  // a deep initial
        else if (t.initial[i] >= 0)
            mark_default_entry(t, m, t.initial[i]);
        for (int more : t.more_initial[i]) {  // initial<A, B>: each of the others
            if (more >= 0) mark_entry(t, m, s, more);
        }
    } else if (t.kinds[i] == kind::parallel) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            mark_default_entry(t, m, c);
    } else if (t.kinds[i] == kind::history && t.initial_target[i] >= 0) {
        // A history state enters its default (what it restores has been active before).
        mark_entry(t, m, t.parent[i], t.initial_target[i]);
    }
}

// Marks the states a transition into `target` enters below `domain`: the path, the default
// entries of parallel siblings on the path, and the default entry of the target. A transition
// with several targets (bsc::targets) is marked target by target: each marks the default
// entry of the regions the others enter otherwise, which keeps reachability an
// over-approximation (a state it calls unreachable is, whatever the targets).
template <std::size_t N, class Marks>
constexpr void mark_entry(topology<N> const& t, Marks& m, int domain, int target) {
    for (int a = target; a != domain && a >= 0; a = t.parent[static_cast<std::size_t>(a)]) {
        set_mark(m, a);
        int const p = t.parent[static_cast<std::size_t>(a)];
        if (p >= 0 && p != domain && t.kinds[static_cast<std::size_t>(p)] == kind::parallel)
            for (int c = t.first_child[static_cast<std::size_t>(p)]; c >= 0;
                 c = t.next_sibling[static_cast<std::size_t>(c)])
                if (c != a) mark_default_entry(t, m, c);
    }
    mark_default_entry(t, m, target);
}

// Whether entering state s can restore a child of `of` by shallow history, which enters that
// child by its default entry: s is a shallow history state, or a composite with a shallow
// history marker (which it is then the `of` of).
template <std::size_t N>
constexpr int restored_by_shallow_history(topology<N> const& t, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (t.hist[i] != history::shallow) return -1;
    if (t.kinds[i] == kind::history) return t.parent[i];
    return t.kinds[i] == kind::composite ? s : -1;
}

// The states some sequence of firing rows reaches. Each state is visited once, when first
// reached, and then follows its own rows (grouped by source, rows_by_source.hpp): linear in
// the chart, whatever the order of its rows.
template <std::size_t N, std::size_t R>
constexpr std::array<bool, N> reachable_states(topology<N> const& t, row_table<R> const& r,
                                               std::array<bool, R> const& dead) {
    auto const rows = rows_by_source<N>(r, [&](std::size_t i) { return !dead[i] && r.target[i] >= 0; });
    marked_states<N> reach;
    std::array<bool, N> restoring{};  // composites a reached shallow history restores a child of
    std::array<bool, N> restored{};   // children a shallow history has re-entered by default
    // A shallow history restores a child that has been active, and enters it by default: its
    // initial states become active even if they never were (SCXML IRP test 388).
    auto const restore = [&](int c) {
        auto const ci = static_cast<std::size_t>(c);
        if (restored[ci] || t.kinds[ci] == kind::history) return;
        restored[ci] = true;
        mark_default_entry(t, reach, c);
    };
    mark_default_entry(t, reach, 0);
    for (std::size_t next = 0; next < reach.count; ++next) {
        int const s = reach.in_order[next];
        auto const si = static_cast<std::size_t>(s);
        for (int k = rows.begin[si]; k < rows.begin[si + 1]; ++k)
            for (int target : r.targets_of(static_cast<std::size_t>(rows.order[static_cast<std::size_t>(k)])))
                if (target >= 0) mark_entry(t, reach, -1, target);
        int const parent = t.parent[si];
        if (parent >= 0 && restoring[static_cast<std::size_t>(parent)]) restore(s);
        int const of = restored_by_shallow_history(t, s);
        if (of >= 0 && !restoring[static_cast<std::size_t>(of)]) {
            restoring[static_cast<std::size_t>(of)] = true;
            for (int c = t.first_child[static_cast<std::size_t>(of)]; c >= 0;
                 c = t.next_sibling[static_cast<std::size_t>(c)])
                if (reach.flag[static_cast<std::size_t>(c)]) restore(c);
        }
    }
    return reach.flag;
}

template <std::size_t N>
constexpr int find_unreachable(topology<N> const&, std::array<bool, N> const& reach) {
    for (std::size_t s = 1; s < N; ++s)
        if (!reach[s]) return static_cast<int>(s);
    return -1;
}

// Whether entering `target` necessarily enters basic state x again: x itself, or an ancestor
// whose initial children (or history, which remembers x) lead back down to x.
template <std::size_t N>
constexpr bool reenters(topology<N> const& t, int target, int x) {
    if (target == x) return true;
    if (!t.is_proper_ancestor(target, x)) return false;
    for (int c = target; c != x;) {
        auto const ci = static_cast<std::size_t>(c);
        int const toward = t.child_toward(c, x);
        if (t.kinds[ci] == kind::composite) {
            if (t.hist[ci] == history::deep) return true;
            if (t.hist[ci] == history::none && t.initial[ci] != toward) return false;
        }
        c = toward;
    }
    return true;
}

// A basic state x has a way out if some transition with a target can fire while x is active,
// exits x (its domain is above x) and does not necessarily enter x again. Such a transition
// leaves x itself or an ancestor of x, or a state in another region of a parallel ancestor of x
// (then its domain must be above that parallel state). Rows are grouped by source
// (rows_by_source.hpp), so both kinds are found without scanning every row for every state.
template <std::size_t N, std::size_t R>
constexpr int find_dead_end(topology<N> const& t, row_table<R> const& r, std::array<bool, R> const& dead,
                            std::array<bool, N> const& reach) {
    auto const rows = rows_by_source<N>(r, [&](std::size_t i) { return r.target[i] >= 0 && !dead[i]; });
    auto const& begin = rows.begin;
    auto const& order = rows.order;
    // Rows whose source lies in the states [lo, hi) of document order.
    auto way_out_among = [&](int lo, int hi, int x, int above) {
        for (int k = begin[static_cast<std::size_t>(lo)]; k < begin[static_cast<std::size_t>(hi)]; ++k) {
            auto const i = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
            if (t.is_proper_ancestor(r.domain[i], above) && !reenters(t, r.target[i], x)) return true;
        }
        return false;
    };
    for (std::size_t xi = 1; xi < N; ++xi) {
        if (t.kinds[xi] != kind::basic || !reach[xi]) continue;
        int const x = static_cast<int>(xi);
        bool leaves = false;
        for (int a = x; a > 0 && !leaves; a = t.parent[static_cast<std::size_t>(a)]) {
            leaves = way_out_among(a, a + 1, x, x);
            int const p = t.parent[static_cast<std::size_t>(a)];
            if (!leaves && t.kinds[static_cast<std::size_t>(p)] == kind::parallel)
                leaves = way_out_among(p + 1, a, x, p) ||
                         way_out_among(t.end[static_cast<std::size_t>(a)], t.end[static_cast<std::size_t>(p)], x, p);
        }
        if (!leaves) return x;
    }
    return -1;
}

}  // namespace bsc::detail
