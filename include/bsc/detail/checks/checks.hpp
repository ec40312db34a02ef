#pragma once
// Runs every static check of a chart and turns each finding into the error type that names
// it. A check returns its findings as a type_list of bsc::error types (empty: nothing found);
// nothing is reported here: make_chart returns the findings (detail::rejected_chart), and
// their destruction reports them. Structural checks come first: the others assume a
// well-formed tree.

#include <bsc/detail/checks/dead_transitions.hpp>
#include <bsc/detail/checks/determinism.hpp>
#include <bsc/detail/checks/done_events.hpp>
#include <bsc/error.hpp>
#include <bsc/detail/checks/livelock.hpp>
#include <bsc/detail/checks/reachability.hpp>
#include <bsc/detail/checks/row_text.hpp>
#include <bsc/detail/checks/signatures.hpp>
#include <bsc/detail/checks/structure.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

template <class Row>
struct trigger_type {
    using type = typename trigger_event<Row>::type;
};
template <class S, class G, class A, class T>
struct trigger_type<transition_row<S, eventless_trigger, G, A, T>> {
    using type = eventless_trigger;
};
template <class S, class G, class A, class T>
struct trigger_type<transition_row<S, timeout_trigger, G, A, T>> {
    using type = timeout_trigger;
};

// An error about the row at Index of the chart's rows (error::at_row names its position and,
// where the compiler prints strings legibly, the row as written).
template <class Chart, int Index, class Error>
using row_error = error::at_row<static_cast<std::size_t>(Index) + 1, Error,
#if BSC_DETAIL_PRINTS_STRING_ARGUMENTS
                                error::as_written<row_text<typename chart_model<Chart>::template row_at<Index>>()>
#else
                                void
#endif
                                >;

// Whether the tree and the rows are well formed, computed without reporting anything, so
// that the other checks are not even instantiated on a malformed chart.
template <class Chart>
constexpr bool structure_valid() {
    using model = chart_model<Chart>;
    return find_duplicate(typename model::tags{}) < 0 && find_unknown_state(model::rows) < 0 &&
           find_initial_problem(model::tree) < 0 && find_invalid_history(model::tree, model::rows) < 0 &&
           find_initial_set_problem(model::tree) < 0;
}

template <class Chart>
constexpr auto check_structure() {
    using model = chart_model<Chart>;
    constexpr int duplicate = find_duplicate(typename model::tags{});
    if constexpr (duplicate >= 0) {
        using S = typename model::template tag_at<duplicate>;
        constexpr int first = model::template index_of_state<S>::value;
        constexpr int implicit = model::tree.implicit[duplicate] ? duplicate : model::tree.implicit[first] ? first : -1;
        if constexpr (implicit >= 0)
            return type_list<
                error::initial_not_a_child<typename model::template tag_at<model::tree.parent[implicit]>, S>>{};
        else
            return type_list<error::duplicate_state<S>>{};
    } else {
        constexpr int unknown = find_unknown_state(model::rows);
        if constexpr (unknown >= 0) {
            using row = typename model::template row_at<unknown>;
            if constexpr (model::rows.source[unknown] == unknown_state)
                return type_list<row_error<Chart, unknown, error::state_not_in_chart<typename row::source>>>{};
            else
                return type_list<row_error<Chart, unknown, error::state_not_in_chart<typename row::target>>>{};
        } else {
            constexpr int composite = find_initial_problem(model::tree);
            if constexpr (composite >= 0) {
                using S = typename model::template tag_at<composite>;
                if constexpr (model::tree.initial_count[composite] == 0)
                    return type_list<error::missing_initial_state<S>>{};
                else
                    return type_list<error::multiple_initial_states<S>>{};
            } else {
                constexpr int history_state = find_invalid_history(model::tree, model::rows);
                constexpr int initial_set = find_initial_set_problem(model::tree);
                if constexpr (history_state >= 0)
                    return type_list<error::invalid_history_state<typename model::template tag_at<history_state>>>{};
                else if constexpr (initial_set >= 0)
                    return type_list<
                        error::initial_states_not_orthogonal<typename model::template tag_at<initial_set>>>{};
                else
                    return type_list<>{};
            }
        }
    }
}

template <class Chart>
constexpr auto check_orthogonality() {
    using model = chart_model<Chart>;
    constexpr int row = find_orthogonal_transition(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<row_error<
            Chart, row, error::transition_between_orthogonal_regions<typename R::source, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_local_targets() {
    using model = chart_model<Chart>;
    constexpr int row = find_misplaced_local(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<
            row_error<Chart, row, error::local_target_outside_source<typename R::source, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_several_targets() {
    using model = chart_model<Chart>;
    constexpr int row = find_targets_not_orthogonal(model::tree, model::rows);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        // clang-format off
        using named = decltype([]<class... S>(type_list<S...>) { return error::target_states<S...>{}; }(typename R::targets{}));
        // clang-format on
        return type_list<row_error<Chart, row, error::targets_not_orthogonal<typename R::source, named>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_deferrals() {
    using model = chart_model<Chart>;
    constexpr int row = find_invalid_deferral(model::rows, position_in<any_event, typename model::events>::value);
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        return type_list<
            row_error<Chart, row, error::invalid_deferral<typename R::source, typename trigger_type<R>::type>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_initial_actions() {
    using model = chart_model<Chart>;
    constexpr int row = find_misplaced_initial_action(model::tree, model::rows);
    if constexpr (row >= 0)
        return type_list<row_error<
            Chart, row,
            error::initial_action_without_initial_transition<typename model::template row_at<row>::source>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_event_families() {
    using events = typename chart_model<Chart>::events;
    constexpr auto const& nearest = event_families<events>::nearest;
    constexpr int tangled = [] {
        for (std::size_t t = 0; t < nearest.size(); ++t)
            if (nearest[t] == -2) return static_cast<int>(t);
        return -1;
    }();
    if constexpr (tangled >= 0)
        return type_list<error::event_in_two_families<at<static_cast<std::size_t>(tangled), events>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_determinism() {
    using model = chart_model<Chart>;
    constexpr determinism_findings found = find_nondeterminism(model::tree, model::rows);
    constexpr row_pair conflict = found.conflict;
    constexpr row_pair shadowed = found.shadowed;
    if constexpr (conflict.found()) {
        using R = typename model::template row_at<conflict.second>;
        return type_list<
            row_error<Chart, conflict.second,
                      error::conflicting_transitions<typename R::source, typename trigger_type<R>::type>>>{};
    } else if constexpr (shadowed.found()) {
        using R = typename model::template row_at<shadowed.second>;
        return type_list<row_error<
            Chart, shadowed.second,
            error::shadowed_transition<typename R::source, typename trigger_type<R>::type, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_done_events() {
    using model = chart_model<Chart>;
    constexpr done_finding found = [] {
        if constexpr (takes_done_event(typename model::events{}))
            return find_dead_done_row(model::tree, model::rows,
                                      completed_states<typename model::tags>(typename model::events{}));
        else
            return done_finding{};  // most charts: nothing to look at
    }();
    if constexpr (found.fault == done_fault::none) {
        return type_list<>{};
    } else {
        using R = typename model::template row_at<found.row>;
        using S = typename completed_state<typename trigger_type<R>::type>::type;
        if constexpr (found.fault == done_fault::not_in_chart)
            return type_list<row_error<Chart, found.row, error::done_of_state_not_in_chart<S>>>{};
        else if constexpr (found.fault == done_fault::never_raised)
            return type_list<row_error<Chart, found.row, error::done_never_raised<S>>>{};
        else
            return type_list<row_error<Chart, found.row, error::done_source_inactive<typename R::source, S>>>{};
    }
}

template <class Chart>
inline constexpr auto liveness_of = find_dead_transitions(chart_model<Chart>::tree, chart_model<Chart>::rows,
                                                          chart_model<Chart>::order);

template <class Chart>
constexpr auto check_dead_transitions() {
    using model = chart_model<Chart>;
    constexpr int row = liveness_of<Chart>.first_dead;
    if constexpr (row >= 0) {
        using R = typename model::template row_at<row>;
        constexpr int outer = liveness_of<Chart>.outer;
        if constexpr (outer >= 0)
            return type_list<row_error<
                Chart, row,
                error::dead_transition_behind_outer<typename R::source, typename trigger_type<R>::type,
                                                    typename R::target, typename model::template tag_at<outer>>>>{};
        else
            return type_list<row_error<
                Chart, row,
                error::dead_transition<typename R::source, typename trigger_type<R>::type, typename R::target>>>{};
    } else {
        return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_reachability() {
    using model = chart_model<Chart>;
    constexpr auto const& dead = liveness_of<Chart>.dead;
    constexpr auto reach = reachable_states(model::tree, model::rows, dead);
    constexpr int unreachable = find_unreachable(model::tree, reach);
    if constexpr (unreachable >= 0) {
        return type_list<error::unreachable_state<typename model::template tag_at<unreachable>>>{};
    } else {
        constexpr int dead_end = find_dead_end(model::tree, model::rows, dead, reach);
        if constexpr (dead_end >= 0)
            return type_list<error::dead_end_state<typename model::template tag_at<dead_end>>>{};
        else
            return type_list<>{};
    }
}

template <class Chart>
constexpr auto check_livelock() {
    using model = chart_model<Chart>;
    constexpr std::size_t edges = count_eventless_edges(model::tree, model::rows, model::order);
    constexpr int source = find_eventless_cycle<edges>(model::tree, model::rows, model::order);
    if constexpr (source >= 0)
        return type_list<error::eventless_livelock<typename model::template tag_at<source>>>{};
    else
        return type_list<>{};
}

template <class Chart>
constexpr auto check_signatures() {
    using model = chart_model<Chart>;
    using context = typename Chart::context_type;
    constexpr int row = first_signature_error<context>(typename Chart::row_types{});
    if constexpr (row >= 0)
        return type_list<row_error<Chart, row, signature_error<context, typename model::template row_at<row>>>>{};
    else
        return type_list<>{};
}

// bsc::in<S> in a guard: S must be a state of the chart, and not a history state (never
// active). The first such S of each row's guard, as its error; nothing for a chart without
// bsc::in, which is most.
template <class Model, class S>
constexpr auto in_state_errors() {
    constexpr int s = state_index<S, typename Model::tags>::value;
    if constexpr (s < 0)
        return type_list<error::in_of_state_not_in_chart<S>>{};
    else if constexpr (Model::tree.kinds[static_cast<std::size_t>(s)] == kind::history)
        return type_list<error::in_of_history_state<S>>{};
    else
        return type_list<>{};
}
template <class Model, class Row>
constexpr auto in_guard_errors(Row const*) {
    if constexpr (row_tests_configuration<Row>) {
        using states = typename in_states<std::remove_cv_t<decltype(Row::guard)>>::type;
        // clang-format off
        return []<class... S>(type_list<S...>) {
            return concat_t<decltype(in_state_errors<Model, S>())...>{};
        }(states{});
        // clang-format on
    } else {
        return type_list<>{};
    }
}
template <class Model, class... Rows>
constexpr int first_in_guard_error(type_list<Rows...>) {
    constexpr bool bad[] = {(decltype(in_guard_errors<Model>(static_cast<Rows const*>(nullptr)))::size > 0)..., false};
    for (std::size_t i = 0; i < sizeof...(Rows); ++i)
        if (bad[i]) return static_cast<int>(i);
    return -1;
}

template <class Chart>
constexpr auto check_in_guards() {
    using model = chart_model<Chart>;
    if constexpr (!any_row_tests_configuration<typename Chart::row_types>) {
        return type_list<>{};
    } else {
        constexpr int row = first_in_guard_error<model>(typename Chart::row_types{});
        if constexpr (row >= 0) {
            using errors = decltype(in_guard_errors<model>(
                static_cast<typename model::template row_at<row> const*>(nullptr)));
            return type_list<row_error<Chart, row, at<0, errors>>>{};
        } else {
            return type_list<>{};
        }
    }
}

// The errors of a chart, as a type_list; empty for a well-formed chart.
template <class Chart>
constexpr auto check_chart() {
    if constexpr (!structure_valid<Chart>())
        return check_structure<Chart>();
    else
        // Each check runs, so one build reports every kind of problem it finds.
        return concat_t<decltype(check_orthogonality<Chart>()), decltype(check_local_targets<Chart>()),
                        decltype(check_several_targets<Chart>()), decltype(check_initial_actions<Chart>()),
                        decltype(check_deferrals<Chart>()), decltype(check_event_families<Chart>()),
                        decltype(check_determinism<Chart>()), decltype(check_done_events<Chart>()),
                        decltype(check_dead_transitions<Chart>()), decltype(check_reachability<Chart>()),
                        decltype(check_livelock<Chart>()), decltype(check_signatures<Chart>()),
                        decltype(check_in_guards<Chart>())>{};
}

}  // namespace bsc::detail
