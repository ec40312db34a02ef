#pragma once
// bsc::statechart: what a machine takes as its chart.

#include <type_traits>

#include <bsc/chart.hpp>
#include <bsc/chart_ref.hpp>
#include <bsc/error.hpp>

namespace bsc {

namespace detail {
template <class T>
inline constexpr bool is_chart = false;
template <class Context, class Root, priority Order, class... Rows>
inline constexpr bool is_chart<chart<Context, Root, Order, Rows...>> = true;
}  // namespace detail

/// The type of a chart that bsc::make_chart returned (`decltype(chart)`, const or not), or
/// `bsc::chart_ref<chart>`: what bsc::machine and bsc::table::machine take as their Chart.
/// `bsc::machine<int>` fails at its declaration, naming this concept. (A chart that failed its
/// checks is one too: its machine compiles and does nothing, so that the chart's own errors are
/// the only ones.)
template <class T>
concept statechart = detail::is_chart<std::remove_cv_t<T>> || detail::is_rejected_chart<std::remove_cv_t<T>> ||
    detail::is_chart_ref<std::remove_cv_t<T>>;

}  // namespace bsc
