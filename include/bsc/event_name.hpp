#pragma once
// The name of an event type, as bsc::event_set, dispatch_by_name and bsc::logger use it.

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>
#include <type_traits>

#include <bsc/detail/type_name.hpp>
#include <bsc/events.hpp>

namespace bsc {

namespace detail {
// A static member `name` (a data member called name, e.g. `std::string name;` in an event that
// carries a name as data, is not the event's name).
template <class E>
concept names_itself = requires {
    requires std::convertible_to<decltype(E::name), std::string_view>;
    requires !std::is_member_object_pointer_v<decltype(&E::name)>;
};

// "done.state." and the state's name, in static storage.
template <class S>
inline constexpr auto done_event_text = [] {
    constexpr std::string_view prefix = "done.state.";
    constexpr std::string_view state = name_of<S>;
    std::array<char, prefix.size() + state.size()> text{};
    std::size_t n = 0;
    for (char c : prefix) text[n++] = c;
    for (char c : state) text[n++] = c;
    return text;
}();
}  // namespace detail

/// The name of event type E: its static member `name` if it declares one
/// (`static constexpr std::string_view name = "ON_P";`), otherwise bsc::name_of<E>. SCXML's
/// names for the two events bsc defines: "done.state.S" for bsc::done<S>, "*" for
/// bsc::any_event.
template <class E>
inline constexpr std::string_view event_name = [] {
    if constexpr (detail::names_itself<E>)
        return std::string_view{E::name};
    else
        return name_of<E>;
}();
template <class S>
inline constexpr std::string_view event_name<done<S>> = {detail::done_event_text<S>.data(),
                                                         detail::done_event_text<S>.size()};
template <>
inline constexpr std::string_view event_name<any_event> = "*";

}  // namespace bsc
