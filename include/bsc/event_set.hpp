#pragma once
// bsc::event_set<Chart>: the events of a chart, named and numbered at compile time, so that a
// program can dispatch an event it received as text (an operator panel, a command line) or as a
// number (a field bus, a network message):
//
//   m.dispatch_by_name("ON_P");                      // outcome::unknown_event if no event is so named
//   m.dispatch_by_number(3, decode);                 // decode(std::type_identity<E>{}) builds E
//   bsc::event_set<decltype(chart)>::names           // {"ON_P", "OFF_P", ...}
//
// An event's name is its static member `name` when it has one (`static constexpr
// std::string_view name = "ON_P";`), otherwise its type's unqualified name (bsc::name_of). Its
// number is its position among the chart's events: the trigger events of the rows, in the order
// in which they first appear, without those the environment cannot send (detail::reserved_event:
// bsc::done<S> and bsc::action_failed, which only the machine raises, and bsc::any_event, a tag).
// So "done.state.S" and "*" name no event here, and dispatch_by_name answers
// outcome::unknown_event for them. Two events of a chart with the same name are an error
// (bsc::error::duplicate_event_name).

#include <array>
#include <cassert>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include <bsc/events.hpp>
#include <bsc/error.hpp>
#include <bsc/event_name.hpp>
#include <bsc/detail/model/chart_model.hpp>

namespace bsc {

namespace detail {

// The first pair of events of Events with the same name, as positions (-1, -1 if none).
template <class... Events>
constexpr std::pair<int, int> duplicate_event_name() {
    constexpr std::array<std::string_view, sizeof...(Events)> names{event_name<Events>...};
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = i + 1; j < names.size(); ++j)
            if (names[i] == names[j]) return {static_cast<int>(i), static_cast<int>(j)};
    return {-1, -1};
}

// The events a chart may take that the environment cannot send: bsc::done<S>, raised by the
// machine when S completes, bsc::action_failed, raised when one of its guards or actions throws,
// and bsc::any_event, the tag that a row on every event receives instead of the event. A dispatch
// of one from outside would fake what only the machine knows (bsc::error::event_not_dispatchable).
template <class E>
inline constexpr bool reserved_event = false;
template <class S>
inline constexpr bool reserved_event<done<S>> = true;
template <>
inline constexpr bool reserved_event<action_failed> = true;
template <>
inline constexpr bool reserved_event<any_event> = true;

// The events that can be sent by name or number: the chart's, without the reserved ones.
template <class Events>
struct sendable_events;
template <class... Events>
struct sendable_events<type_list<Events...>> {
    using type = concat_t<std::conditional_t<reserved_event<Events>, type_list<>, type_list<Events>>...>;
};

template <class Events>
struct event_set_of;
template <class... Events>
struct event_set_of<type_list<Events...>> {
    static constexpr std::size_t size = sizeof...(Events);
    static constexpr std::array<std::string_view, size> names{event_name<Events>...};

    // Calls f(std::type_identity<E>{}) for the event numbered `number` (< size).
    template <class F>
    static constexpr decltype(auto) visit(std::size_t number, F&& f) {
        assert(number < size);
        return visit_from<0>(number, f);
    }

private:
    template <std::size_t I, class F>
    static constexpr decltype(auto) visit_from(std::size_t number, F& f) {
        if constexpr (I + 1 < size) {
            if (number != I) return visit_from<I + 1>(number, f);
        }
        return f(std::type_identity<at<I, type_list<Events...>>>{});
    }
};

// Reports the first two events of the list with the same name; true either way, so that the
// static_assert that calls it adds no error of its own.
template <class... Events>
constexpr bool check_event_names(type_list<Events...>) {
    constexpr auto duplicate = duplicate_event_name<Events...>();
    if constexpr (duplicate.first >= 0)
        report<error::duplicate_event_name<at<static_cast<std::size_t>(duplicate.first), type_list<Events...>>,
                                           at<static_cast<std::size_t>(duplicate.second), type_list<Events...>>>>();
    return true;
}

}  // namespace detail

/// The events of Chart, named and numbered at compile time (see the top of this header).
/// Requirements: no two events of the chart have the same event_name.
template <class Chart>
struct event_set {
private:
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    using sendable = typename detail::sendable_events<typename model::events>::type;
    using base = detail::event_set_of<sendable>;
    static_assert(detail::check_event_names(sendable{}));

public:
    /// The events the environment may send, as a type list in number order: the chart's trigger
    /// events without bsc::done<S>, bsc::action_failed and bsc::any_event.
    using events = sendable;
    /// How many they are.
    static constexpr std::size_t size = base::size;
    /// Their names, by number.
    static constexpr std::array<std::string_view, size> names = base::names;

    /// The number of event E (bsc::error::not_an_event_of_the_chart if E is none of `events`).
    template <class E>
    static constexpr std::size_t number_of = [] {
        constexpr int n = detail::position_in<E, sendable>::value;
        if constexpr (n < 0) detail::report<error::not_an_event_of_the_chart<E>>();
        return static_cast<std::size_t>(n < 0 ? 0 : n);
    }();

    /// The number of the event called `name` (exactly, case included), or nothing.
    static constexpr std::optional<std::size_t> find(std::string_view name) {
        for (std::size_t i = 0; i < size; ++i)
            if (names[i] == name) return i;
        return std::nullopt;
    }

    /// Why `name` names no event: "no event of this chart is named 'X'; its events are A, B, C".
    static std::string unknown(std::string_view name) {
        std::string text = "no event of this chart is named '";
        text.append(name).append(size == 0 ? "'; it has no events" : "'; its events are ");
        for (std::size_t i = 0; i < size; ++i) text.append(i == 0 ? "" : ", ").append(names[i]);
        return text;
    }

    /// Calls f(std::type_identity<E>{}) for the event numbered `number`.
    /// Requirements: number < size.
    template <class F>
    static constexpr decltype(auto) visit(std::size_t number, F&& f) {
        return base::visit(number, f);
    }
};

}  // namespace bsc
