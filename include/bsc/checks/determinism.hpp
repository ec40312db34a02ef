#pragma once
// Determinism: two unguarded transitions on the same source and trigger conflict; a
// transition after an unguarded one on the same source and trigger is shadowed.

#include <bsc/detail/topology.hpp>

namespace bsc::detail {

struct row_pair {
    int first = -1;
    int second = -1;
    constexpr bool found() const { return first >= 0; }
};

template <std::size_t R>
constexpr row_pair find_same_trigger_pair(row_table<R> const& r, bool second_guarded) {
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.guarded[i])
            continue;
        for (std::size_t j = i + 1; j < R; ++j)
            if (r.kinds[j] == row_kind::transition && r.source[j] == r.source[i] && r.trigger[j] == r.trigger[i] &&
                r.guarded[j] == second_guarded)
                return {static_cast<int>(i), static_cast<int>(j)};
    }
    return {};
}

template <std::size_t R>
constexpr row_pair find_conflict(row_table<R> const& r) {
    return find_same_trigger_pair(r, false);
}
template <std::size_t R>
constexpr row_pair find_shadowed(row_table<R> const& r) {
    return find_same_trigger_pair(r, true);
}

}  // namespace bsc::detail
