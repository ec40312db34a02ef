#pragma once
// BSC timers (seed 002, section III.C): data in the context, started or reset by actions,
// updated by the machine at the beginning of each cycle. A timer started during cycle k begins
// timing at cycle k+1; its expired flag `tm()` turns true at the first cycle whose time is at
// least the limit after that.

#include <chrono>
#include <cstdint>

namespace bsc {

/// The machine's notion of time: a duration since an arbitrary origin, given to step(now).
using duration = std::chrono::nanoseconds;

namespace detail {
struct timer_base {};
struct timer_access;
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
    }
    /// Stops the timer and clears tm().
    constexpr void reset() {
        phase_ = phase::idle;
        expired_ = false;
    }
    /// The paper's `tm`: the limit has been reached or passed.
    constexpr bool tm() const { return expired_; }
    constexpr bool expired() const { return expired_; }
    constexpr bool running() const { return phase_ == phase::running && !expired_; }
    constexpr duration limit() const { return limit_; }
    /// Time since timing began (zero unless running or expired).
    constexpr duration elapsed() const { return elapsed_; }

    /// Called by the machine at the beginning of each cycle with the cycle's time.
    constexpr void update(duration now) {
        if (phase_ == phase::pending) {
            phase_ = phase::running;
            started_ = now;
        }
        if (phase_ == phase::running) {
            elapsed_ = now - started_;
            if (elapsed_ >= limit_) expired_ = true;
        } else {
            elapsed_ = duration::zero();
        }
    }

    friend constexpr bool operator==(timer const& a, timer const& b) {
        return a.limit_ == b.limit_ && a.started_ == b.started_ && a.elapsed_ == b.elapsed_ &&
               a.phase_ == b.phase_ && a.expired_ == b.expired_;
    }

private:
    friend struct detail::timer_access;
    enum class phase : std::uint8_t { idle, pending, running };
    duration limit_{};
    duration started_{};
    duration elapsed_{};
    phase phase_ = phase::idle;
    bool expired_ = false;
};

namespace detail {
// Read-write access to a timer's state, for the state-space explorer only.
struct timer_access {
    static constexpr std::uint8_t phase(timer const& t) { return static_cast<std::uint8_t>(t.phase_); }
    static constexpr duration started(timer const& t) { return t.started_; }
    static constexpr void set(timer& t, std::uint8_t phase, bool expired, duration started, duration elapsed) {
        t.phase_ = static_cast<timer::phase>(phase);
        t.expired_ = expired;
        t.started_ = started;
        t.elapsed_ = elapsed;
    }
};
}  // namespace detail

}  // namespace bsc
