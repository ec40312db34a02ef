#pragma once
// The rows of a chart, held as one object: each row in a base of its own, keyed by its
// position. A row is read with row_at<I>(rows), a function template whose arguments are the
// position and that row's type alone (deduced from the base), so the symbols the compiler makes
// for a read do not spell every row of the chart, as a tuple's get<I> would: for a large chart
// those names, one per row read, were a large part of its compile time. An empty row (a guard
// and an action that capture nothing) takes no room.

#include <cstddef>
#include <utility>

namespace bsc::detail {

template <std::size_t I, class Row>
struct row_slot {
    [[no_unique_address]] Row row;
};

template <class Positions, class... Rows>
struct row_slots;
template <std::size_t... I, class... Rows>
struct row_slots<std::index_sequence<I...>, Rows...> : row_slot<I, Rows>... {};

template <class... Rows>
using row_storage = row_slots<std::index_sequence_for<Rows...>, Rows...>;

/// The row at position I (from 0, in make_chart's order).
template <std::size_t I, class Row>
constexpr Row const& row_at(row_slot<I, Row> const& slot) {
    return slot.row;
}

/// The row at position I, to move from (the row's type deduced from the base, as row_at's).
template <std::size_t I, class Row>
constexpr Row&& take_row(row_slot<I, Row>& slot) {
    return static_cast<Row&&>(slot.row);
}

/// Calls f with every row, in order.
template <class F, std::size_t... I, class... Rows>
constexpr decltype(auto) with_rows(row_slots<std::index_sequence<I...>, Rows...> const& rows, F&& f) {
    return std::forward<F>(f)(detail::row_at<I>(rows)...);
}

}  // namespace bsc::detail
