#pragma once
// bsc::action_failed: the event a machine raises when one of its guards or actions throws.

#include <exception>

namespace bsc {

/// What a machine puts on its internal queue when a guard, an action, an entry or an exit
/// action throws (W3C SCXML's error.execution): the rest of that callable is skipped, the
/// microstep completes, and this event carries the exception. A chart handles it with
/// ordinary rows, e.g. `state<Running> + event<bsc::action_failed> = state<Fault>`. A failure
/// that no transition takes is the caller's: dispatch() or step() rethrows it once the machine
/// is consistent (or reports outcome::failed, as the policy says).
struct action_failed {
    std::exception_ptr error;
};

}  // namespace bsc
