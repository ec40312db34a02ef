#pragma once
// The limits a machine runs under: bsc::default_policy, bsc::scan_policy, bsc::lean_policy, and
// the requirements a policy of one's own meets (bsc::machine_policy).

#include <concepts>
#include <cstddef>

namespace bsc {

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

/// What a machine reads of its policy: every member of bsc::default_policy, of its type. A
/// policy of one's own derives from bsc::default_policy and overrides members, and so meets it;
/// `bsc::machine<decltype(chart), Context, Observer, Policy>` with a Policy that does not names
/// this concept in its error, at the declaration.
template <class Policy>
concept machine_policy = requires {
    { Policy::queue_capacity } -> std::convertible_to<std::size_t>;
    { Policy::max_eventless_steps } -> std::convertible_to<std::size_t>;
    { Policy::max_internal_events } -> std::convertible_to<std::size_t>;
    { Policy::settle_eventless } -> std::convertible_to<bool>;
    { Policy::rethrow_failures } -> std::convertible_to<bool>;
    { Policy::refuse_reentry } -> std::convertible_to<bool>;
    { Policy::keep_last_outcome } -> std::convertible_to<bool>;
    { Policy::keep_clock } -> std::convertible_to<bool>;
};

}  // namespace bsc
