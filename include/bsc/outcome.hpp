#pragma once
// What a run reports: the outcome of a dispatch, the report of a cycle; and the tag that lets
// a dispatch ignore an event no transition handles.

#include <cstddef>
#include <cstdint>

#include <bsc/policies.hpp>  // the policies, which bsc 0.1 declared here

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
