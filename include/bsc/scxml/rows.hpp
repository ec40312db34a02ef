#pragma once
// bsc::scxml::guard_of and bsc::scxml::action_of: the guard and the action of a row of a chart,
// for a chart that bsc-scxml compiles back from the annotated SCXML export of that chart
// (bsc::to_scxml_annotated; docs/scxml.md, "Round trip").

#include <cstddef>
#include <type_traits>

#include <bsc/chart.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/dsl/row.hpp>

namespace bsc::scxml::detail {

template <class A>
struct unwrapped_action {
    static constexpr A const& of(A const& a) noexcept { return a; }
};
// An entry, exit or initial row holds its action wrapped for the calls such a row makes; the
// row made again wraps it again.
template <class A>
struct unwrapped_action<bsc::detail::state_action<A>> {
    static constexpr A const& of(bsc::detail::state_action<A> const& a) noexcept { return a.fn; }
};

template <auto const& Chart, std::size_t Position>
constexpr auto const& row_of() noexcept {
    static_assert(Position >= 1 && Position <= std::remove_cvref_t<decltype(Chart)>::row_types::size,
                  "bsc::scxml: a row position counts from 1 up to the number of the chart's rows");
    return bsc::detail::row_at<Position - 1>(Chart.rows);
}

}  // namespace bsc::scxml::detail

namespace bsc::scxml {

/// The guard of the row at Position (from 1, in make_chart's order, as bsc's errors and the
/// annotated export count) of Chart, a chart declared `constexpr` with static storage: a copy,
/// which guards the same way (named guards keep their names).
template <auto const& Chart, std::size_t Position>
inline constexpr auto guard_of = detail::row_of<Chart, Position>().guard;

/// The action of the row at Position of Chart: a transition's action, or an entry, exit or
/// initial row's.
template <auto const& Chart, std::size_t Position>
inline constexpr auto action_of =
    detail::unwrapped_action<std::remove_cvref_t<decltype(detail::row_of<Chart, Position>().action)>>::of(
        detail::row_of<Chart, Position>().action);

}  // namespace bsc::scxml
