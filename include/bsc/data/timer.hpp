#pragma once
// BSC timers (the Basic Statechart paper [BSC] in docs/references.md, section III.C): data in
// the context, started or reset by actions, updated by the machine at the beginning of each
// cycle. A timer started during cycle k begins timing at cycle k+1; its expired flag `tm()` turns
// true at the first cycle whose time is at least the limit after that.

#include <cstdint>

#include <bsc/detail/access.hpp>
#include <bsc/duration.hpp>

namespace bsc {

namespace detail {
struct timer_base {};
}  // namespace detail

/// A timer with a fixed limit. Requirements: limit >= 0.
class timer : detail::timer_base {
public:
    constexpr timer() = default;
    constexpr explicit timer(duration limit) : limit_(limit) {}

    /// Starts (or restarts) the timer; timing begins at the next cycle. Clears tm().
    constexpr void start() {
        phase_ = phase::pending;
        expired_ = false;
        elapsed_ = duration::zero();
    }
    /// Stops the timer and clears tm() and elapsed().
    constexpr void reset() {
        phase_ = phase::idle;
        expired_ = false;
        elapsed_ = duration::zero();
    }
    /// The paper's `tm`: the limit has been reached or passed.
    constexpr bool tm() const { return expired_; }
    constexpr bool expired() const { return expired_; }
    constexpr bool running() const { return phase_ == phase::running && !expired_; }
    constexpr duration limit() const { return limit_; }
    /// Time since timing began (zero unless running or expired).
    constexpr duration elapsed() const { return elapsed_; }

    friend constexpr bool operator==(timer const& a, timer const& b) {
        return a.limit_ == b.limit_ && a.started_ == b.started_ && a.elapsed_ == b.elapsed_ && a.phase_ == b.phase_ &&
               a.expired_ == b.expired_;
    }

private:
    friend struct detail::access;  // the machine updates it; the explorer encodes it
    // Called by the machine at the beginning of each cycle with the cycle's time.
    constexpr void update(duration now) {
        if (phase_ == phase::pending) {
            phase_ = phase::running;
            started_ = now;
        }
        if (phase_ == phase::running) {
            elapsed_ = detail::elapsed(started_, now);
            if (elapsed_ >= limit_) expired_ = true;
        } else {
            elapsed_ = duration::zero();
        }
    }

    enum class phase : std::uint8_t { idle, pending, running };
    duration limit_{};
    duration started_{};
    duration elapsed_{};
    phase phase_ = phase::idle;
    bool expired_ = false;
};

}  // namespace bsc
