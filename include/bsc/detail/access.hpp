#pragma once
// The one door to what users may not touch: a channel's latch and commit, a timer's update
// and its internal state, a machine's writable context, configuration, clock, timeout slots and
// queue. Only the machines, the explorer, the retentive state (bsc/retain.hpp), the VCD
// recorder and the project's own tests go through it; every class it opens names it as its
// only friend.

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <bsc/duration.hpp>
#include <bsc/outcome.hpp>

namespace bsc::detail {

struct access {
    // ---- channels and timers: driven by the machine around each cycle and dispatch ----------
    template <class Channel>
    static constexpr void latch(Channel& c) {
        c.latch();
    }
    template <class Channel>
    static constexpr void commit(Channel& c) {
        c.commit();
    }
    // Both values of a channel at once, as a restored or decoded state has them: what it holds
    // now and what the next cycle boundary takes. (Not through set: an input's set is the
    // environment's, an output's the chart's; a restore is neither.)
    template <class Channel, class T>
    static constexpr void set_channel(Channel& c, T const& current, T const& pending) {
        c.now_ = current;
        c.next_ = pending;
    }
    template <class Timer>
    static constexpr void update(Timer& t, duration now) {
        t.update(now);
    }
    template <class Timer>
    static constexpr std::uint8_t timer_phase(Timer const& t) {
        return static_cast<std::uint8_t>(t.phase_);
    }
    template <class Timer>
    static constexpr duration timer_started(Timer const& t) {
        return t.started_;
    }
    template <class Timer>
    static constexpr void set_timer(Timer& t, std::uint8_t phase, bool expired, duration started, duration elapsed) {
        t.phase_ = static_cast<typename Timer::phase>(phase);
        t.expired_ = expired;
        t.started_ = started;
        t.elapsed_ = elapsed;
    }
    template <class Timer>
    static constexpr void set_timer_limit(Timer& t, duration limit) {
        t.limit_ = limit;
    }

    // ---- machines: read and written by the explorer, read by the tests ---------------------
    // (through the shared driver, which holds the data and names this class its friend)

    // The machine's context, writable: for what restores or decodes a machine's whole state
    // (retain, the explorer). The public context() is const: the environment's view.
    template <class M>
    static constexpr auto& context(M& m) {
        if constexpr (requires { typename std::remove_const_t<M>::driver_type; })
            return driver_of(m).context_.value;
        else
            return m.context_;  // a machine of a rejected chart (detail/runtime/rejected.hpp)
    }
    // The chart a machine runs: to build another machine of it (bsc/benchmark.hpp replays a
    // dispatch with a logger).
    template <class M>
    static constexpr auto const& chart(M const& m) {
        return driver_of(m).chart();
    }
    template <class M>
    static constexpr auto& configuration(M& m) {
        return driver_of(m).config_;
    }
    // The machine's clock (zero for a machine that keeps none: nothing it does depends on time).
    template <class M>
    static constexpr duration clock(M const& m) {
        return driver_of(m).cycle_time();
    }
    // Whether a cycle has run (the clock is the caller's time); false without a clock.
    template <class M>
    static constexpr bool clock_started(M const& m) {
        return driver_of(m).clock_started();
    }
    // Sets a machine's clock as if a cycle had run at `now` (or, started = false, as if none had).
    template <class M>
    static constexpr void set_clock(M& m, duration now, bool started = true) {
        driver_of(m).set_clock(now, started);
    }
    // Inside a dispatch, a cycle or the construction: the machine's data is in flux.
    template <class M>
    static constexpr bool running(M const& m) {
        return driver_of(m).running();
    }
    // Forgets the exception of the last failed run (a restored machine's last run was not its own).
    template <class M>
    static constexpr void forget_failure(M& m) {
        auto& d = driver_of(m);
        d.failure_.reset();
        if constexpr (requires { d.reported_.reset(); }) d.reported_.reset();
    }
    template <class M>
    static constexpr auto& armed(M& m) {
        return driver_of(m).armed_;
    }
    // The last outcome as the machine keeps it (outcome::ignored under a policy that keeps none).
    template <class M>
    static constexpr outcome last_outcome(M const& m) {
        return driver_of(m).kept_outcome();
    }
    template <class M>
    static constexpr void set_last_outcome(M& m, outcome last) {
        driver_of(m).record(last);
    }
    template <class M>
    static constexpr auto& queue(M& m) {
        return driver_of(m).queue_;
    }
    // The events a chart that defers keeps (an event_queue, or no_deferral for one that does not).
    template <class M>
    static constexpr auto& deferred(M& m) {
        return driver_of(m).deferred_;
    }
    // Whether a transition changed the configuration since the deferred events were last retried.
    template <class M>
    static constexpr bool deferral_pending_retry(M const& m) {
        if constexpr (std::remove_cvref_t<decltype(driver_of(m))>::defers)
            return driver_of(m).deferral_.changed;
        else
            return false;
    }
    template <class M>
    static constexpr void set_deferral_pending_retry(M& m, bool changed) {
        if constexpr (std::remove_cvref_t<decltype(driver_of(m))>::defers) {
            driver_of(m).deferral_.changed = changed;
            driver_of(m).deferral_.retry = 0;
        }
    }
    template <class M>
    static constexpr auto longest_timeout(M const& m) {
        return driver_of(m).longest_timeout();
    }
    template <class M>
    static constexpr auto row_delays(M const& m) {
        return driver_of(m).row_delays();
    }
    template <class M>
    static constexpr auto canonical_configuration(M const& m) {
        return driver_of(m).canonical_configuration();
    }
    template <class M>
    static constexpr bool timeout_armed(M const& m, std::size_t slot) {
        return driver_of(m).timeout_armed(slot);
    }
    template <class M>
    static constexpr auto active_flags(M const& m) {
        return driver_of(m).active_flags();
    }

private:
    template <class M>
    static constexpr auto& driver_of(M& m) {
        using driver = typename std::remove_const_t<M>::driver_type;
        if constexpr (std::is_const_v<M>)
            return static_cast<driver const&>(m);
        else
            return static_cast<driver&>(m);
    }
};

}  // namespace bsc::detail
