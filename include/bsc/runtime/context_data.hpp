#pragma once
// The machine's view of a context's data model: it latches input channels, commits output
// channels and updates timers by visiting the context's members. A context that is not an
// aggregate, or has no channel or timer, costs nothing.

#include <tuple>
#include <type_traits>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/fields.hpp>

namespace bsc::detail {

template <class Tuple>
struct field_kinds;
template <class... Fields>
struct field_kinds<std::tuple<Fields&...>> {
    static constexpr bool channels = (is_channel<std::remove_cv_t<Fields>> || ...);
    static constexpr bool timers = (std::is_base_of_v<timer_base, std::remove_cv_t<Fields>> || ...);
};

template <class Ctx>
constexpr auto context_field_kinds() {
    if constexpr (std::is_aggregate_v<Ctx> && !std::is_array_v<Ctx>)
        return field_kinds<decltype(tie_fields(std::declval<Ctx&>()))>{};
    else
        return field_kinds<std::tuple<>>{};
}

template <class Ctx>
inline constexpr bool has_channels = decltype(context_field_kinds<Ctx>())::channels;
template <class Ctx>
inline constexpr bool has_timers = decltype(context_field_kinds<Ctx>())::timers;

template <class Ctx>
constexpr void latch_inputs(Ctx& ctx) {
    if constexpr (has_channels<Ctx>)
        for_each_field(ctx, [](auto& f) {
            if constexpr (is_channel<std::remove_cvref_t<decltype(f)>>) access::latch(f);
        });
}

template <class Ctx>
constexpr void commit_outputs(Ctx& ctx) {
    if constexpr (has_channels<Ctx>)
        for_each_field(ctx, [](auto& f) {
            if constexpr (is_channel<std::remove_cvref_t<decltype(f)>>) access::commit(f);
        });
}

template <class Ctx>
constexpr void update_timers(Ctx& ctx, duration now) {
    if constexpr (has_timers<Ctx>)
        for_each_field(ctx, [now](auto& f) {
            if constexpr (std::is_base_of_v<timer_base, std::remove_cvref_t<decltype(f)>>) access::update(f, now);
        });
}

}  // namespace bsc::detail
