#pragma once
// Transitions that can never fire (seed 000's "unreachable transitions"), found from the
// structure alone, guards ignored:
//   - a row leaving a final child of a composite root: the machine halts there, and dispatch
//     only ever answers outcome::halted;
//   - child first (the default priority): a row on an event leaving a composite or parallel
//     state S when every basic or final state below S takes that event first with an unguarded
//     row of its own or of an ancestor below S (on the event or on a family of it): the event
//     is consumed below S in every configuration, so it never reaches S's row;
//   - parent first: a row on an event leaving S when a proper ancestor of S has an unguarded
//     row on that event or on a family of it: that row is tried first whenever S is active;
//     likewise an eventless row, below an unguarded eventless row of the same component.
// Reachability and dead ends (reachability.hpp) then follow only the rows that can fire.
// A timeout row behind a shorter unguarded timeout of the same state is found where the
// delays are known, in make_chart's constant evaluation (chart.hpp).

#include <array>
#include <cstddef>

#include <bsc/detail/checks/rows_by_source.hpp>
#include <bsc/detail/model/chart_model.hpp>
#include <bsc/priority.hpp>

namespace bsc::detail {

template <std::size_t R>
struct row_liveness {
    std::array<bool, R> dead{};
    int first_dead = -1;  // the first dead row in declaration order, or -1
    int outer = -1;       // parent first: the ancestor whose row always beats first_dead; else -1
};

template <std::size_t N, std::size_t R>
constexpr row_liveness<R> find_dead_transitions(topology<N> const& t, row_table<R> const& r, priority order) {
    row_liveness<R> found;
    constexpr int root = 1;
    bool const root_halts = N > 1 && t.kinds[root] == kind::composite;
    // Whether state b has an unguarded transition row on `trigger` or on a family of it.
    auto const unguarded = rows_by_source<N>(r, [&](std::size_t j) { return !r.guarded[j]; });
    auto takes_unguarded = [&](int b, int trigger) {
        auto const bi = static_cast<std::size_t>(b);
        for (int k = unguarded.begin[bi]; k < unguarded.begin[bi + 1]; ++k)
            if (r.takes(r.trigger[static_cast<std::size_t>(unguarded.order[static_cast<std::size_t>(k)])], trigger))
                return true;
        return false;
    };
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition) continue;
        int const s = r.source[i];
        auto const si = static_cast<std::size_t>(s);
        bool dead = false;
        int outer = -1;
        if (root_halts && t.kinds[si] == kind::final_state && t.parent[si] == root) {
            dead = true;
        } else if (order == priority::parent_first) {
            // An eventless row is tried within its [BSC] component only, under a scan policy:
            // the ancestors above the nearest parallel state take their turn in another one.
            bool const eventless = r.trigger[i] == eventless_id;
            if (r.trigger[i] >= 0 || eventless)
                for (int a = t.parent[si]; a >= 0 && outer < 0; a = t.parent[static_cast<std::size_t>(a)]) {
                    if (eventless && t.kinds[static_cast<std::size_t>(a)] == kind::parallel) break;
                    if (takes_unguarded(a, r.trigger[i])) outer = a;
                }
            dead = outer >= 0;
        } else if (r.trigger[i] >= 0 && !t.is_leaf(s) && t.end[si] > s + 1) {
            dead = true;
            for (int a = s + 1; a < t.end[si] && dead; ++a) {
                if (!t.is_leaf(a)) continue;
                bool taken = false;
                for (int b = a; b != s && !taken; b = t.parent[static_cast<std::size_t>(b)])
                    taken = takes_unguarded(b, r.trigger[i]);
                dead = taken;
            }
        }
        found.dead[i] = dead;
        if (dead && found.first_dead < 0) {
            found.first_dead = static_cast<int>(i);
            found.outer = outer;
        }
    }
    return found;
}

}  // namespace bsc::detail
