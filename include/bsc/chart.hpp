#pragma once
// bsc::make_chart: a chart is its state tree and its rows, checked when it is declared.

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <bsc/error.hpp>
#include <bsc/checks/checks.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/duration.hpp>
#include <bsc/dsl/row.hpp>
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
    static constexpr std::size_t size = (rows_in<A> + ... + 0);
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

// Row J of the flattened arguments, moved from where it is: the argument itself, or a row of
// the group it is.
template <std::size_t Argument, std::size_t Position, class Arguments>
constexpr auto&& flat_row(Arguments& arguments) {
    auto&& a = take_row<Argument>(arguments);
    if constexpr (is_row_group<std::remove_cvref_t<decltype(a)>>)
        return take_row<Position>(a.rows);
    else
        return static_cast<std::remove_cvref_t<decltype(a)>&&>(a);
}

// The rows and groups of rows A..., as one group. (Not std::tuple_cat and std::apply: their
// instantiations, a recursion over the tuples and a noexcept test of a call with every row,
// were most of what a chart of many groups cost to declare.)
template <class... A>
constexpr auto flatten_rows(A... a) {
    using positions = flat_positions<A...>;
    row_storage<A...> arguments{{static_cast<A&&>(a)}...};
    return [&]<std::size_t... J>(std::index_sequence<J...>) {
        return row_group<std::remove_cvref_t<
            decltype(flat_row<positions::of[J].argument, positions::of[J].position>(arguments))>...>{
            {{flat_row<positions::of[J].argument, positions::of[J].position>(arguments)}...}};
    }(std::make_index_sequence<positions::size>{});
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

/// A statechart over the context type `Context`: the state tree `Root` and the rows.
/// Obtain one with make_chart; run it with bsc::machine.
template <class Context, class Root, class... Rows>
struct chart {
    using context_type = Context;
    using root_type = Root;
    using row_types = detail::type_list<Rows...>;
    detail::row_storage<Rows...> rows;
};

namespace detail {
// The dead transitions that only the delays tell (checks/dead_transitions.hpp finds the others):
// a timeout row of S behind an unguarded timeout row of S with a target and a shorter delay, or
// an equal one declared earlier, which always fires first and leaves S, so the clock of the
// other starts again before it is due. (make_chart reports it through the dead row's copy:
// dsl/row.hpp, timeout_trigger.) Returns the positions (from 1) of the first dead row found and of the row that fires before
// it; {0, 0} if there is none.
struct dead_timeout {
    std::size_t row = 0;
    std::size_t fires_first = 0;
};
template <std::size_t Count>
constexpr dead_timeout find_dead_timeout(row_table<Count> const& r, std::array<duration, Count> const& delay) {
    auto const timeout = [&](std::size_t i) { return r.kinds[i] == row_kind::transition && r.trigger[i] <= -2; };
    for (std::size_t i = 0; i < Count; ++i) {
        if (!timeout(i) || r.guarded[i] || r.target[i] < 0) continue;
        for (std::size_t j = 0; j < Count; ++j)
            if (j != i && timeout(j) && r.source[j] == r.source[i] &&
                (delay[i] < delay[j] || (delay[i] == delay[j] && i < j)))
                return {j + 1, i + 1};
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
    (mark(rows), ...);
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

template <class Context, class Root, class... Rows>
constexpr auto make_chart(Root root, Rows... rows) {
    if constexpr ((detail::is_row_group<Rows> || ...)) {
        auto group = detail::flatten_rows(std::move(rows)...);
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
            return make_chart<Context>(std::move(root), detail::take_row<I>(group.rows)...);
        }(std::make_index_sequence<detail::rows_in<decltype(group)>>{});
    } else if constexpr (!detail::is_compound_root<Root>()) {
        return detail::rejected_chart<Context, error::root_must_be_composite<Root>>{};
    } else if constexpr (!(detail::is_row<Rows> && ...)) {
        constexpr int bad = detail::position_in<std::false_type, detail::type_list<std::bool_constant<detail::is_row<Rows>>...>>::value;
        return detail::rejected_chart<Context,
                                      error::not_a_row<detail::at<static_cast<std::size_t>(bad), detail::type_list<Rows...>>>>{};
    } else {
        // The chart, or, when its checks find errors, the rejected_chart whose destruction
        // reports them.
        using chart_type = chart<Context, Root, Rows...>;
        using errors = decltype(detail::check_chart<chart_type>());
        if constexpr (errors::size == 0) {
            if constexpr ((detail::is_timeout_row<Rows> || ...)) {
                auto const dead = detail::find_dead_timeout(detail::chart_model<chart_type>::rows, detail::delays_of(rows...));
                if (dead.row != 0) {
                    if (!std::is_constant_evaluated())
                        detail::bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout(dead.row, dead.fires_first);
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
