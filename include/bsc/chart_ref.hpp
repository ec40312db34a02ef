#pragma once
// bsc::chart_ref<chart>: the type of a chart, named after the constexpr variable that holds it.
//
// A chart's own type spells out its whole state tree and every row, so each function the
// compiler generates for `bsc::machine<decltype(chart)>` carries that spelling in its symbol
// name, and for large charts building those names dominates compile time (it grows faster
// than the chart). `bsc::machine<bsc::chart_ref<chart>>` is the same machine, with the same
// behaviour and size, whose symbols name the variable instead:
//
//   inline constexpr auto chart = bsc::make_chart<io>(...);
//   using controller = bsc::machine<bsc::chart_ref<chart>>;
//   controller m{chart};
//
// Requirements: `Chart` is a chart (from bsc::make_chart) declared as a constexpr variable
// with static storage duration (namespace scope, or a static data member).

#include <type_traits>

namespace bsc {

template <auto const& Chart>
struct chart_ref : std::remove_cvref_t<decltype(Chart)> {
    using chart_type = std::remove_cvref_t<decltype(Chart)>;
    constexpr chart_ref() : chart_type(Chart) {}
    // Implicit, so that a machine of chart_ref<chart> is constructed from `chart` itself.
    constexpr chart_ref(chart_type const& other) : chart_type(other) {}  // NOLINT(google-explicit-constructor)
};

}  // namespace bsc
