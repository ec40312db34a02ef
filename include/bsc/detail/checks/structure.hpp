#pragma once
// Structural checks: every state declared once, every row's states in the tree, exactly one
// initial child per composite, no transition between orthogonal regions, every local
// transition's target inside its source.

#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

// The second declaration of a state declared twice, or -1.
template <class... Tags>
constexpr int find_duplicate(type_list<Tags...>) {
    constexpr int first[] = {position_in<Tags, type_list<Tags...>>::value..., 0};
    for (int i = 0; i < static_cast<int>(sizeof...(Tags)); ++i)
        if (first[i] != i) return i;
    return -1;
}

template <std::size_t N>
constexpr int find_initial_problem(topology<N> const& t) {
    for (std::size_t s = 1; s < N; ++s)
        if (t.kinds[s] == kind::composite && t.initial_count[s] != 1) return static_cast<int>(s);
    return -1;
}

template <std::size_t R>
constexpr int find_unknown_state(row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.source[i] == unknown_state || r.target[i] == unknown_state) return static_cast<int>(i);
        for (int m : r.more_targets[i])
            if (m == unknown_state) return static_cast<int>(i);
    }
    return -1;
}

template <std::size_t N, std::size_t R>
constexpr int find_orthogonal_transition(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        int const s = r.source[i], d = r.target[i];
        if (r.kinds[i] != row_kind::transition || d < 0) continue;
        int const l = t.lca(s, d);
        if (t.kinds[static_cast<std::size_t>(l)] == kind::parallel && l != s && l != d) return static_cast<int>(i);
    }
    return -1;
}

// The first history pseudo-state that is not a child of a composite, whose default does not
// lie inside its composite (or is a history state), or that is the source of a row other than
// on_initial; -1 if none.
template <std::size_t N, std::size_t R>
constexpr int find_invalid_history(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t s = 1; s < N; ++s) {
        if (t.kinds[s] != kind::history) continue;
        auto const p = static_cast<std::size_t>(t.parent[s]);
        int const d = t.initial_target[s];
        if (t.kinds[p] != kind::composite || d < 0 || t.kinds[static_cast<std::size_t>(d)] == kind::history)
            return static_cast<int>(s);
    }
    for (std::size_t i = 0; i < R; ++i)
        if (r.kinds[i] != row_kind::initial && r.source[i] >= 0 &&
            t.kinds[static_cast<std::size_t>(r.source[i])] == kind::history)
            return r.source[i];
    return -1;
}

// The first on_initial row of a state that takes no initial transition (not a composite, or
// one with a history marker, which takes its history instead), or -1.
template <std::size_t N, std::size_t R>
constexpr int find_misplaced_initial_action(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::initial) continue;
        auto const s = static_cast<std::size_t>(r.source[i]);
        if (t.kinds[s] == kind::history) continue;  // the action of a history state's default transition
        if (t.kinds[s] != kind::composite || t.hist[s] != history::none) return static_cast<int>(i);
    }
    return -1;
}

// The first row that defers but has no event trigger (eventless, a timeout), takes
// bsc::any_event (which would keep only its tag), or has a target; -1 if none.
template <std::size_t R>
constexpr int find_invalid_deferral(row_table<R> const& r, int any_event_trigger) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.defers[i] && (r.trigger[i] < 0 || r.trigger[i] == any_event_trigger || r.target[i] >= 0))
            return static_cast<int>(i);
    return -1;
}

// Whether the states in `all` (n of them) lie pairwise in different regions of parallel states.
template <std::size_t N, std::size_t M>
constexpr bool orthogonal_set(topology<N> const& t, std::array<int, M> const& all, std::size_t n) {
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b)
            if (all[a] < 0 || all[b] < 0 || t.contains(all[a], all[b]) || t.contains(all[b], all[a]) ||
                t.kinds[static_cast<std::size_t>(t.lca(all[a], all[b]))] != kind::parallel)
                return false;
    return true;
}

// The first composite with several initial states (bsc::initial<A, B>) one of which does not
// lie below it, or two of which are not in different regions of a parallel state; -1 if none.
template <std::size_t N>
constexpr int find_initial_set_problem(topology<N> const& t) {
    for (std::size_t s = 1; s < N; ++s) {
        if (t.kinds[s] != kind::composite || t.more_initial[s][0] == -1) continue;
        auto const all = t.initial_states(s);
        std::size_t n = 1;  // the first always (-1 if it is not below s); then up to the first -1
        while (n < all.size() && all[n] != -1) ++n;  // (unknown_state, -2, counts: it is reported)
        for (std::size_t k = 0; k < n; ++k)
            if (all[k] < 0 || !t.is_proper_ancestor(static_cast<int>(s), all[k])) return static_cast<int>(s);
        if (!orthogonal_set(t, all, n)) return static_cast<int>(s);
    }
    return -1;
}

// The first row with several targets two of which are not in different regions of a parallel
// state (one contains the other, or their nearest common ancestor is a composite); -1 if none.
template <std::size_t N, std::size_t R>
constexpr int find_targets_not_orthogonal(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        if (!r.several(i)) continue;
        auto const all = r.targets_of(i);
        std::size_t n = 0;
        while (n < all.size() && all[n] >= 0) ++n;
        if (!orthogonal_set(t, all, n)) return static_cast<int>(i);
    }
    return -1;
}

// The first local row whose target is not a proper descendant of its source, or -1.
template <std::size_t N, std::size_t R>
constexpr int find_misplaced_local(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.local[i] && !t.is_proper_ancestor(r.source[i], r.target[i])) return static_cast<int>(i);
    return -1;
}

}  // namespace bsc::detail
