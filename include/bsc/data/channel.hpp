#pragma once
// Data channels of a Basic Statechart (the Basic Statechart paper [BSC], docs/references.md):
// the context's members through which a chart talks to its environment and to other charts.
// Plain members of the context are the chart's internal variables: an action's write is visible
// at once to every later guard.

#include <type_traits>
#include <utility>

#include <bsc/detail/access.hpp>

namespace bsc::detail {
// Lets the machine find channels among the context's members. Equal to any other, so that
// the channels' defaulted == compare their values.
struct channel_base {
    friend constexpr bool operator==(channel_base const&, channel_base const&) = default;
};
}  // namespace bsc::detail

namespace bsc {

/// An input channel: written by the environment between cycles (`set`), latched at the start
/// of each cycle (and each dispatch), so that every component of a cycle reads the same value.
/// Requirements: T is copyable.
template <class T>
class input : detail::channel_base {
public:
    constexpr input() = default;
    constexpr explicit input(T initial) : next_(initial), now_(initial) {}
    /// The latched value, as guards and actions see it during this cycle.
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    /// Written by the environment; visible from the next cycle on.
    constexpr void set(T value) { next_ = value; }
    /// The value that the next cycle will latch.
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(input const&, input const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() {}
    T next_{};
    T now_{};
};

/// An output channel, double-buffered: actions write the next value (`set`); the published
/// value (`get`) changes at the end of the cycle (or dispatch), when every component has run.
template <class T>
class output : detail::channel_base {
public:
    constexpr output() = default;
    constexpr explicit output(T initial) : next_(initial), now_(initial) {}
    /// The published value: what the environment and other charts read.
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    /// Written by actions; published at the end of the cycle.
    constexpr void set(T value) { next_ = value; }
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(output const&, output const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() {}
    constexpr void commit() { now_ = next_; }
    T next_{};
    T now_{};
};

/// A channel that is both input and output ([BSC] allows it): written by the environment or
/// by actions, read as the value latched at the start of the cycle; writes take effect at the
/// next cycle boundary.
template <class T>
class inout : detail::channel_base {
public:
    constexpr inout() = default;
    constexpr explicit inout(T initial) : next_(initial), now_(initial) {}
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    constexpr void set(T value) { next_ = value; }
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(inout const&, inout const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() { now_ = next_; }
    T next_{};
    T now_{};
};

template <class T>
inline constexpr bool is_channel = std::is_base_of_v<detail::channel_base, T>;

}  // namespace bsc

namespace bsc::detail {
// The type of a channel's value.
template <class Channel>
using channel_value = std::remove_cvref_t<decltype(std::declval<Channel const&>().get())>;
}  // namespace bsc::detail
