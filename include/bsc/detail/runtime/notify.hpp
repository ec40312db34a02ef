#pragma once
// The calls a machine makes to its observer, by state and row number: each hook is called
// only if the observer has it, and a machine without observer generates nothing.

#include <type_traits>

#include <bsc/detail/guard_label.hpp>
#include <bsc/detail/model/chart_model.hpp>
#include <bsc/observer.hpp>

namespace bsc::detail {

template <class Model, class Observer>
struct notify {
    template <int S>
    using tag = state_tag<typename Model::template tag_at<S>>;

    template <int Row>
    using source_tag = state_tag<typename Model::template row_at<Row>::source>;
    template <int Row, class Target = typename Model::template row_at<Row>::target>
    using target_tag = std::conditional_t<std::is_same_v<Target, no_target>, state_tag<internal>, state_tag<Target>>;

    template <int S>
    static constexpr bool observes_entry_of = S > 0 && observes_entry<Observer, tag<S>>;
    template <int S>
    static constexpr bool observes_exit_of = S > 0 && observes_exit<Observer, tag<S>>;
    // The event on_transition receives for row Row taken on E: a timeout row's delay.
    template <int Row, class E>
    using reported_event = std::conditional_t<is_timeout_row<typename Model::template row_at<Row>>, timeout_elapsed, E>;
    template <int Row, class E>
    static constexpr bool observes_row =
        observes_transition<Observer, source_tag<Row>, target_tag<Row>, reported_event<Row, E>> ||
        observes_rows<Observer> || (Model::rows.guarded[Row] && observes_guards<Observer>) ||
        (Model::rows.defers[Row] && observes_deferrals<Observer, source_tag<Row>, E>);

    // After state S's entry actions.
    template <int S>
    static constexpr void entered(Observer& o) {
        if constexpr (observes_entry_of<S>) o.on_entry(tag<S>{});
    }
    // After state S's exit actions.
    template <int S>
    static constexpr void exited(Observer& o) {
        if constexpr (observes_exit_of<S>) o.on_exit(tag<S>{});
    }
    // Before the action of transition Row (the row object `row`), taken on event e; a timeout
    // row reports timeout_elapsed with its delay instead (reported_event).
    template <int Row, class RowObject, class E>
    static constexpr void transition(Observer& o, RowObject const& row, E const& e) {
        using reported = reported_event<Row, E>;
        if constexpr (Model::rows.guarded[Row] && observes_guards<Observer>) o.on_guard(guard_label(row.guard));
        if constexpr (Model::rows.defers[Row] && observes_deferrals<Observer, source_tag<Row>, E>)
            o.on_defer(source_tag<Row>{}, e);
        if constexpr (observes_transition<Observer, source_tag<Row>, target_tag<Row>, reported>) {
            if constexpr (std::is_same_v<reported, timeout_elapsed>)
                o.on_transition(source_tag<Row>{}, target_tag<Row>{}, timeout_elapsed{row.trigger_value.delay});
            else
                o.on_transition(source_tag<Row>{}, target_tag<Row>{}, e);
        }
        if constexpr (observes_rows<Observer>) o.on_row(Row);
    }

    // A dispatch of e begins; a cycle at time now begins; that cycle ends.
    template <class E>
    static constexpr void dispatching(Observer& o, E const& e) {
        if constexpr (observes_dispatch<Observer, E>) o.on_dispatch(e);
    }
    static constexpr void cycle_begins(Observer& o, duration now) {
        if constexpr (observes_cycles<Observer>) o.on_cycle(now);
    }
    static constexpr void cycle_ends(Observer& o) {
        if constexpr (observes_cycle_ends<Observer>) o.on_cycle_end();
    }
};

}  // namespace bsc::detail
