#pragma once
// What dispatch reports, and the limits a machine runs under.

#include <cstddef>
#include <cstdint>

namespace bsc {

/// The result of dispatching one event (run to completion, internal events included).
enum class outcome : std::uint8_t {
    consumed,        ///< at least one transition fired for the dispatched event
    ignored,         ///< no transition was enabled; the event was discarded (SCXML semantics)
    queue_overflow,  ///< an action raised an event while the internal queue was full; that event was dropped
    livelock,        ///< the eventless-step or internal-event limit was reached; the rest was abandoned
    halted,          ///< the machine had reached a final child of its root; nothing was processed
    reentrant,       ///< called from inside one of the machine's own guards or actions: refused, nothing changed
    failed,          ///< a guard or action threw and no transition took the bsc::action_failed event (the
                     ///< policy's rethrow_failures is false; last_failure() holds the exception)
    unknown_event,   ///< dispatch_by_name or dispatch_by_number named no event of the chart: nothing was
                     ///< processed (bsc::event_set<Chart>::unknown(name) says why)
};

/// The limits of a machine. Derive from it and override a member to change one:
/// `struct my_limits : bsc::default_policy { static constexpr std::size_t queue_capacity = 32; };`
struct default_policy {
    /// Events an action may raise before the queue is drained; one more is an overflow.
    static constexpr std::size_t queue_capacity = 8;
    /// Events a machine keeps deferred (`/ bsc::defer`) at once; one more is an overflow. Read
    /// only for a chart with a deferring row.
    static constexpr std::size_t deferred_capacity = 8;
    /// Events sent with bsc::raise_after pending at once; one more is an overflow. Read only for
    /// a chart whose actions send delayed events.
    static constexpr std::size_t delayed_capacity = 8;
    /// Eventless transitions taken in a row before dispatch reports a livelock.
    static constexpr std::size_t max_eventless_steps = 64;
    /// Internal events processed within one dispatch before it reports a livelock.
    static constexpr std::size_t max_internal_events = 256;
    /// true (SCXML): construction and dispatch take eventless transitions until none is
    /// enabled. false (BSC scan): eventless transitions are taken only by step(), at most one
    /// per component per cycle.
    static constexpr bool settle_eventless = true;
    /// What happens to an exception from a guard or action that no transition takes as a
    /// bsc::action_failed event: true, dispatch() or step() rethrows it once the machine is
    /// consistent (and the constructor, for an entry action); false, they return
    /// outcome::failed and last_failure() holds it.
    static constexpr bool rethrow_failures = true;
    /// true: a dispatch or step called from inside the machine's own guards, actions or
    /// observer hooks is refused (outcome::reentrant). false: the caller promises that none
    /// is; the machine does not test for it, and one that is called is undefined behaviour (a
    /// run starts from an empty queue, which the optimiser is told; builds without NDEBUG
    /// check it with an assertion).
    static constexpr bool refuse_reentry = true;
    /// true: the machine keeps each run's outcome for last_outcome(). false: it keeps nothing
    /// (dispatch and step still return it); last_outcome() and last_failure() do not compile.
    static constexpr bool keep_last_outcome = true;
    /// true: every machine keeps the time of its last cycle, for now() and for
    /// step_report::clock_went_backwards. false: only a machine whose chart needs time keeps it
    /// (a timeout row, a bsc::timer in the context, a delayed event); in the others now() does
    /// not compile, clock_went_backwards stays false, and the machine is smaller by the clock
    /// and its flag (8 bytes and 1, with their padding). bsc::vcd_recorder reads now().
    static constexpr bool keep_clock = true;
};

/// The limits of a machine driven by BSC execution cycles (the Basic Statechart paper [BSC],
/// docs/references.md): eventless transitions are condition-driven and run only in step(), so a
/// chart whose components keep reacting to each other (a PLC scan loop) neither livelocks at
/// construction nor in dispatch.
struct scan_policy : default_policy {
    static constexpr bool settle_eventless = false;
};

/// The policy of a machine with nothing but the chart's own work: no test for a reentrant
/// call, no record of the last outcome, and no clock unless the chart needs time
/// (docs/performance.md, rule "A lean machine is the chart's own work": on a flat chart with
/// noexcept actions, a dispatch is then as short as a hand-written switch, and the machine is
/// its configuration and its context). For code whose guards, actions and observer never call the machine back, that
/// reads each outcome from dispatch's return value, and that keeps its own time.
struct lean_policy : default_policy {
    static constexpr bool refuse_reentry = false;
    static constexpr bool keep_last_outcome = false;
    static constexpr bool keep_clock = false;
};

/// What one BSC execution cycle (`step(now)`) did, on either back end.
struct step_report {
    outcome status = outcome::ignored;  ///< consumed if any transition fired in the cycle
    int transitions = 0;                ///< condition-driven transitions fired by the components
    bool clock_went_backwards = false;  ///< `now` was earlier than the previous cycle's time
};

/// Tag for dispatch(e, bsc::allow_unhandled): dispatching an event type that no transition
/// handles is then allowed (and ignored) instead of failing to compile.
struct allow_unhandled_t {
    explicit allow_unhandled_t() = default;
};
inline constexpr allow_unhandled_t allow_unhandled{};

}  // namespace bsc
