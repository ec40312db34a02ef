#pragma once
// bsc::make_chart: a chart is its state tree and its rows, checked when it is declared.

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <bsc/allow.hpp>
#include <bsc/error.hpp>
#include <bsc/detail/checks/checks.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/duration.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/priority.hpp>
#include <bsc/dsl/tree.hpp>

namespace bsc::detail {
// Rows grouped by bsc::rows, held as a chart holds its rows (detail/row_storage.hpp).
template <class... Rows>
struct row_group {
    row_storage<Rows...> rows;
};
template <class A>
inline constexpr bool is_row_group = false;
template <class... Rows>
inline constexpr bool is_row_group<row_group<Rows...>> = true;

// How many rows an argument of bsc::rows or make_chart brings: a row one, a group its own.
template <class A>
inline constexpr std::size_t rows_in = 1;
template <class... Rows>
inline constexpr std::size_t rows_in<row_group<Rows...>> = sizeof...(Rows);

// Where each row of the flattened list comes from: its argument, and its position there.
template <class... A>
struct flat_positions {
    static constexpr std::size_t size = [] {
        std::size_t n = 0;
        for (std::size_t k : {rows_in<A>..., std::size_t{0}}) n += k;  // (a list: detail::max_fold)
        return n;
    }();
    struct from {
        std::size_t argument = 0;
        std::size_t position = 0;
    };
    static constexpr std::array<from, size> of = [] {
        std::array<from, size> out{};
        std::size_t j = 0, k = 0;
        for (std::size_t n : {rows_in<A>...}) {
            for (std::size_t i = 0; i < n; ++i) out[j++] = {k, i};
            ++k;
        }
        return out;
    }();
};

// An argument of bsc::rows or make_chart as a group: a group as it is, a row as a group of one;
// and the rows of a group.
template <class A>
struct group_of {
    using type = row_group<A>;
};
template <class... Rows>
struct group_of<row_group<Rows...>> {
    using type = row_group<Rows...>;
};
template <class Group>
struct rows_of;
template <class... Rows>
struct rows_of<row_group<Rows...>> {
    using type = type_list<Rows...>;
};
template <class A>
constexpr typename group_of<A>::type as_group(A&& a) {
    if constexpr (is_row_group<A>)
        return static_cast<A&&>(a);
    else
        return {{{static_cast<A&&>(a)}}};
}

// The rows and groups of rows A..., as one group. Each row is moved from the slot that holds
// it, named by its position and type (a cast to a known base), not found by a deduction among
// every row, which made a group of n rows cost O(n^2), nor by a function per row, whose name
// would spell the group. (Not std::tuple_cat and std::apply: their instantiations, a recursion
// over the tuples and a noexcept test of a call with every row, were most of what a chart of
// many groups cost to declare.)
template <class... A>
constexpr auto flatten_rows(A... a) {
    using positions = flat_positions<A...>;
    using groups = type_list<typename group_of<A>::type...>;
    using flat = concat_t<typename rows_of<typename group_of<A>::type>::type...>;
    row_storage<typename group_of<A>::type...> arguments{{as_group(static_cast<A&&>(a))}...};
    // clang-format off
    return [&]<std::size_t... J, class... Rs>(std::index_sequence<J...>, type_list<Rs...>) {
        return row_group<Rs...>{{{static_cast<Rs&&>(
            static_cast<row_slot<positions::of[J].position, Rs>&>(
                static_cast<row_slot<positions::of[J].argument, at<positions::of[J].argument, groups>>&>(arguments)
                    .row.rows)
                .row)}...}};
    }(std::make_index_sequence<positions::size>{}, flat{});
    // clang-format on
}

template <class Root>
constexpr bool is_compound_root() {
    if constexpr (is_node<Root>)
        return Root::node_kind == kind::composite || Root::node_kind == kind::parallel;
    else
        return false;
}
}  // namespace bsc::detail

namespace bsc {

/// A statechart over the context type `Context`: the state tree `Root`, the priority `Order`
/// among nested transitions (bsc/priority.hpp) and the rows.
/// Obtain one with make_chart; run it with bsc::machine.
template <class Context, class Root, priority Order, class... Rows>
struct chart {
    using context_type = Context;
    using root_type = Root;
    static constexpr priority order = Order;
    using row_types = detail::type_list<Rows...>;
    detail::row_storage<Rows...> rows;
};

namespace detail {
// The dead transitions that only the delays tell (detail/checks/dead_transitions.hpp finds the others):
// a timeout row that an unguarded timeout row, with a target, always beats. That row, of state
// C, leaves the states from C up to its domain no later than its delay after C's entry. Each
// such state P whose entry starts C's clock too (C is P, or C is active whenever P is: every
// composite between them has C's branch as its only child, and no row whose domain lies inside
// P exits C) leaves, with its clock, every state D below P that is likewise active with P. A
// timeout row of such a D with a longer delay never fires; with an equal delay, neither does
// one of C declared later, or one of an ancestor of C in C's [BSC] component (child first: the
// deeper state's row is tried first), or one of a descendant of C (parent first, or across a
// parallel state: the outer row is tried first, or its component takes its turn first). For D
// other than C, only where no other condition-driven row is tried before C's in C's component:
// one that fires in the cycle C's row comes due holds it back, one transition per component per
// cycle, and D's may come due meanwhile. (C's own timeouts compete by due time.)
// (make_chart reports it through the dead row's copy: dsl/row.hpp, timeout_trigger.) Returns
// the positions (from 1) of the first dead row found and of the row that beats it; {0, 0} if
// there is none.
struct dead_timeout {
    std::size_t row = 0;
    std::size_t fires_first = 0;
};

// Whether state d (p itself or below p) is active whenever p is, with the clock it had when p
// was entered.
template <std::size_t N, std::size_t Count>
constexpr bool active_with(topology<N> const& t, row_table<Count> const& r, int p, int d) {
    for (int below = d; below != p;) {
        int const x = t.parent[static_cast<std::size_t>(below)];
        auto const xi = static_cast<std::size_t>(x);
        if (t.kinds[xi] == kind::composite)  // a parallel state enters every region
            for (int other = t.first_child[xi]; other >= 0; other = t.next_sibling[static_cast<std::size_t>(other)])
                if (other != below && t.kinds[static_cast<std::size_t>(other)] != kind::history) return false;
        below = x;
    }
    for (std::size_t k = 0; k < Count; ++k)
        if (r.kinds[k] == row_kind::transition && r.domain[k] >= 0 && t.contains(p, r.domain[k]) &&
            t.is_proper_ancestor(r.domain[k], d))
            return false;
    return true;
}

// The [BSC] component of state s: the root, or the child of a parallel state that s lies in.
template <std::size_t N>
constexpr int component_of(topology<N> const& t, int s) {
    for (int a = s; a > 1; a = t.parent[static_cast<std::size_t>(a)])
        if (t.kinds[static_cast<std::size_t>(t.parent[static_cast<std::size_t>(a)])] == kind::parallel) return a;
    return 1;
}

// Whether a condition-driven row other than `first` and `other` is tried before `first` in its
// component: a guarded or internal one could fire in the cycle `first` comes due instead of it.
template <std::size_t N, std::size_t Count>
constexpr bool held_back(topology<N> const& t, row_table<Count> const& r, std::size_t first, std::size_t other,
                         priority order) {
    int const c = r.source[first];
    for (std::size_t k = 0; k < Count; ++k) {
        int const s = r.source[k];
        if (k == first || k == other || r.kinds[k] != row_kind::transition || r.trigger[k] >= 0) continue;
        if (s == c) {
            if (r.trigger[k] == eventless_id && k < first) return true;  // its timeouts compete by due time
        } else if (component_of(t, s) == component_of(t, c) &&
                   (order == priority::child_first ? t.is_proper_ancestor(c, s) : t.is_proper_ancestor(s, c))) {
            return true;
        }
    }
    return false;
}

template <std::size_t N, std::size_t Count>
constexpr dead_timeout find_dead_timeout(topology<N> const& t, row_table<Count> const& r,
                                         std::array<duration, Count> const& delay, priority order) {
    std::array<std::size_t, Count> timeouts{};
    std::size_t count = 0;
    for (std::size_t i = 0; i < Count; ++i)
        if (r.kinds[i] == row_kind::transition && r.trigger[i] <= -2) timeouts[count++] = i;
    for (std::size_t a = 0; a < count; ++a) {
        std::size_t const first = timeouts[a];
        if (r.guarded[first] || r.target[first] < 0 || r.domain[first] < 0) continue;
        int const c = r.source[first];
        for (int p = c; p >= 0 && !t.contains(p, r.domain[first]); p = t.parent[static_cast<std::size_t>(p)]) {
            if (p != c && !active_with(t, r, p, c)) break;  // nor is C for the states above
            for (std::size_t b = 0; b < count; ++b) {
                std::size_t const j = timeouts[b];
                int const d = r.source[j];
                if (j == first || !t.contains(p, d) || (d != p && !active_with(t, r, p, d))) continue;
                if (d != c && held_back(t, r, first, j, order)) continue;
                bool const inner_first = order == priority::child_first && component_of(t, c) == component_of(t, d);
                bool const tried_first = d == c        ? first < j
                                         : inner_first ? t.is_proper_ancestor(d, c)
                                                       : t.is_proper_ancestor(c, d);
                bool const beaten = delay[first] < delay[j] || (delay[first] == delay[j] && tried_first);
                if (beaten) return {j + 1, first + 1};
            }
        }
    }
    return {};
}

// Marks the dead row's parameter (timeout_trigger's destructor reports it).
template <class... Rows>
constexpr void mark_dead_timeout(dead_timeout const& dead, Rows&... rows) {
    std::size_t position = 0;
    auto const mark = [&](auto& row) {
        ++position;
        if constexpr (is_timeout_row<std::remove_cvref_t<decltype(row)>>)
            if (position == dead.row) row.trigger_value.delay = timeout_trigger::dead_mark(dead.row, dead.fires_first);
    };
    [[maybe_unused]] int const marked[] = {(mark(rows), 0)..., 0};  // (a list: detail::max_fold)
}

template <class... Rows>
constexpr std::array<duration, sizeof...(Rows)> delays_of(Rows const&... rows) {
    return {[&] {
        if constexpr (is_timeout_row<Rows>)
            return rows.trigger_value.delay;
        else
            return duration::zero();
    }()...};
}

template <class Errors>
struct rejected_chart_of;
template <class... Errors>
struct rejected_chart_of<type_list<Errors...>> {
    template <class Context>
    using type = rejected_chart<Context, Errors...>;
};

}  // namespace detail

/// Declares a chart: first the state tree, then the rows (transitions, entry and exit actions).
/// The static checks run here; a malformed chart fails to compile with an error that names
/// the offending state (see docs/checks.md).
/// Groups rows so that a set of rules can be defined once and reused in several charts:
/// `inline constexpr auto pause_rules = bsc::rows(row1, row2);` then
/// `bsc::make_chart<C>(tree, base_rules, pause_rules, row3)`. Groups may nest.
template <class... Rows>
constexpr auto rows(Rows... rows) {
    return detail::flatten_rows(std::move(rows)...);
}

/// `make_chart<Context, Priority, bsc::allow<Findings...>>(tree, rows...)` declares a chart that
/// allows the findings named (bsc/allow.hpp): the checks run, and those findings are dropped.
/// `make_chart<Context, bsc::parent_first>(tree, rows...)` declares a chart whose outer
/// transitions have priority over inner ones (bsc/priority.hpp); `make_chart<Context>` is
/// `make_chart<Context, bsc::child_first>`.
// (One function, the priority a defaulted parameter: a forwarding overload would move the rows
// into a second call, whose frame, spelling every row, a dead timeout's error would then carry.)
template <class Context, priority Order = priority::child_first, class Allowed = allow<>, class Root, class... Rows>
constexpr auto make_chart(Root root, Rows... rows) {
    if constexpr (!detail::is_allow<Allowed> || !detail::all_allowable<Allowed>) {
        return detail::rejected_chart<Context, error::finding_not_allowable<Allowed>>{};
    } else if constexpr (detail::any_true({detail::is_row_group<Rows>..., false})) {
        auto group = detail::flatten_rows(std::move(rows)...);
        // clang-format off
        return [&]<std::size_t... I, class... Rs>(detail::row_slots<std::index_sequence<I...>, Rs...>& slots) {
            return make_chart<Context, Order, Allowed>(
                std::move(root), static_cast<Rs&&>(static_cast<detail::row_slot<I, Rs>&>(slots).row)...);
        }(group.rows);
        // clang-format on
    } else if constexpr (!detail::is_compound_root<Root>()) {
        return detail::rejected_chart<Context, error::root_must_be_composite<Root>>{};
    } else if constexpr (!detail::all_true({detail::is_row<Rows>...})) {
        constexpr int bad =
            detail::position_in<std::false_type, detail::type_list<std::bool_constant<detail::is_row<Rows>>...>>::value;
        return detail::rejected_chart<
            Context, error::not_a_row<detail::at<static_cast<std::size_t>(bad), detail::type_list<Rows...>>>>{};
    } else {
        // The chart, or, when its checks find errors, the rejected_chart whose destruction
        // reports them.
        using chart_type = chart<Context, Root, Order, Rows...>;
        using errors = typename detail::without_allowed<Allowed, decltype(detail::check_chart<chart_type>())>::type;
        if constexpr (errors::size == 0) {
            if constexpr (detail::any_true({detail::is_timeout_row<Rows>..., false})) {
                auto const dead = detail::find_dead_timeout(detail::chart_model<chart_type>::tree,
                                                            detail::chart_model<chart_type>::rows,
                                                            detail::delays_of(rows...), Order);
                if (dead.row != 0) {
                    if (!std::is_constant_evaluated())
                        detail::bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(dead.row,
                                                                                               dead.fires_first);
                    // In a constant expression, the error comes from the marked parameter's
                    // destruction, after this returns (detail::timeout_trigger).
                    chart_type built{{{std::move(rows)}...}};
                    detail::mark_dead_timeout(dead, rows...);
                    return built;
                }
            }
            return chart_type{{{std::move(rows)}...}};
        } else {
            return typename detail::rejected_chart_of<errors>::template type<Context>{};
        }
    }
}

}  // namespace bsc
