#pragma once
// What every back end lays out the same way, computed once from the chart model: the
// components of a BSC cycle, the timeout slots, the children of each state, the bytes of the
// initial configuration, the transitions in declaration order and the entry and exit rows of
// each state. Both back ends number these alike because both read them from here.

#include <array>
#include <cstddef>
#include <cstdint>

#include <bsc/detail/model/chart_model.hpp>

namespace bsc::detail {

template <class Model>
struct chart_layout {
    static constexpr auto const& tree = Model::tree;
    using ordinal_type = typename Model::ordinal_type;
    static constexpr auto const& rows = Model::rows;
    static constexpr int N = Model::N;
    static constexpr int R = Model::R;
    static constexpr int root = 1;  // state 0 is the implicit top above the chart's root

    // Whether row `row` is a transition on `trigger`: an event's position, eventless_id, or
    // any_condition (eventless or timeout).
    static constexpr bool is_transition_on(int row, int trigger) {
        auto const r = static_cast<std::size_t>(row);
        if (rows.kinds[r] != row_kind::transition) return false;
        if (trigger == any_condition) return rows.trigger[r] < 0;
        // A row on a family of the trigger's event takes it too (detail/model/event_families.hpp).
        if constexpr (Model::has_families)
            return rows.takes(rows.trigger[r], trigger);
        else
            return rows.trigger[r] == trigger;
    }

    static constexpr bool has_trigger(int trigger) {
        for (int r = 0; r < R; ++r)
            if (is_transition_on(r, trigger)) return true;
        return false;
    }

    static constexpr bool is_timeout_row(int row) {
        auto const r = static_cast<std::size_t>(row);
        return rows.kinds[r] == row_kind::transition && rows.trigger[r] <= timeout_trigger_id(0);
    }

    // The children of state S, in document order.
    template <int S>
    static constexpr auto children = [] {
        std::array<int, static_cast<std::size_t>(tree.child_count[static_cast<std::size_t>(S)])> out{};
        std::size_t n = 0;
        for (int c = tree.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = tree.next_sibling[static_cast<std::size_t>(c)])
            out[n++] = c;
        return out;
    }();

    // BSC components: the root and every child of a parallel state, in document order. In a
    // cycle each fires at most one condition-driven transition, chosen from the states between
    // its active frontier (a basic state, or a parallel state whose children are components of
    // their own) and its root.
    static constexpr int component_count() {
        int n = 1;
        for (int s = 2; s < N; ++s)
            n += tree.kinds[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] == kind::parallel;
        return n;
    }
    static constexpr auto components = [] {
        std::array<int, static_cast<std::size_t>(component_count())> out{};
        std::size_t n = 0;
        out[n++] = root;
        for (int s = 2; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] == kind::parallel)
                out[n++] = s;
        return out;
    }();

    // Every timeout row has a slot for the time from which its delay counts: the entry of its
    // source, or the cycle it last fired in for an internal timeout (which re-arms itself).
    // Slots are numbered by source state in document order, then by row, so the slots of one
    // state are contiguous: timeout_slot[s] is the first (-1 if none), timeout_slot_count[s]
    // how many; row_timeout_slot[r] is row r's (-1 for other rows).
    static constexpr auto timeout_slot_count = [] {
        std::array<int, static_cast<std::size_t>(N)> count{};
        for (int r = 0; r < R; ++r)
            if (is_timeout_row(r)) ++count[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])];
        return count;
    }();
    static constexpr auto timeout_slot = [] {
        std::array<int, static_cast<std::size_t>(N)> first{};
        int n = 0;
        for (std::size_t s = 0; s < first.size(); ++s) {
            first[s] = timeout_slot_count[s] > 0 ? n : -1;
            n += timeout_slot_count[s];
        }
        return first;
    }();
    static constexpr int timeout_slots = [] {
        int n = 0;
        for (int count : timeout_slot_count) n += count;
        return n;
    }();
    static constexpr auto row_timeout_slot = [] {
        std::array<int, static_cast<std::size_t>(R)> slot{};
        std::array<int, static_cast<std::size_t>(N)> used{};
        for (int r = 0; r < R; ++r) {
            auto const source = static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)]);
            slot[static_cast<std::size_t>(r)] = is_timeout_row(r) ? timeout_slot[source] + used[source]++ : -1;
        }
        return slot;
    }();
    // The state whose entry arms a slot.
    static constexpr auto timeout_slot_state = [] {
        std::array<int, static_cast<std::size_t>(timeout_slots)> state{};
        for (int s = 0; s < N; ++s)
            for (int k = 0; k < timeout_slot_count[static_cast<std::size_t>(s)]; ++k)
                state[static_cast<std::size_t>(timeout_slot[static_cast<std::size_t>(s)] + k)] = s;
        return state;
    }();
    // Whether some state has two timeout rows or more: only their timeouts compete by due time
    // (the one that came due first fires; docs/semantics.md, "Timers").
    static constexpr bool has_competing_timeouts = [] {
        for (int count : timeout_slot_count)
            if (count > 1) return true;
        return false;
    }();

    // Whether timeout row `row` competes with other timeouts of its state by due time.
    static constexpr bool competes_by_due_time(int row) {
        return has_competing_timeouts && is_timeout_row(row) &&
               timeout_slot_count[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(row)])] > 1;
    }

    // Whether timeout row `row`, when it fires, leaves its state active and so counts again from
    // that cycle: an internal timeout (no domain), or a local one (its domain is its state).
    static constexpr bool rearms(int row) {
        auto const r = static_cast<std::size_t>(row);
        return is_timeout_row(row) && (rows.domain[r] < 0 || rows.domain[r] == rows.source[r]);
    }

    // The rows of each state, in declaration order, all kinds: those of state s are
    // from_source[from_source_begin[s]] to from_source[from_source_begin[s + 1]] (exclusive).
    // Built once, so that what is asked per state or per (state, trigger) reads that state's
    // rows and not all the chart's: the compile time stays linear in the chart.
    static constexpr auto from_source_begin = [] {
        std::array<int, static_cast<std::size_t>(N) + 1> begin{};
        for (int r = 0; r < R; ++r) ++begin[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)]) + 1];
        for (std::size_t s = 0; s < static_cast<std::size_t>(N); ++s) begin[s + 1] += begin[s];
        return begin;
    }();
    static constexpr auto from_source = [] {
        std::array<int, static_cast<std::size_t>(R)> out{};
        auto next = from_source_begin;
        for (int r = 0; r < R; ++r)
            out[static_cast<std::size_t>(next[static_cast<std::size_t>(rows.source[static_cast<std::size_t>(r)])]++)] =
                r;
        return out;
    }();

    static constexpr int count_rows(row_kind k, int state) {
        int n = 0;
        if (state < 0) {
            for (int r = 0; r < R; ++r) n += rows.kinds[static_cast<std::size_t>(r)] == k;
        } else {
            for (int i = from_source_begin[static_cast<std::size_t>(state)];
                 i < from_source_begin[static_cast<std::size_t>(state) + 1]; ++i)
                n += rows.kinds[static_cast<std::size_t>(from_source[static_cast<std::size_t>(i)])] == k;
        }
        return n;
    }

    // The rows of kind K from state S (every state if S is -1), in declaration order: the
    // entry or exit rows of a state, or all transitions.
    template <row_kind K, int S>
    static constexpr auto rows_of = [] {
        std::array<int, static_cast<std::size_t>(count_rows(K, S))> out{};
        std::size_t n = 0;
        if constexpr (S < 0) {
            for (int r = 0; r < R; ++r)
                if (rows.kinds[static_cast<std::size_t>(r)] == K) out[n++] = r;
        } else {
            for (int i = from_source_begin[S]; i < from_source_begin[S + 1]; ++i)
                if (rows.kinds[static_cast<std::size_t>(from_source[static_cast<std::size_t>(i)])] == K)
                    out[n++] = from_source[static_cast<std::size_t>(i)];
        }
        return out;
    }();
    static constexpr auto const& transition_rows = rows_of<row_kind::transition, -1>;

    // How many basic states below s can be active at once: the most transitions one event
    // can select there.
    static constexpr int max_active_leaves(int s = root) {
        auto const i = static_cast<std::size_t>(s);
        if (tree.is_leaf(s)) return 1;
        int result = 0;
        for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)]) {
            int const m = max_active_leaves(c);
            result = tree.kinds[i] == kind::parallel ? result + m : (m > result ? m : result);
        }
        return result;
    }

    static constexpr bool has_parallel = [] {
        for (int s = 0; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::parallel) return true;
        return false;
    }();

    // history_child[s]: the first history pseudo-state among the children of composite s, -1
    // if none; deep_history_child[s]: whether one of them is deep.
    static constexpr auto history_child = [] {
        std::array<int, static_cast<std::size_t>(N)> out{};
        for (int s = 0; s < N; ++s) {
            out[static_cast<std::size_t>(s)] = -1;
            for (int c = tree.first_child[static_cast<std::size_t>(s)]; c >= 0;
                 c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (tree.kinds[static_cast<std::size_t>(c)] == kind::history && out[static_cast<std::size_t>(s)] < 0)
                    out[static_cast<std::size_t>(s)] = c;
        }
        return out;
    }();
    static constexpr auto deep_history_child = [] {
        std::array<bool, static_cast<std::size_t>(N)> out{};
        for (int s = 1; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::history &&
                tree.hist[static_cast<std::size_t>(s)] == history::deep)
                out[static_cast<std::size_t>(tree.parent[static_cast<std::size_t>(s)])] = true;
        return out;
    }();
    static constexpr bool has_history_states = [] {
        for (int s = 0; s < N; ++s)
            if (tree.kinds[static_cast<std::size_t>(s)] == kind::history) return true;
        return false;
    }();

    // The initial configuration: every composite's byte at its initial child; the byte of a
    // composite with history states at the first of them, which is never active: the mark of a
    // composite that has never been active, whose history states take their defaults.
    static constexpr auto initial_bytes = [] {
        std::array<ordinal_type, static_cast<std::size_t>(tree.slots)> bytes{};
        for (std::size_t s = 0; s < static_cast<std::size_t>(N); ++s)
            if (tree.slot[s] >= 0)
                bytes[static_cast<std::size_t>(tree.slot[s])] = static_cast<ordinal_type>(
                    tree.ordinal[static_cast<std::size_t>(history_child[s] >= 0 ? history_child[s] : tree.initial[s])]);
        return bytes;
    }();
    // Whether composite s's byte says it has never been active (it selects a history state).
    template <int S>
    static constexpr bool never_active_byte(int byte) {
        bool is_history = false;
        for (int c = tree.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = tree.next_sibling[static_cast<std::size_t>(c)])
            is_history = is_history || (tree.kinds[static_cast<std::size_t>(c)] == kind::history &&
                                        tree.ordinal[static_cast<std::size_t>(c)] == byte);
        return is_history;
    }

    // Which children of the root are final, by ordinal: the machine halts when its root's
    // byte selects one. Empty unless the root is a composite with a final child.
    static constexpr bool can_halt = [] {
        if (tree.kinds[root] != kind::composite) return false;
        for (int c = tree.first_child[root]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
            if (tree.kinds[static_cast<std::size_t>(c)] == kind::final_state) return true;
        return false;
    }();
    static constexpr auto final_root_children = [] {
        std::array<bool, can_halt ? static_cast<std::size_t>(tree.child_count[root]) : 0> out{};
        if constexpr (can_halt)
            for (int c = tree.first_child[root]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                out[static_cast<std::size_t>(tree.ordinal[static_cast<std::size_t>(c)])] =
                    tree.kinds[static_cast<std::size_t>(c)] == kind::final_state;
        return out;
    }();

    // Two selected transitions conflict when their exit sets meet, i.e. when their domains nest.
    static constexpr bool conflict(int r1, int r2) {
        int const d1 = rows.domain[static_cast<std::size_t>(r1)], d2 = rows.domain[static_cast<std::size_t>(r2)];
        if (d1 < 0 || d2 < 0) return false;
        return tree.contains(d1, d2) || tree.contains(d2, d1);
    }
    // Of two conflicting transitions, the later-selected one preempts the earlier when its
    // source lies below the earlier one's (SCXML's removeConflictingTransitions).
    static constexpr bool preempts(int later, int earlier) {
        return tree.is_proper_ancestor(rows.source[static_cast<std::size_t>(earlier)],
                                       rows.source[static_cast<std::size_t>(later)]);
    }
};

}  // namespace bsc::detail
