#pragma once
// Structural checks: every state declared once, every row's states in the tree, exactly one
// initial child per composite, no transition between orthogonal regions.

#include <bsc/model/chart_model.hpp>

namespace bsc::detail {

// The second declaration of a state declared twice, or -1.
template <class... Tags>
constexpr int find_duplicate(type_list<Tags...>) {
    constexpr int first[] = {index_in<Tags, Tags...>()..., 0};
    for (int i = 0; i < static_cast<int>(sizeof...(Tags)); ++i)
        if (first[i] != i)
            return i;
    return -1;
}

template <std::size_t N>
constexpr int find_initial_problem(topology<N> const& t) {
    for (std::size_t s = 1; s < N; ++s)
        if (t.kinds[s] == kind::composite && (t.initial_count[s] != 1 || t.child_count[s] > 255))
            return static_cast<int>(s);
    return -1;
}

template <std::size_t R>
constexpr int find_unknown_state(row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i)
        if (r.source[i] == unknown_state || r.target[i] == unknown_state)
            return static_cast<int>(i);
    return -1;
}

template <std::size_t N, std::size_t R>
constexpr int find_orthogonal_transition(topology<N> const& t, row_table<R> const& r) {
    for (std::size_t i = 0; i < R; ++i) {
        int const s = r.source[i], d = r.target[i];
        if (r.kinds[i] != row_kind::transition || d < 0)
            continue;
        int const l = t.lca(s, d);
        if (t.kinds[static_cast<std::size_t>(l)] == kind::parallel && l != s && l != d)
            return static_cast<int>(i);
    }
    return -1;
}

}  // namespace bsc::detail
