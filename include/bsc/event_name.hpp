#pragma once
// The name of an event type, as bsc::event_set, dispatch_by_name and bsc::logger use it.

#include <concepts>
#include <string_view>
#include <type_traits>

#include <bsc/detail/type_name.hpp>

namespace bsc {

namespace detail {
// A static member `name` (a data member called name, e.g. `std::string name;` in an event that
// carries a name as data, is not the event's name).
template <class E>
concept names_itself = requires {
    requires std::convertible_to<decltype(E::name), std::string_view>;
    requires !std::is_member_object_pointer_v<decltype(&E::name)>;
};
}  // namespace detail

/// The name of event type E: its static member `name` if it declares one
/// (`static constexpr std::string_view name = "ON_P";`), otherwise bsc::name_of<E>.
template <class E>
inline constexpr std::string_view event_name = [] {
    if constexpr (detail::names_itself<E>)
        return std::string_view{E::name};
    else
        return name_of<E>;
}();

}  // namespace bsc
