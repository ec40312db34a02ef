#pragma once
// Compile-time dispatch plans: for a trigger, which states lead to a transition and, for each
// basic state, which transitions are its candidates in SCXML order (deepest source first,
// then declaration order). The compiled machine expands these into switches and straight-line
// code; nothing here exists at run time.

#include <array>

#include <bsc/detail/topology.hpp>

namespace bsc::detail {

template <class An>
struct plan {
    static constexpr auto const& topo = An::topo;
    static constexpr auto const& table = An::table;
    static constexpr int N = An::N;
    static constexpr int R = An::R;

    // `trigger` is an event's position, eventless_id, or any_condition (eventless or timeout).
    static constexpr bool is_transition_on(int row, int trigger) {
        auto const r = static_cast<std::size_t>(row);
        if (table.kinds[r] != row_kind::transition) return false;
        return trigger == any_condition ? table.trigger[r] < 0 : table.trigger[r] == trigger;
    }

    static constexpr bool has_trigger(int trigger) {
        for (int r = 0; r < R; ++r)
            if (is_transition_on(r, trigger))
                return true;
        return false;
    }

    // State s needs visiting for the trigger: a transition on it leaves s, an ancestor or a descendant.
    template <int Trigger>
    static constexpr std::array<bool, static_cast<std::size_t>(N)> relevant = [] {
        std::array<bool, static_cast<std::size_t>(N)> rel{};
        for (int r = 0; r < R; ++r) {
            if (!is_transition_on(r, Trigger))
                continue;
            int const src = table.source[static_cast<std::size_t>(r)];
            for (int s = 0; s < N; ++s)
                if (topo.contains(src, s) || topo.contains(s, src))
                    rel[static_cast<std::size_t>(s)] = true;
        }
        return rel;
    }();

    // The children of composite S that are relevant to the trigger, in document order: the
    // only ones dispatch on the trigger compares S's byte with, so each trigger instantiates
    // code along its own paths only (linear in the transitions, not in states x triggers).
    template <int Trigger, int S>
    static constexpr auto relevant_children = [] {
        constexpr auto& rel = relevant<Trigger>;
        constexpr int count = [] {
            int n = 0;
            for (int c = topo.first_child[static_cast<std::size_t>(S)]; c >= 0;
                 c = topo.next_sibling[static_cast<std::size_t>(c)])
                n += rel[static_cast<std::size_t>(c)];
            return n;
        }();
        std::array<int, static_cast<std::size_t>(count)> out{};
        std::size_t n = 0;
        for (int c = topo.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = topo.next_sibling[static_cast<std::size_t>(c)])
            if (rel[static_cast<std::size_t>(c)])
                out[n++] = c;
        return out;
    }();

    static constexpr int candidate_count(int leaf, int trigger) {
        int n = 0;
        for (int a = leaf; a >= 0; a = topo.parent[static_cast<std::size_t>(a)])
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, trigger) && table.source[static_cast<std::size_t>(r)] == a)
                    ++n;
        return n;
    }

    template <int Leaf, int Trigger>
    static constexpr auto candidates = [] {
        std::array<int, static_cast<std::size_t>(candidate_count(Leaf, Trigger))> out{};
        std::size_t n = 0;
        for (int a = Leaf; a >= 0; a = topo.parent[static_cast<std::size_t>(a)])
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, Trigger) && table.source[static_cast<std::size_t>(r)] == a)
                    out[n++] = r;
        return out;
    }();

    // BSC components: the root and every child of a parallel state, in document order. In a
    // cycle each fires at most one condition-driven transition, chosen from the states between
    // its active frontier (a basic state, or a parallel state whose children are components of
    // their own) and its root.
    static constexpr int component_count() {
        int n = 1;
        for (int s = 2; s < N; ++s)
            n += topo.kinds[static_cast<std::size_t>(topo.parent[static_cast<std::size_t>(s)])] == kind::parallel;
        return n;
    }
    static constexpr auto components = [] {
        std::array<int, static_cast<std::size_t>(component_count())> out{};
        std::size_t n = 0;
        out[n++] = 1;
        for (int s = 2; s < N; ++s)
            if (topo.kinds[static_cast<std::size_t>(topo.parent[static_cast<std::size_t>(s)])] == kind::parallel)
                out[n++] = s;
        return out;
    }();

    static constexpr int component_candidate_count(int frontier, int component) {
        int n = 0;
        for (int a = frontier;; a = topo.parent[static_cast<std::size_t>(a)]) {
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, any_condition) && table.source[static_cast<std::size_t>(r)] == a) ++n;
            if (a == component) break;
        }
        return n;
    }
    template <int Frontier, int Component>
    static constexpr auto component_candidates = [] {
        std::array<int, static_cast<std::size_t>(component_candidate_count(Frontier, Component))> out{};
        std::size_t n = 0;
        for (int a = Frontier;; a = topo.parent[static_cast<std::size_t>(a)]) {
            for (int r = 0; r < R; ++r)
                if (is_transition_on(r, any_condition) && table.source[static_cast<std::size_t>(r)] == a)
                    out[n++] = r;
            if (a == Component) break;
        }
        return out;
    }();

    // States that are the source of a timeout row get a slot for the time they were entered,
    // numbered in document order.
    static constexpr auto timeout_slot = [] {
        std::array<bool, static_cast<std::size_t>(N)> has{};
        for (int r = 0; r < R; ++r)
            if (table.kinds[static_cast<std::size_t>(r)] == row_kind::transition &&
                table.trigger[static_cast<std::size_t>(r)] <= timeout_trigger_id(0))
                has[static_cast<std::size_t>(table.source[static_cast<std::size_t>(r)])] = true;
        std::array<int, static_cast<std::size_t>(N)> slot{};
        int n = 0;
        for (std::size_t s = 0; s < slot.size(); ++s) slot[s] = has[s] ? n++ : -1;
        return slot;
    }();
    static constexpr int timeout_slots = [] {
        int n = 0;
        for (int slot : timeout_slot) n += slot >= 0;
        return n;
    }();

    static constexpr int transition_count(int trigger) {
        int n = 0;
        for (int r = 0; r < R; ++r) n += is_transition_on(r, trigger) ? 1 : 0;
        return n;
    }

    // The transitions on a trigger, in declaration order; the selection buffer stores positions here.
    template <int Trigger>
    static constexpr auto transitions = [] {
        std::array<int, static_cast<std::size_t>(transition_count(Trigger))> out{};
        std::size_t n = 0;
        for (int r = 0; r < R; ++r)
            if (is_transition_on(r, Trigger))
                out[n++] = r;
        return out;
    }();

    template <int Trigger>
    static constexpr int position_of(int row) {
        for (std::size_t i = 0; i < transitions<Trigger>.size(); ++i)
            if (transitions<Trigger>[i] == row)
                return static_cast<int>(i);
        return -1;
    }

    static constexpr int count_rows(row_kind k, int state) {
        int n = 0;
        for (int r = 0; r < R; ++r)
            n += table.kinds[static_cast<std::size_t>(r)] == k && table.source[static_cast<std::size_t>(r)] == state;
        return n;
    }

    // Entry or exit rows of a state, in declaration order.
    template <row_kind K, int State>
    static constexpr auto state_rows = [] {
        std::array<int, static_cast<std::size_t>(count_rows(K, State))> out{};
        std::size_t n = 0;
        for (int r = 0; r < R; ++r)
            if (table.kinds[static_cast<std::size_t>(r)] == K && table.source[static_cast<std::size_t>(r)] == State)
                out[n++] = r;
        return out;
    }();

    template <int S>
    static constexpr auto children = [] {
        std::array<int, static_cast<std::size_t>(topo.child_count[static_cast<std::size_t>(S)])> out{};
        std::size_t n = 0;
        for (int c = topo.first_child[static_cast<std::size_t>(S)]; c >= 0;
             c = topo.next_sibling[static_cast<std::size_t>(c)])
            out[n++] = c;
        return out;
    }();

    // How many basic states can be active at once: the size of the selection buffer.
    static constexpr int max_active_leaves(int s) {
        auto const i = static_cast<std::size_t>(s);
        if (topo.is_leaf(s))
            return 1;
        int result = 0;
        for (int c = topo.first_child[i]; c >= 0; c = topo.next_sibling[static_cast<std::size_t>(c)]) {
            int const m = max_active_leaves(c);
            result = topo.kinds[i] == kind::parallel ? result + m : (m > result ? m : result);
        }
        return result;
    }

    static constexpr bool has_parallel = [] {
        for (int s = 0; s < N; ++s)
            if (topo.kinds[static_cast<std::size_t>(s)] == kind::parallel)
                return true;
        return false;
    }();

    // The initial configuration: every composite's byte at its initial child.
    template <std::size_t Slots>
    static constexpr std::array<std::uint8_t, Slots> initial_bytes() {
        std::array<std::uint8_t, Slots> bytes{};
        for (int s = 0; s < N; ++s) {
            auto const i = static_cast<std::size_t>(s);
            if (topo.slot[i] >= 0)
                bytes[static_cast<std::size_t>(topo.slot[i])] =
                    static_cast<std::uint8_t>(topo.ordinal[static_cast<std::size_t>(topo.initial[i])]);
        }
        return bytes;
    }

    // Two selected transitions conflict when their exit sets meet, i.e. when their domains nest.
    static constexpr bool conflict(int r1, int r2) {
        int const d1 = table.domain[static_cast<std::size_t>(r1)], d2 = table.domain[static_cast<std::size_t>(r2)];
        if (d1 < 0 || d2 < 0)
            return false;
        return topo.contains(d1, d2) || topo.contains(d2, d1);
    }

    static constexpr int index_in_components(int s) {
        for (std::size_t i = 0; i < components.size(); ++i)
            if (components[i] == s) return static_cast<int>(i);
        return -1;
    }

    // The zone of a state: the component (plan::components) it lies in, as an index there.
    // Within a zone at most one transition is selected per microstep: its basic states that
    // lie below no further parallel state are mutually exclusive.
    static constexpr auto zone = [] {
        std::array<int, static_cast<std::size_t>(N)> z{};
        for (int s = 0; s < N; ++s) {
            z[static_cast<std::size_t>(s)] = 0;
            for (int a = s; a > 1; a = topo.parent[static_cast<std::size_t>(a)]) {
                int const i = index_in_components(a);
                if (i >= 0) {
                    z[static_cast<std::size_t>(s)] = i;
                    break;
                }
            }
        }
        return z;
    }();

    static constexpr int zone_row_count(int trigger, int z) {
        int n = 0;
        for (int r = 0; r < R; ++r)
            n += is_transition_on(r, trigger) && zone[static_cast<std::size_t>(table.source[static_cast<std::size_t>(r)])] == z;
        return n;
    }
    // The transitions on a trigger whose source lies in zone Z, in declaration order.
    template <int Trigger, int Z>
    static constexpr auto zone_rows = [] {
        std::array<int, static_cast<std::size_t>(zone_row_count(Trigger, Z))> out{};
        std::size_t n = 0;
        for (int r = 0; r < R; ++r)
            if (is_transition_on(r, Trigger) && zone[static_cast<std::size_t>(table.source[static_cast<std::size_t>(r)])] == Z)
                out[n++] = r;
        return out;
    }();
    // What a region-local selection records for a row: 1 + its position in its zone's rows.
    template <int Trigger, int Row>
    static constexpr int zone_code = [] {
        constexpr auto const& rows = zone_rows<Trigger, zone[static_cast<std::size_t>(table.source[Row])]>;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (rows[i] == Row) return static_cast<int>(i) + 1;
        return 0;
    }();

    // A trigger is region-local when what SCXML's conflict resolution does at run time is known
    // at compile time to keep every selected transition: no transition on it leaves a state that
    // contains a parallel state (so each is selected by one basic state at most), and no two
    // transitions from different zones have nesting domains (so none preempts another). Its
    // microstep then records one row per zone and fires the zones in document order, with no
    // run-time conflict check.
    template <int Trigger>
    static constexpr bool region_local = [] {
        if (!has_parallel) return false;  // nothing to resolve: every transition fires where selected
        for (int r = 0; r < R; ++r) {
            if (!is_transition_on(r, Trigger)) continue;
            int const src = table.source[static_cast<std::size_t>(r)];
            for (int s = 0; s < N; ++s)
                if (topo.kinds[static_cast<std::size_t>(s)] == kind::parallel && topo.contains(src, s))
                    return false;
            if (zone_row_count(Trigger, zone[static_cast<std::size_t>(src)]) > 254) return false;
            for (int r2 = r + 1; r2 < R; ++r2)
                if (is_transition_on(r2, Trigger) &&
                    zone[static_cast<std::size_t>(table.source[static_cast<std::size_t>(r2)])] != zone[static_cast<std::size_t>(src)] &&
                    conflict(r, r2))
                    return false;
        }
        return true;
    }();

    // A region-local trigger whose transitions can fire as they are selected, with the same
    // effects as selecting all first: none is guarded (so no selection can depend on another
    // zone's action), and no state that one of them exits or enters has an entry or exit row
    // (so the only visible effects are the transition actions, which run in document order
    // either way). Each zone's transition changes only the bytes inside its own domain.
    template <int Trigger>
    static constexpr bool fires_at_selection = [] {
        if (!region_local<Trigger>) return false;
        for (int r = 0; r < R; ++r) {
            if (!is_transition_on(r, Trigger)) continue;
            if (table.guarded[static_cast<std::size_t>(r)]) return false;
            int const d = table.domain[static_cast<std::size_t>(r)];
            if (d < 0) continue;  // targetless: exits and enters nothing
            for (int r2 = 0; r2 < R; ++r2) {
                auto const k = table.kinds[static_cast<std::size_t>(r2)];
                int const s = table.source[static_cast<std::size_t>(r2)];
                if ((k == row_kind::entry || k == row_kind::exit) && s != d && topo.contains(d, s)) return false;
            }
        }
        return true;
    }();

    // The zones in which a transition on the trigger can be selected under a parallel state.
    static constexpr int selecting_zone_count(int trigger) {
        int n = 0;
        for (std::size_t z = 1; z < components.size(); ++z) n += zone_row_count(trigger, static_cast<int>(z)) > 0;
        return n;
    }
    template <int Trigger>
    static constexpr auto selecting_zones = [] {
        std::array<int, static_cast<std::size_t>(selecting_zone_count(Trigger))> out{};
        std::size_t n = 0;
        for (std::size_t z = 1; z < components.size(); ++z)
            if (zone_row_count(Trigger, static_cast<int>(z)) > 0) out[n++] = static_cast<int>(z);
        return out;
    }();

};

}  // namespace bsc::detail
