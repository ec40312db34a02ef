#pragma once
// Runs every static check of a chart and turns a finding into the error that names it.
// Structural checks come first: the others assume a well-formed tree.

#include <bsc/checks/determinism.hpp>
#include <bsc/checks/errors.hpp>
#include <bsc/checks/livelock.hpp>
#include <bsc/checks/reachability.hpp>
#include <bsc/checks/structure.hpp>
#include <bsc/detail/topology.hpp>

namespace bsc::detail {

template <class Row>
struct trigger_type {
    using type = typename trigger_event<Row>::type;
};
template <class S, class G, class A, class T>
struct trigger_type<transition_row<S, eventless_trigger, G, A, T>> {
    using type = eventless_trigger;
};

// Whether the tree and the rows are well formed, computed without reporting anything, so
// that the other checks are not even instantiated on a malformed chart.
template <class Chart>
constexpr bool structure_valid() {
    using an = analysis<Chart>;
    return find_duplicate(typename an::tags{}) < 0 && find_unknown_state(an::table) < 0 &&
           find_initial_problem(an::topo) < 0;
}

template <class Chart>
constexpr bool check_structure() {
    using an = analysis<Chart>;
    constexpr int duplicate = find_duplicate(typename an::tags{});
    if constexpr (duplicate >= 0) {
        using S = typename an::template tag_at<duplicate>;
        constexpr int first = an::template index_of_state<S>;
        constexpr int implicit = an::topo.implicit[duplicate] ? duplicate : an::topo.implicit[first] ? first : -1;
        if constexpr (implicit >= 0)
            return error::initial_not_a_child<typename an::template tag_at<an::topo.parent[implicit]>, S>::value;
        else
            return error::duplicate_state<S>::value;
    } else {
        constexpr int unknown = find_unknown_state(an::table);
        if constexpr (unknown >= 0) {
            using row = typename an::template row_at<unknown>;
            if constexpr (an::table.source[unknown] == unknown_state)
                return error::state_not_in_chart<typename row::source>::value;
            else
                return error::state_not_in_chart<typename row::target>::value;
        } else {
            constexpr int composite = find_initial_problem(an::topo);
            if constexpr (composite >= 0) {
                using S = typename an::template tag_at<composite>;
                if constexpr (an::topo.child_count[composite] > 255)
                    return error::too_many_children<S>::value;
                else if constexpr (an::topo.initial_count[composite] == 0)
                    return error::missing_initial_state<S>::value;
                else
                    return error::multiple_initial_states<S>::value;
            } else {
                return true;
            }
        }
    }
}

template <class Chart>
constexpr bool check_orthogonality() {
    using an = analysis<Chart>;
    constexpr int row = find_orthogonal_transition(an::topo, an::table);
    if constexpr (row >= 0) {
        using R = typename an::template row_at<row>;
        return error::transition_between_orthogonal_regions<typename R::source, typename R::target>::value;
    } else {
        return true;
    }
}

template <class Chart>
constexpr bool check_determinism() {
    using an = analysis<Chart>;
    constexpr determinism_findings found = find_nondeterminism(an::topo, an::table);
    constexpr row_pair conflict = found.conflict;
    constexpr row_pair shadowed = found.shadowed;
    if constexpr (conflict.found()) {
        using R = typename an::template row_at<conflict.second>;
        return error::conflicting_transitions<typename R::source, typename trigger_type<R>::type>::value;
    } else if constexpr (shadowed.found()) {
        using R = typename an::template row_at<shadowed.second>;
        return error::shadowed_transition<typename R::source, typename trigger_type<R>::type,
                                          typename R::target>::value;
    } else {
        return true;
    }
}

template <class Chart>
constexpr bool check_reachability() {
    using an = analysis<Chart>;
    constexpr auto reach = reachable_states(an::topo, an::table);
    constexpr int unreachable = find_unreachable(an::topo, reach);
    if constexpr (unreachable >= 0) {
        return error::unreachable_state<typename an::template tag_at<unreachable>>::value;
    } else {
        constexpr int dead_end = find_dead_end(an::topo, an::table, reach);
        if constexpr (dead_end >= 0)
            return error::dead_end_state<typename an::template tag_at<dead_end>>::value;
        else
            return true;
    }
}

template <class Chart>
constexpr bool check_livelock() {
    using an = analysis<Chart>;
    constexpr std::size_t edges = count_eventless_edges(an::topo, an::table);
    constexpr int source = find_eventless_cycle<edges>(an::topo, an::table);
    if constexpr (source >= 0)
        return error::eventless_livelock<typename an::template tag_at<source>>::value;
    else
        return true;
}

// True for a well-formed chart; otherwise one of the bsc::error templates fails to instantiate.
template <class Chart>
constexpr bool check_chart() {
    if constexpr (!structure_valid<Chart>())
        return check_structure<Chart>();
    else {
        // Each check is evaluated, so one build reports every kind of problem it finds.
        constexpr bool orthogonal = check_orthogonality<Chart>();
        constexpr bool deterministic = check_determinism<Chart>();
        constexpr bool reachable = check_reachability<Chart>();
        constexpr bool settles = check_livelock<Chart>();
        return orthogonal && deterministic && reachable && settles;
    }
}

}  // namespace bsc::detail
