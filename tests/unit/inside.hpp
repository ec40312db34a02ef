#pragma once
// The one place the tests look inside bsc, for what they must check and the public interface
// does not show: a machine's queue, the compile-time dispatch plan, the chart model the
// exports are checked against, the exporters' naming helpers and the explorer's codec. Every
// other test file uses the public API only (tests/README.md).

#include <cstddef>
#include <type_traits>
#include <utility>

#include <bsc/bsc.hpp>
#include <bsc/compiled/plan.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/export.hpp>
#include <bsc/verify.hpp>

namespace inside {

// A machine's internal event queue (either back end).
template <class Machine>
constexpr auto const& queue(Machine const& m) {
    return bsc::detail::access::queue(const_cast<Machine&>(m));
}
template <class Machine>
using queue_type = std::remove_cvref_t<decltype(bsc::detail::access::queue(std::declval<Machine&>()))>;

// The chart model and the compiled back end's dispatch plan of a chart type.
template <class Chart>
using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
template <class Chart>
using plan = bsc::detail::plan<model<Chart>>;
template <class Chart, class E>
inline constexpr int trigger_of = model<Chart>::template trigger_of<E>;

// Type lists, as the model and the machines' event_types use them.
template <class... Ts>
using type_list = bsc::detail::type_list<Ts...>;
template <std::size_t I, class List>
using at = bsc::detail::at<I, List>;
using kind = bsc::detail::kind;
using history = bsc::detail::history;
using row_kind = bsc::detail::row_kind;

// Whether a callable is a guard or action object of bsc's (bsc::guard, bsc::named, ...).
template <class T>
inline constexpr bool is_bsc_guard = bsc::detail::bsc_guard<T>;
template <class T>
inline constexpr bool is_bsc_action = bsc::detail::bsc_action<T>;

// The exporters' naming helpers.
using bsc::detail::action_label;
using bsc::detail::guard_label;
using bsc::detail::identifier;
using bsc::detail::last_scopes;
using bsc::detail::unique_identifiers;
using bsc::detail::unique_names;

// Where the table engine's entry and exit thunks report failures.
using failure_sink = bsc::detail::failure_sink;

// The explorer's encoding of a value.
template <class T>
using codec = bsc::detail::codec<T>;

// Channels are latched and committed by machines only.
template <class Channel>
constexpr void latch(Channel& c) {
    bsc::detail::access::latch(c);
}
template <class Channel>
constexpr void commit(Channel& c) {
    bsc::detail::access::commit(c);
}

}  // namespace inside
