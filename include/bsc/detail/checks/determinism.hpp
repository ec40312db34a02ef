#pragma once
// Determinism: two unguarded transitions on the same source and trigger conflict; a
// transition after an unguarded one on the same source and trigger, or on a family of its
// trigger (detail/model/event_families.hpp), is shadowed.

#include <bsc/detail/checks/rows_by_source.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

struct row_pair {
    int first = -1;
    int second = -1;
    constexpr bool found() const { return first >= 0; }
};

struct determinism_findings {
    row_pair conflict;  // the first pair of unguarded rows on one source and trigger
    row_pair shadowed;  // the first unguarded row followed by a guarded one
};

// Only rows of the same source are compared (rows_by_source.hpp).
template <std::size_t N, std::size_t R>
constexpr determinism_findings find_nondeterminism(topology<N> const&, row_table<R> const& r) {
    determinism_findings found;
    auto const rows = rows_by_source<N>(r, [](std::size_t) { return true; });
    auto const& begin = rows.begin;
    auto const& order = rows.order;
    // Report the pair a reader meets first: by the earlier row, then by the later one.
    auto earlier = [](row_pair const& a, int i, int j) {
        return !a.found() || i < a.first || (i == a.first && j < a.second);
    };
    for (std::size_t s = 0; s < N; ++s)
        for (int a = begin[s]; a < begin[s + 1]; ++a) {
            auto const i = static_cast<std::size_t>(order[static_cast<std::size_t>(a)]);
            if (r.guarded[i]) continue;
            for (int b = a + 1; b < begin[s + 1]; ++b) {
                auto const j = static_cast<std::size_t>(order[static_cast<std::size_t>(b)]);
                // Row i takes every event row j takes: the same trigger, or a family of j's.
                if (!r.takes(r.trigger[i], r.trigger[j])) continue;
                bool const same = r.trigger[j] == r.trigger[i];
                row_pair& slot = r.guarded[j] || !same ? found.shadowed : found.conflict;
                if (earlier(slot, static_cast<int>(i), static_cast<int>(j)))
                    slot = {static_cast<int>(i), static_cast<int>(j)};
            }
        }
    return found;
}

}  // namespace bsc::detail
