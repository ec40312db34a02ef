#pragma once
// The machine's view of a context's data model: it latches input channels, commits output
// channels and updates timers, wherever they are in the context (detail/members.hpp walks it:
// members, aggregates, std::arrays, types described by bsc::fields, at any depth; transient
// members too, since their channels and timers still run). Members that hold none cost
// nothing, and a context with none is not visited at all.

#include <type_traits>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/members.hpp>
#include <bsc/duration.hpp>

namespace bsc::detail {

// Calls act(point) for each channel (Channels) or each timer of a context, transient members'
// included.
template <bool Channels, class Act>
struct point_visitor {
    static constexpr bool all = true;
    template <class T>
    static constexpr bool visits = Channels ? is_channel<T> : is_timer<T>;
    Act act;
    template <class Point>
    constexpr void leaf(Point& point, no_name) const {
        act(point);
    }
};

struct latch_act {
    template <class Channel>
    constexpr void operator()(Channel& c) const {
        access::latch(c);
    }
};
struct commit_act {
    template <class Channel>
    constexpr void operator()(Channel& c) const {
        access::commit(c);
    }
};
struct update_act {
    duration now;
    template <class Timer>
    constexpr void operator()(Timer& t) const {
        access::update(t, now);
    }
};
using latch_visitor = point_visitor<true, latch_act>;
using update_visitor = point_visitor<false, update_act>;

template <class Ctx>
inline constexpr bool has_channels = reaches<latch_visitor, Ctx>();
template <class Ctx>
inline constexpr bool has_timers = reaches<update_visitor, Ctx>();

template <class Ctx>
constexpr void latch_inputs(Ctx& ctx) {
    latch_visitor const v{};
    walk(ctx, v);
}

template <class Ctx>
constexpr void commit_outputs(Ctx& ctx) {
    point_visitor<true, commit_act> const v{};
    walk(ctx, v);
}

template <class Ctx>
constexpr void update_timers(Ctx& ctx, duration now) {
    update_visitor const v{{now}};
    walk(ctx, v);
}

}  // namespace bsc::detail
