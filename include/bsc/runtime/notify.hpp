#pragma once
// The calls a machine makes to its observer, by state and row number: each hook is called
// only if the observer has it, and a machine without observer generates nothing.

#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/dsl/guard.hpp>
#include <bsc/model/chart_model.hpp>
#include <bsc/observer.hpp>

namespace bsc::detail {

// Whether a row defers its event (`/ bsc::defer`).
template <class Row>
inline constexpr bool row_defers = [] {
    if constexpr (requires { Row::defers; })
        return Row::defers;
    else
        return false;
}();

// What kind of guard expression G is.
template <class G>
struct guard_kind {
    static constexpr bool fn = false, negation = false, conjunction = false, disjunction = false;
};
template <class F>
struct guard_kind<guard_fn<F>> : guard_kind<void> {
    static constexpr bool fn = true;
};
template <class G>
struct guard_kind<not_guard<G>> : guard_kind<void> {
    static constexpr bool negation = true;
};
template <class L, class R>
struct guard_kind<and_guard<L, R>> : guard_kind<void> {
    static constexpr bool conjunction = true;
};
template <class L, class R>
struct guard_kind<or_guard<L, R>> : guard_kind<void> {
    static constexpr bool disjunction = true;
};

// A guard as the exports write it (export/model.hpp, guard_expression): its name, given with
// bsc::named<"text"> or bsc::named(text, f); a composition with its unnamed parts as "guard", in
// parentheses where precedence needs them (3: a name or !, 2: &&, 1: ||). Appends to `out`;
// returns whether some part has a name.
template <class G>
bool guard_text(G const& g, std::string& out, int outer = 0);
template <class L, class R>
bool guard_text_of_pair(L const& l, R const& r, std::string_view op, int precedence, std::string& out, int outer) {
    if (outer > precedence) out += '(';
    bool const left = guard_text(l, out, precedence);
    out.append(op);
    bool const right = guard_text(r, out, precedence);
    if (outer > precedence) out += ')';
    return left || right;
}
template <class G>
bool guard_text(G const& g, std::string& out, int outer) {
    if constexpr (requires { std::string_view{g.name}; }) {
        out.append(std::string_view{g.name});
        return true;
    } else if constexpr (guard_kind<G>::fn) {
        return guard_text(g.fn, out, outer);
    } else if constexpr (guard_kind<G>::negation) {
        out += '!';
        return guard_text(g.g, out, 3);
    } else if constexpr (guard_kind<G>::conjunction) {
        return guard_text_of_pair(g.l, g.r, " && ", 2, out, outer);
    } else if constexpr (guard_kind<G>::disjunction) {
        return guard_text_of_pair(g.l, g.r, " || ", 1, out, outer);
    } else {
        out += "guard";
        return false;
    }
}

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
    using reported_event =
        std::conditional_t<is_timeout_row<typename Model::template row_at<Row>>, timeout_elapsed, E>;
    template <int Row, class E>
    static constexpr bool observes_row =
        observes_transition<Observer, source_tag<Row>, target_tag<Row>, reported_event<Row, E>> ||
        observes_rows<Observer>;

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
        using row_type = typename Model::template row_at<Row>;
        if constexpr (observes_guards<Observer>) {
            if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(row.guard)>, no_guard>) {
                std::string text;
                if (!guard_text(row.guard, text)) text = "guard";
                o.on_guard(text);
            }
        }
        if constexpr (observes_deferrals<Observer, source_tag<Row>, E>)
            if constexpr (row_defers<row_type>) o.on_defer(source_tag<Row>{}, e);
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
