#pragma once
// bsc::chart_ref<chart>: the type of a chart, named after the constexpr variable that holds it.
//
// A chart's own type spells out its whole state tree and every row, so each function the
// compiler generates for `bsc::machine<decltype(chart)>` carries that spelling in its symbol
// name, and for large charts building those names dominates compile time (it grows faster
// than the chart). `bsc::machine<bsc::chart_ref<chart>>` is the same machine, with the same
// behaviour, whose symbols name the variable instead:
//
//   inline constexpr auto chart = bsc::make_chart<io>(...);
//   using controller = bsc::machine<bsc::chart_ref<chart>>;
//   controller m{chart};
//
// Since the type names the variable, a machine of it stores no copy of the chart: every such
// machine reads one constant copy of `chart` (detail::shared_chart), so what the rows hold,
// delays, captured values, raised events, is folded into the code, and the machine is smaller
// by the chart's size.
//
// Requirements: `Chart` is a chart (from bsc::make_chart) declared as a constexpr variable
// with static storage duration (namespace scope, or a static data member). A chart_ref is made
// from `Chart` itself, or default-constructed; made from any other chart, even an equal one,
// it does not compile (bsc::detail::bsc_chart_ref_made_from_another_chart), since the machine
// would silently run `Chart` instead.

#include <type_traits>

namespace bsc::detail {
// Deliberately not constexpr: reaching it in the constant evaluation of chart_ref's constructor
// is the compile error, and its name says what is wrong.
inline void bsc_chart_ref_made_from_another_chart() {}
}  // namespace bsc::detail

namespace bsc {

template <auto const& Chart>
struct chart_ref : std::remove_cvref_t<decltype(Chart)> {
    using chart_type = std::remove_cvref_t<decltype(Chart)>;
    constexpr chart_ref() : chart_type(Chart) {}
    // Implicit, so that a machine of chart_ref<chart> is constructed from `chart` itself; an
    // immediate function, so that it can check that it is `chart` indeed.
    consteval chart_ref(chart_type const& other) : chart_type(other) {  // NOLINT(google-explicit-constructor)
        if (&other != &Chart) detail::bsc_chart_ref_made_from_another_chart();
    }
};

}  // namespace bsc

namespace bsc::detail {
template <class T>
inline constexpr bool is_chart_ref = false;
template <auto const& Chart>
inline constexpr bool is_chart_ref<chart_ref<Chart>> = true;
}  // namespace bsc::detail
