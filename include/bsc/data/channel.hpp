#pragma once
// Data channels of a Basic Statechart (the Basic Statechart paper [BSC], docs/references.md):
// the context's members through which a chart talks to its environment and to other charts.
// Plain members of the context are the chart's internal variables: an action's write is visible
// at once to every later guard.
//
// Who writes what follows the formalism, and the types say it: inputs are the plant's (the
// environment's), outputs the chart's. The environment holds a machine's context as const
// (machine::context() returns a const reference), the chart's actions receive it as non-const
// (Context&), and each channel's `set` is const or not accordingly:
//   bsc::input<T>   set(v) const: the environment writes; an action's write is a compile error
//                   (bsc::error::input_written_by_the_chart)
//   bsc::output<T>  set(v): actions write; the environment's write is a compile error
//                   (bsc::error::output_written_from_outside)
//   bsc::inout<T>   set(v) const: both write
// A channel's initial value is given by its constructor (bsc::input<bool> start{true}), not by a
// write before the machine runs.

#include <type_traits>
#include <utility>

#include <bsc/detail/access.hpp>
#include <bsc/error.hpp>

namespace bsc::detail {
// Lets the machine find channels among the context's members. Equal to any other, so that
// the channels' defaulted == compare their values.
struct channel_base {
    friend constexpr bool operator==(channel_base const&, channel_base const&) = default;
};

// The pending value of an input or inout, writable through the const context the environment
// holds: mutable storage. It is not declared `mutable` because GCC (12 at least) refuses to read
// a mutable member in constant evaluation, even of an object created there, and a machine with
// an input could then no longer run in a static_assert. Writing through the const view is
// defined: the channel itself is not a const object (a machine's context is not; only the view
// of it that context() returns is), so an input must not be set on a context or a machine
// declared const.
template <class T>
constexpr T& wire(T const& pending) {
    return const_cast<T&>(pending);  // NOLINT(cppcoreguidelines-pro-type-const-cast)
}
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
    /// Written by the environment (which holds the machine's context as const) and by the links
    /// of a bsc::system; visible from the next cycle on.
    constexpr void set(T value) const { detail::wire(next_) = value; }
    /// Chosen for a non-const input, whatever the argument: the chart's actions receive the
    /// context as non-const, and a chart does not write its own inputs. A compile error.
    template <class U = T>
    constexpr void set(U&&) {
        detail::report<error::input_written_by_the_chart<T>>();
    }
    /// The value that the next cycle will latch.
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(input const&, input const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() {}
    // The pending value is the plant's wire, not the machine's state, until the next cycle
    // latches it: the environment writes it through the const context it holds, so it is
    // mutable storage (detail::wire). What the chart reads (now_) changes only when the
    // machine latches.
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
    /// Chosen for a const output: the environment holds the machine's context as const, and
    /// only the chart writes its outputs. A compile error. (The parameter is T, as the action's
    /// overload's, so that a non-const output always takes that one, whatever the argument.)
    template <class U = T>
    constexpr void set(std::type_identity_t<U>) const {
        detail::report<error::output_written_from_outside<T>>();
    }
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
/// by actions (`set` works on the const context and on the non-const one), read as the value
/// latched at the start of the cycle; writes take effect at the next cycle boundary.
template <class T>
class inout : detail::channel_base {
public:
    constexpr inout() = default;
    constexpr explicit inout(T initial) : next_(initial), now_(initial) {}
    constexpr T const& get() const { return now_; }
    constexpr operator T const&() const { return now_; }  // NOLINT
    constexpr void set(T value) const { detail::wire(next_) = value; }
    constexpr T const& pending() const { return next_; }
    friend constexpr bool operator==(inout const&, inout const&) = default;

private:
    friend struct detail::access;  // the machine latches and commits
    constexpr void latch() { now_ = next_; }
    constexpr void commit() { now_ = next_; }
    // Mutable storage as an input's (detail::wire): the environment writes it through the const
    // context.
    T next_{};
    T now_{};
};

template <class T>
inline constexpr bool is_channel = std::is_base_of_v<detail::channel_base, T>;

}  // namespace bsc

namespace bsc::detail {
// Channel kinds: bsc::input, bsc::output, bsc::inout (each only itself).
template <class T>
inline constexpr bool is_input_channel = false;
template <class T>
inline constexpr bool is_input_channel<input<T>> = true;
template <class T>
inline constexpr bool is_output_channel = false;
template <class T>
inline constexpr bool is_output_channel<output<T>> = true;
template <class T>
inline constexpr bool is_inout_channel = false;
template <class T>
inline constexpr bool is_inout_channel<inout<T>> = true;

// The type of a channel's value.
template <class Channel>
using channel_value = std::remove_cvref_t<decltype(std::declval<Channel const&>().get())>;
}  // namespace bsc::detail
