#pragma once
// What a program that runs or shows a bsc::system knows of it at compile time: the actors in
// their order, with their names; the links with their ends' places and channel names. Used by
// bsc::net::node and bsc::system_inspector.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/detail/member_names.hpp>
#include <bsc/system.hpp>

namespace bsc::detail {

template <std::size_t I, auto... Members>
struct nth_member;
template <auto First, auto... Rest>
struct nth_member<0, First, Rest...> {
    static constexpr auto value = First;
};
template <std::size_t I, auto First, auto... Rest>
struct nth_member<I, First, Rest...> : nth_member<I - 1, Rest...> {};

template <class System>
struct system_plan {
    static_assert(sizeof(System) == 0, "System must be a bsc::system<Actors, bsc::order<...>, links...>");
};

template <class Actors, auto... Steps, class... Entries>
struct system_plan<system<Actors, order<Steps...>, Entries...>> {
    // The links only: a system's bsc::from_outside entries are the environment's business.
    using links = typename system<Actors, order<Steps...>, Entries...>::links_type;
    static constexpr std::size_t actor_count = sizeof...(Steps);
    static constexpr std::size_t link_count = std::tuple_size_v<links>;
    static constexpr std::array<std::string_view, actor_count> names{member_name<Steps>()...};

    template <auto Actor>
    static constexpr std::size_t place() {
        std::size_t i = 0, found = actor_count;
        ((same_member_pointer<Actor, Steps>() ? (found = i, ++i) : ++i), ...);
        return found;
    }
    template <std::size_t I>
    static constexpr auto step_at = nth_member<I, Steps...>::value;
    template <std::size_t I>
    using machine_at = std::remove_cvref_t<decltype(std::declval<Actors&>().*nth_member<I, Steps...>::value)>;

    // What link L carries over the network: the source's value, as its publisher published it
    // (the consumer's side applies the link's bsc::convert).
    template <class L>
    using value_of = channel_value<
        std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::from_actor).context()).*L::from_channel)>>;
    // What the consumer of link L reads: its input's value type.
    template <class L>
    using target_value_of =
        channel_value<std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::to_actor).context()).*L::to_channel)>>;

    // (Every actor a link names is in the order: bsc::system checks it.)
    // clang-format off
    static constexpr std::array<std::size_t, link_count> from = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::from_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<std::size_t, link_count> to = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::to_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<bool, link_count> lossless = []<class... L>(std::tuple<L...>*) {
        return std::array<bool, link_count>{std::is_same_v<typename L::when_stale, bsc::lossless>...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // The name of a channel in its actor's context; empty where the context is not an aggregate
    // (one described by bsc::fields: its members' names are not known here).
    template <auto Channel>
    static constexpr std::string_view channel_name() {
        if constexpr (std::is_aggregate_v<decltype(class_of_member(Channel))>)
            return member_name<Channel>();
        else
            return {};
    }
    // The channels each link joins, by their names.
    static constexpr std::array<std::string_view, link_count> from_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::from_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
    static constexpr std::array<std::string_view, link_count> to_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::to_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
};

}  // namespace bsc::detail
