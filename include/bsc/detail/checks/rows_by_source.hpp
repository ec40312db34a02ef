#pragma once
// The rows a check looks at, grouped by source state in declaration order (a counting sort),
// so that a check compares only the rows of one state: linear in the chart for the usual few
// rows per state. Rows of state s are order[begin[s]] .. order[begin[s + 1] - 1].

#include <array>
#include <cstddef>

#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

template <std::size_t N, std::size_t R>
struct row_buckets {
    std::array<int, N + 1> begin{};
    std::array<int, R + 1> order{};
};

// Groups the transition rows for which keep(i) holds.
template <std::size_t N, std::size_t R, class Keep>
constexpr row_buckets<N, R> rows_by_source(row_table<R> const& r, Keep keep) {
    row_buckets<N, R> b;
    auto const kept = [&](std::size_t i) { return r.kinds[i] == row_kind::transition && keep(i); };
    for (std::size_t i = 0; i < R; ++i)
        if (kept(i)) ++b.begin[static_cast<std::size_t>(r.source[i]) + 1];
    for (std::size_t s = 0; s < N; ++s) b.begin[s + 1] += b.begin[s];
    std::array<int, N + 1> fill = b.begin;
    for (std::size_t i = 0; i < R; ++i)
        if (kept(i))
            b.order[static_cast<std::size_t>(fill[static_cast<std::size_t>(r.source[i])]++)] = static_cast<int>(i);
    return b;
}

}  // namespace bsc::detail
