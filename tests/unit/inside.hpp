#pragma once
// The one place the tests look inside bsc, for what they must check and the public interface
// does not show: a machine's queue, the compile-time dispatch plan, the chart model the
// exports are checked against, the exporters' naming helpers and the explorer's codec. Every
// other test file uses the public API only (tests/README.md).

#include <cstddef>
#include <type_traits>
#include <utility>


#include <bsc/bsc.hpp>
#include <bsc/detail/compiled/plan.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/export.hpp>
#include <bsc/retain.hpp>
#include <bsc/verify.hpp>

namespace inside {

// A machine's context, writable. The environment's view (context()) is const: it sets inputs
// and reads the rest. The differential and fault-injection harnesses change variables of the
// chart between runs as no environment can, to compare the back ends from states their runs
// alone would not reach.
template <class Machine>
constexpr auto& context(Machine& m) {
    return bsc::detail::access::context(m);
}

// A machine's internal event queue (either back end).
template <class Machine>
constexpr auto const& queue(Machine const& m) {
    return bsc::detail::access::queue(const_cast<Machine&>(m));
}
template <class Machine>
using queue_type = std::remove_cvref_t<decltype(bsc::detail::access::queue(std::declval<Machine&>()))>;

// The events a machine keeps between calls: deferred, and delayed (pending, not yet due).
template <class Machine>
std::size_t deferred_count(Machine const& m) {
    return bsc::detail::access::deferred(const_cast<Machine&>(m)).size();
}
template <class Machine>
std::size_t delayed_count(Machine const& m) {
    return bsc::detail::access::queue(const_cast<Machine&>(m)).scheduled();
}

// The chart model and the compiled back end's dispatch plan of a chart type.
template <class Chart>
using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
template <class Chart>
using plan = bsc::detail::plan<model<Chart>>;
template <class Chart, class E>
inline constexpr int trigger_of = model<Chart>::template trigger_of<E>::value;

// Type lists, as the model and the machines' event_types use them.
template <class... Ts>
using type_list = bsc::detail::type_list<Ts...>;
template <std::size_t I, class List>
using at = bsc::detail::at<I, List>;
template <class... Lists>
using concat_t = bsc::detail::concat_t<Lists...>;
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

// A row's text as bsc's errors write it (detail/checks/row_text.hpp).
template <class Row>
constexpr auto row_text() {
    return bsc::detail::row_text<Row>();
}

// The queue a chart's machine gets (detail/runtime/queue_for.hpp), and its one-event kind.
template <class Chart, class Policy>
using queue_for = bsc::detail::queue_for<Chart, Policy>;
template <std::size_t Capacity, class E>
using single_event_queue = bsc::detail::single_event_queue<Capacity, E>;

// The events that can be dispatched from outside (event_set.hpp), as a type list.
template <class Events>
using sendable_events = typename bsc::detail::sendable_events<Events>::type;

// The retentive state's format: its header's size, its checksum, the fingerprints it checks a
// restore against, and the timeout slots a chart keeps.
inline constexpr std::size_t retain_header_size = bsc::detail::retain::header_size;
inline std::uint32_t crc32(std::byte const* bytes, std::size_t n) { return bsc::detail::crc32(bytes, n); }
template <class Machine>
constexpr std::uint64_t chart_fingerprint() {
    return bsc::detail::chart_fingerprint<Machine>();
}
template <class Machine>
constexpr std::uint64_t layout_fingerprint() {
    return bsc::detail::layout_fingerprint<Machine>();
}
template <class Chart>
inline constexpr std::size_t timeout_slots =
    bsc::detail::chart_layout<bsc::detail::chart_model<std::remove_cv_t<Chart>>>::timeout_slots;

// How the member layer sees a type: an enum with a fixed underlying type, the number of an
// aggregate's fields, their names.
template <class T>
inline constexpr bool has_fixed_underlying_type = bsc::detail::has_fixed_underlying_type<T>;
template <class T>
constexpr std::size_t field_count() {
    return bsc::detail::field_count<T>();
}
template <class T>
inline constexpr auto const& member_names = bsc::detail::member_names<T>;

// ---- fault injection -------------------------------------------------------------------
// with_faults<Injector>(chart) is the same chart with every guard and every action (transition,
// entry and exit rows alike) calling Injector::point() first, so a test can make any call site
// throw in turn. The rows keep their sources, triggers and targets.
template <class Injector, class Guard>
struct faulty_guard {
    Guard inner;
    template <class Ctx, class E>
    constexpr bool operator()(Ctx const& context, E const& event) const {
        Injector::point();
        return static_cast<bool>(inner(context, event));
    }
};
template <class Injector, class Action>
struct faulty_action {
    Action inner;
    template <class... Arguments>
    constexpr void operator()(Arguments&... arguments) const {
        Injector::point();
        inner(arguments...);
    }
};

template <class Injector, class Action>
constexpr auto faulty_transition_action(Action const& action) {
    if constexpr (std::is_same_v<Action, bsc::detail::no_action>)
        return action;  // no call site
    else
        return faulty_action<Injector, Action>{action};
}

template <class Injector, class Row>
constexpr auto faulty_row(Row const& row) {
    using namespace bsc::detail;
    if constexpr (is_transition_row<Row>) {
        auto const guard = [&] {
            if constexpr (Row::guarded)
                return faulty_guard<Injector, std::remove_cvref_t<decltype(row.guard)>>{row.guard};
            else
                return row.guard;
        }();
        auto const action = faulty_transition_action<Injector>(row.action);
        return transition_row<typename Row::source, typename Row::trigger, std::remove_cvref_t<decltype(guard)>,
                              std::remove_cvref_t<decltype(action)>, typename Row::target>{
            {}, row.trigger_value, guard, action};
    } else if constexpr (is_entry_row<Row>) {
        auto const action = faulty_action<Injector, std::remove_cvref_t<decltype(row.action)>>{row.action};
        return entry_row<typename Row::source, std::remove_cvref_t<decltype(action)>>{{}, action};
    } else {
        auto const action = faulty_action<Injector, std::remove_cvref_t<decltype(row.action)>>{row.action};
        return exit_row<typename Row::source, std::remove_cvref_t<decltype(action)>>{{}, action};
    }
}

template <class Injector, class Chart>
constexpr auto with_faults(Chart const& chart) {
    return bsc::detail::with_rows(chart.rows, [](auto const&... rows) {
        return bsc::make_chart<typename Chart::context_type>(typename Chart::root_type{},
                                                             faulty_row<Injector>(rows)...);
    });
}

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
