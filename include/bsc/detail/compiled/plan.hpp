#pragma once
// Compile-time dispatch plans: for a trigger, which states lead to a transition and, for each
// basic state, which transitions are its candidates in the chart's priority order (deepest
// source first, or outermost first; then declaration order). The compiled machine expands these into switches and straight-line
// code; nothing here exists at run time.

#include <array>

#include <bsc/detail/model/layout.hpp>
#include <bsc/priority.hpp>

namespace bsc::detail {

template <class Model>
struct plan : chart_layout<Model> {
    using layout = chart_layout<Model>;
    using layout::tree;
    using layout::rows;
    using layout::N;
    using layout::R;
    using layout::is_transition_on;
    using layout::components;
    using layout::has_parallel;
    using layout::conflict;
    using layout::from_source;
    using layout::from_source_begin;

    // The transitions on each event, in declaration order, for a chart without event families
    // (where a row takes the events of its trigger only): those on event position t are
    // on_event[on_event_begin[t]] to on_event[on_event_begin[t + 1]] (exclusive). Built once,
    // so that each trigger's list is read, not found by a scan of every row.
    static constexpr int event_count = static_cast<int>(Model::events::size);
    static constexpr auto on_event_begin = [] {
        std::array<int, static_cast<std::size_t>(event_count) + 1> begin{};
        for (int r = 0; r < R; ++r)
            if (rows.kinds[static_cast<std::size_t>(r)] == row_kind::transition &&
                rows.trigger[static_cast<std::size_t>(r)] >= 0)
                ++begin[static_cast<std::size_t>(rows.trigger[static_cast<std::size_t>(r)]) + 1];
        for (std::size_t t = 0; t < static_cast<std::size_t>(event_count); ++t) begin[t + 1] += begin[t];
        return begin;
    }();
    static constexpr auto on_event = [] {
        std::array<int, static_cast<std::size_t>(on_event_begin[static_cast<std::size_t>(event_count)])> out{};
        auto next = on_event_begin;
        for (int r = 0; r < R; ++r)
            if (rows.kinds[static_cast<std::size_t>(r)] == row_kind::transition &&
                rows.trigger[static_cast<std::size_t>(r)] >= 0)
                out[static_cast<std::size_t>(
                    next[static_cast<std::size_t>(rows.trigger[static_cast<std::size_t>(r)])]++)] = r;
        return out;
    }();
    static constexpr bool indexed_by_event(int trigger) { return !Model::has_families && trigger >= 0; }

    static constexpr int transition_count(int trigger) {
        if (indexed_by_event(trigger))
            return on_event_begin[static_cast<std::size_t>(trigger) + 1] -
                   on_event_begin[static_cast<std::size_t>(trigger)];
        int n = 0;
        for (int r = 0; r < R; ++r) n += is_transition_on(r, trigger) ? 1 : 0;
        return n;
    }

    // The transitions on a trigger, in declaration order; the selection buffer stores positions
    // here. What follows reads this list.
    template <int Trigger>
    static constexpr auto transitions = [] {
        std::array<int, static_cast<std::size_t>(transition_count(Trigger))> out{};
        std::size_t n = 0;
        if constexpr (indexed_by_event(Trigger)) {
            for (int i = on_event_begin[static_cast<std::size_t>(Trigger)];
                 i < on_event_begin[static_cast<std::size_t>(Trigger) + 1]; ++i)
                out[n++] = on_event[static_cast<std::size_t>(i)];
        } else {
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, Trigger)) out[n++] = r;
        }
        return out;
    }();

    // State s needs visiting for the trigger: a transition on it leaves s, an ancestor or a
    // descendant. (Asked of the states a dispatch walks through, each asking reads the trigger's
    // transitions: no array of every state per trigger, which made the compile time quadratic.)
    template <int Trigger>
    static constexpr bool relevant(int s) {
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (tree.contains(src, s) || tree.contains(s, src)) return true;
        }
        return false;
    }

    // No transition on the trigger leaves a state strictly below s: every state below s takes
    // it by the rows of s and its ancestors only.
    template <int Trigger>
    static constexpr bool no_source_below(int s) {
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (src != s && tree.contains(s, src)) return false;
        }
        return true;
    }

    // The children of composite s toward the sources of the trigger's transitions below it,
    // in document order, each once; or `every`, if a source is s or above it (every child is
    // then relevant).
    template <int Trigger>
    struct children_found {
        std::array<int, transitions<Trigger>.size()> child{};
        std::size_t count = 0;
        bool every = false;
    };
    template <int Trigger>
    static constexpr children_found<Trigger> children_toward_sources(int s) {
        children_found<Trigger> found{};
        for (int const r : transitions<Trigger>) {
            int const src = rows.source[static_cast<std::size_t>(r)];
            if (tree.contains(src, s)) {
                found.every = true;
                return found;
            }
            if (!tree.contains(s, src)) continue;
            int const c = tree.child_toward(s, src);
            bool seen = false;
            for (std::size_t j = 0; j < found.count && !seen; ++j) seen = found.child[j] == c;
            if (seen) continue;
            std::size_t i = found.count++;  // insertion in document order
            for (; i > 0 && found.child[i - 1] > c; --i) found.child[i] = found.child[i - 1];
            found.child[i] = c;
        }
        return found;
    }

    // The children of composite S that are relevant to the trigger, in document order: the
    // only ones dispatch on the trigger compares S's byte with, so each trigger instantiates
    // code along its own paths only (linear in the transitions, not in states x triggers).
    template <int Trigger, int S>
    static constexpr auto relevant_children = [] {
        constexpr auto found = children_toward_sources<Trigger>(S);
        if constexpr (found.every) {
            return layout::template children<S>;
        } else {
            std::array<int, found.count> out{};
            for (std::size_t i = 0; i < found.count; ++i) out[i] = found.child[i];
            return out;
        }
    }();

    // Calls f(a) for each state a from `leaf` up to `top`, in the order their rows are tried:
    // `leaf` first under child-first priority, `top` first under parent-first (bsc/priority.hpp).
    // Fixed here, so that either order is the same straight-line code.
    template <class F>
    static constexpr void for_each_tried(int leaf, int top, F&& f) {
        if constexpr (Model::order == priority::child_first) {
            for (int a = leaf;; a = tree.parent[static_cast<std::size_t>(a)]) {
                f(static_cast<std::size_t>(a));
                if (a == top) break;
            }
        } else {
            int const levels = tree.depth[static_cast<std::size_t>(leaf)] - tree.depth[static_cast<std::size_t>(top)];
            for (int k = levels; k >= 0; --k) {
                int a = leaf;
                for (int i = 0; i < k; ++i) a = tree.parent[static_cast<std::size_t>(a)];
                f(static_cast<std::size_t>(a));
            }
        }
    }

    // The rows on `trigger` a state in `leaf` tries, up to `top`, in priority order.
    static constexpr int candidate_count(int leaf, int top, int trigger) {
        int n = 0;
        for_each_tried(leaf, top, [&](std::size_t a) {
            for (int i = from_source_begin[a]; i < from_source_begin[a + 1]; ++i)
                n += is_transition_on(from_source[static_cast<std::size_t>(i)], trigger) ? 1 : 0;
        });
        return n;
    }
    template <std::size_t Count>
    static constexpr std::array<int, Count> candidate_rows(int leaf, int top, int trigger) {
        std::array<int, Count> out{};
        std::size_t n = 0;
        for_each_tried(leaf, top, [&](std::size_t a) {
            for (int i = from_source_begin[a]; i < from_source_begin[a + 1]; ++i)
                if (is_transition_on(from_source[static_cast<std::size_t>(i)], trigger))
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        });
        return out;
    }

    // The candidates of basic state Leaf on the trigger: its rows and its ancestors'.
    template <int Leaf, int Trigger>
    static constexpr auto candidates =
        candidate_rows<static_cast<std::size_t>(candidate_count(Leaf, 0, Trigger))>(Leaf, 0, Trigger);

    // The condition-driven rows a component's turn tries from its active frontier up to the
    // component itself ([BSC]: one transition per component per cycle).
    template <int Frontier, int Component>
    static constexpr auto component_candidates =
        candidate_rows<static_cast<std::size_t>(candidate_count(Frontier, Component, any_condition))>(Frontier,
                                                                                                      Component,
                                                                                                      any_condition);

    // The timeout rows of the source of timeout row `row` declared after it, in declaration
    // order: those it competes with by due time when its condition holds (the earlier ones did
    // not hold, or it would not be tried). Empty for a state with one timeout row.
    static constexpr int later_timeout_count(int row) {
        int const source = rows.source[static_cast<std::size_t>(row)];
        int n = 0;
        for (int i = from_source_begin[static_cast<std::size_t>(source)];
             i < from_source_begin[static_cast<std::size_t>(source) + 1]; ++i)
            n += from_source[static_cast<std::size_t>(i)] > row &&
                 layout::is_timeout_row(from_source[static_cast<std::size_t>(i)]);
        return n;
    }
    template <int Row>
    static constexpr auto later_timeouts = [] {
        std::array<int, static_cast<std::size_t>(layout::is_timeout_row(Row) ? later_timeout_count(Row) : 0)> out{};
        std::size_t n = 0;
        if constexpr (out.size() > 0) {
            constexpr int source = rows.source[static_cast<std::size_t>(Row)];
            for (int i = from_source_begin[static_cast<std::size_t>(source)];
                 i < from_source_begin[static_cast<std::size_t>(source) + 1]; ++i)
                if (from_source[static_cast<std::size_t>(i)] > Row &&
                    layout::is_timeout_row(from_source[static_cast<std::size_t>(i)]))
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        }
        return out;
    }();

    template <int Trigger>
    static constexpr int position_of(int row) {
        for (std::size_t i = 0; i < transitions<Trigger>.size(); ++i)
            if (transitions<Trigger>[i] == row) return static_cast<int>(i);
        return -1;
    }

    static constexpr int index_in_components(int s) {
        for (std::size_t i = 0; i < components.size(); ++i)
            if (components[i] == s) return static_cast<int>(i);
        return -1;
    }

    // The component a state lies in, as an index into components. Within a component at most
    // one transition is selected per microstep: its basic states that lie below no further
    // parallel state are mutually exclusive.
    static constexpr auto component_of = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int s = 0; s < N; ++s) {
            out[static_cast<std::size_t>(s)] = 0;
            for (int a = s; a > 1; a = tree.parent[static_cast<std::size_t>(a)]) {
                int const i = index_in_components(a);
                if (i >= 0) {
                    out[static_cast<std::size_t>(s)] = i;
                    break;
                }
            }
        }
        return out;
    }();

    template <int Trigger>
    static constexpr int component_row_count(int component) {
        int n = 0;
        for (int const r : transitions<Trigger>)
            n += component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])] == component;
        return n;
    }
    // The transitions on a trigger whose source lies in component C, in declaration order.
    template <int Trigger, int C>
    static constexpr auto component_rows = [] {
        std::array<int, static_cast<std::size_t>(component_row_count<Trigger>(C))> out{};
        std::size_t n = 0;
        for (int const r : transitions<Trigger>)
            if (component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])] == C) out[n++] = r;
        return out;
    }();
    // What a region-local selection records for a row: 1 + its position in its component's rows.
    template <int Trigger, int Row>
    static constexpr int component_code = [] {
        constexpr auto const& list = component_rows<Trigger, component_of[static_cast<std::size_t>(rows.source[Row])]>;
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i] == Row) return static_cast<int>(i) + 1;
        return 0;
    }();

    // A trigger is region-local when what SCXML's conflict resolution does at run time is known
    // at compile time to keep every selected transition: no transition on it leaves a state that
    // contains a parallel state (so each is selected by one basic state at most), and no two
    // transitions from different components have nesting domains (so none preempts another).
    // Its microstep then records one row per component and fires the components in document
    // order, with no run-time conflict check.
    template <int Trigger>
    static constexpr bool region_local = [] {
        if (!has_parallel) return false;  // nothing to resolve: every transition fires where selected
        constexpr auto const& on_trigger = transitions<Trigger>;
        for (std::size_t i = 0; i < on_trigger.size(); ++i) {
            int const r = on_trigger[i];
            int const src = rows.source[static_cast<std::size_t>(r)];
            for (int s = src; s < tree.end[static_cast<std::size_t>(src)]; ++s)
                if (tree.kinds[static_cast<std::size_t>(s)] == kind::parallel) return false;
            if (component_row_count<Trigger>(component_of[static_cast<std::size_t>(src)]) > 254) return false;
            for (std::size_t j = i + 1; j < on_trigger.size(); ++j) {
                int const r2 = on_trigger[j];
                if (component_of[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r2)])] !=
                        component_of[static_cast<std::size_t>(src)] &&
                    conflict(r, r2))
                    return false;
            }
        }
        return true;
    }();

    // A region-local trigger whose transitions can fire as they are selected, with the same
    // effects as selecting all first: none is guarded (so no selection can depend on another
    // component's action), and no state that one of them exits or enters has an entry or exit row
    // (so the only visible effects are the transition actions, which run in document order
    // either way). Each component's transition changes only the bytes inside its own domain.
    template <int Trigger>
    static constexpr bool fires_at_selection = [] {
        if (!region_local<Trigger>) return false;
        for (int const r : transitions<Trigger>) {
            if (rows.guarded[static_cast<std::size_t>(r)]) return false;
            int const d = rows.domain[static_cast<std::size_t>(r)];
            if (d < 0) continue;  // targetless: exits and enters nothing
            for (int r2 = 0; r2 < R; ++r2) {
                auto const k = rows.kinds[static_cast<std::size_t>(r2)];
                int const s = rows.source[static_cast<std::size_t>(r2)];
                if (k != row_kind::transition && s != d && tree.contains(d, s)) return false;
            }
        }
        return true;
    }();

    // The components in which a transition on the trigger can be selected under a parallel state.
    template <int Trigger>
    static constexpr int selecting_component_count() {
        int n = 0;
        for (std::size_t c = 1; c < components.size(); ++c) n += component_row_count<Trigger>(static_cast<int>(c)) > 0;
        return n;
    }
    template <int Trigger>
    static constexpr auto selecting_components = [] {
        std::array<int, static_cast<std::size_t>(selecting_component_count<Trigger>())> out{};
        std::size_t n = 0;
        for (std::size_t c = 1; c < components.size(); ++c)
            if (component_row_count<Trigger>(static_cast<int>(c)) > 0) out[n++] = static_cast<int>(c);
        return out;
    }();
};

}  // namespace bsc::detail
