#pragma once
// bsc::make_chart: a chart is its state tree and its rows, checked when it is declared.

#include <boost/hana/basic_tuple.hpp>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/error.hpp>
#include <bsc/checks/checks.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/dsl/tree.hpp>

namespace bsc::detail {
template <class... Rows>
struct row_group {
    std::tuple<Rows...> rows;
};
template <class A>
inline constexpr bool is_row_group = false;
template <class... Rows>
inline constexpr bool is_row_group<row_group<Rows...>> = true;

template <class A>
constexpr auto row_tuple(A a) {
    if constexpr (is_row_group<A>)
        return a.rows;
    else
        return std::tuple<A>{std::move(a)};
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
    boost::hana::basic_tuple<Rows...> rows;
};

/// Declares a chart: first the state tree, then the rows (transitions, entry and exit actions).
/// The static checks run here; a malformed chart fails to compile with an error that names
/// the offending state (see docs/checks.md).
/// Groups rows so that a set of rules can be defined once and reused in several charts:
/// `inline constexpr auto pause_rules = bsc::rows(row1, row2);` then
/// `bsc::make_chart<C>(tree, base_rules, pause_rules, row3)`. Groups may nest.
template <class... Rows>
constexpr auto rows(Rows... rows) {
    return std::apply([](auto... r) { return detail::row_group<decltype(r)...>{{std::move(r)...}}; },
                      std::tuple_cat(detail::row_tuple(std::move(rows))...));
}

template <class Context, class Root, class... Rows>
constexpr auto make_chart(Root root, Rows... rows) {
    if constexpr ((detail::is_row_group<Rows> || ...)) {
        return std::apply([&](auto... r) { return make_chart<Context>(root, std::move(r)...); },
                          std::tuple_cat(detail::row_tuple(std::move(rows))...));
    } else if constexpr (!detail::is_compound_root<Root>()) {
        static_assert(error::root_must_be_composite<Root>::value);
        return 0;
    } else if constexpr (!(detail::is_row<Rows> && ...)) {
        constexpr int bad = detail::index_in<std::false_type, std::bool_constant<detail::is_row<Rows>>...>();
        static_assert(error::not_a_row<detail::at<static_cast<std::size_t>(bad), detail::type_list<Rows...>>>::value);
        return 0;
    } else {
        using chart_type = chart<Context, Root, Rows...>;
        static_assert(detail::check_chart<chart_type>());
        return chart_type{boost::hana::make_basic_tuple(std::move(rows)...)};
    }
}

}  // namespace bsc
