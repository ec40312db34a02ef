#pragma once
// The machine's view of a context's data model: it latches input channels, commits output
// channels and updates timers, wherever they are in the context: as its members, or inside
// members that are aggregates or std::arrays, at any depth. Members that hold none cost
// nothing, and a context with none is not visited at all.

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/fields.hpp>

namespace bsc::detail {

template <class T>
inline constexpr bool is_std_array = false;
template <class T, std::size_t N>
inline constexpr bool is_std_array<std::array<T, N>> = true;

template <class T>
inline constexpr bool is_timer = std::is_base_of_v<timer_base, T>;

// A member the machine looks into: an aggregate class that is neither a channel, a timer nor
// a std::array (which is visited element by element).
template <class T>
inline constexpr bool is_visited_aggregate =
    std::is_class_v<T> && std::is_aggregate_v<T> && !is_channel<T> && !is_timer<T> && !is_std_array<T>;

struct channel_points {
    template <class T>
    static constexpr bool is_point = is_channel<T>;
};
struct timer_points {
    template <class T>
    static constexpr bool is_point = is_timer<T>;
};

// Whether T holds a point of the kind (a channel, a timer) at any depth.
template <class Points, class T>
constexpr bool holds_points() {
    if constexpr (Points::template is_point<T>)
        return true;
    else if constexpr (is_std_array<T>)
        return holds_points<Points, typename T::value_type>();
    else if constexpr (is_visited_aggregate<T>)
        return []<class... Fields>(std::tuple<Fields&...>*) {
            return (holds_points<Points, std::remove_cv_t<Fields>>() || ...);
        }(static_cast<decltype(tie_fields(std::declval<T&>()))*>(nullptr));
    else
        return false;
}

// Calls f(point) for each point of the kind in t, in declaration order, depth first.
template <class Points, class T, class F>
#if defined(__clang__)
[[gnu::always_inline]]  // as detail::apply_to_fields (detail/fields.hpp)
#endif
constexpr void for_each_point(T& t, F const& f) {
    if constexpr (Points::template is_point<T>) {
        f(t);
    } else if constexpr (!holds_points<Points, T>()) {
        return;
    } else if constexpr (is_std_array<T>) {
        for (auto& element : t) for_each_point<Points>(element, f);
    } else {
        for_each_field(t, [&](auto& field) { for_each_point<Points>(field, f); });
    }
}

template <class Ctx>
inline constexpr bool has_channels = holds_points<channel_points, Ctx>();
template <class Ctx>
inline constexpr bool has_timers = holds_points<timer_points, Ctx>();

template <class Ctx>
constexpr void latch_inputs(Ctx& ctx) {
    if constexpr (has_channels<Ctx>)
        for_each_point<channel_points>(ctx, [](auto& channel) { access::latch(channel); });
}

template <class Ctx>
constexpr void commit_outputs(Ctx& ctx) {
    if constexpr (has_channels<Ctx>)
        for_each_point<channel_points>(ctx, [](auto& channel) { access::commit(channel); });
}

template <class Ctx>
constexpr void update_timers(Ctx& ctx, duration now) {
    if constexpr (has_timers<Ctx>)
        for_each_point<timer_points>(ctx, [now](auto& timer) { access::update(timer, now); });
}

}  // namespace bsc::detail
