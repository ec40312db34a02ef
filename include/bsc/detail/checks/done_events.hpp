#pragma once
// Rows on completion events (bsc::done<S>, SCXML's done.state.S) that can never fire:
//   - S is not a state of the chart (a misspelt name): nothing raises the event;
//   - S never completes: it is basic, final or the root (a final child of the root halts the
//     machine), a composite without a final child, or a parallel state one of whose regions
//     never reaches a final state;
//   - the row's source lies inside S and is not active when S completes: then S's final
//     child is, and for a parallel S its regions and, in each, what completed it.

#include <array>
#include <cstddef>
#include <type_traits>

#include <bsc/detail/meta.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

// The state whose completion an event is (done<S>: S), or void.
template <class E>
struct completed_state {
    using type = void;
};
template <class S>
struct completed_state<done<S>> {
    using type = S;
};

// Whether state s can complete: it raises bsc::done<s> in some configuration.
template <std::size_t N>
constexpr bool can_complete(topology<N> const& t, int s) {
    auto const i = static_cast<std::size_t>(s);
    if (t.kinds[i] == kind::composite) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            if (t.kinds[static_cast<std::size_t>(c)] == kind::final_state) return true;
        return false;
    }
    if (t.kinds[i] == kind::parallel) {
        for (int c = t.first_child[i]; c >= 0; c = t.next_sibling[static_cast<std::size_t>(c)])
            if (t.kinds[static_cast<std::size_t>(c)] != kind::final_state && !can_complete(t, c)) return false;
        return t.first_child[i] >= 0;
    }
    return false;
}

// Whether `source`, a state below s, is active when s completes.
template <std::size_t N>
constexpr bool active_when_complete(topology<N> const& t, int s, int source) {
    int const c = t.child_toward(s, source);
    if (t.kinds[static_cast<std::size_t>(s)] == kind::parallel)
        return c == source || active_when_complete(t, c, source);
    return c == source && t.kinds[static_cast<std::size_t>(c)] == kind::final_state;
}

enum class done_fault { none, not_in_chart, never_raised, source_inactive };

struct done_finding {
    int row = -1;
    done_fault fault = done_fault::none;
};

// The first row on a done event that can never fire. `completes[e]` is, for event e of the
// chart, the index of the state it completes (-1: not a done event; detail::unknown_state:
// done<S> of a state not in the chart).
template <std::size_t N, std::size_t R, std::size_t E>
constexpr done_finding find_dead_done_row(topology<N> const& t, row_table<R> const& r,
                                          std::array<int, E> const& completes) {
    constexpr int root = 1;
    for (std::size_t i = 0; i < R; ++i) {
        if (r.kinds[i] != row_kind::transition || r.trigger[i] < 0) continue;
        int const s = completes[static_cast<std::size_t>(r.trigger[i])];
        if (s == -1) continue;
        if (s == unknown_state) return {static_cast<int>(i), done_fault::not_in_chart};
        if (s <= root || !can_complete(t, s)) return {static_cast<int>(i), done_fault::never_raised};
        if (t.is_proper_ancestor(s, r.source[i]) && !active_when_complete(t, s, r.source[i]))
            return {static_cast<int>(i), done_fault::source_inactive};
    }
    return {};
}

// Whether a chart's events include a completion event: only then is there a row to check.
template <class... Events>
constexpr bool takes_done_event(type_list<Events...>) {
    return any_true({!std::is_void_v<typename completed_state<Events>::type>..., false});
}

// completes[e] for the events of a chart (see find_dead_done_row).
template <class Tags, class... Events>
constexpr std::array<int, sizeof...(Events)> completed_states(type_list<Events...>) {
    return {[] {
        using S = typename completed_state<Events>::type;
        if constexpr (std::is_void_v<S>)
            return -1;
        else
            return position_in<S, Tags>::value >= 0 ? position_in<S, Tags>::value : detail::unknown_state;
    }()...};
}

}  // namespace bsc::detail
