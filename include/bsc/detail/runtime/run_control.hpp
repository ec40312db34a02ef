#pragma once
// A run's bracket and its failures: the mark of a run under way (the refusal of a reentrant
// call), the guarded call of a guard or action, what a failure becomes (bsc::action_failed on
// the queue, or kept for the caller), and the end of a run (the outcome recorded, a kept failure
// rethrown or reported). A layer of the driver (detail/runtime/driver.hpp).

#include <exception>
#include <utility>

#include <bsc/detail/assume.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/runtime/explorer_queries.hpp>
#include <bsc/events.hpp>
#include <bsc/outcome.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class run_control : public explorer_queries<Backend, Chart, Policy, Observer, Queue> {
    using base = explorer_queries<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::completion;
    using typename base::run_status;
    using base::may_throw;
    using base::running_bit;
    using base::failed_bit;
    using base::bits;
    using base::status_;
    using base::queue_;
    using base::failure_;
    using base::reported_;
    using base::entering_;

    // back end that says so (Backend::marks_running_lazily), from the first guard or transition
    // it is about to run (the back end calls mark_running() there): only guards, actions and
    // the observer can call the machine back, and a dispatch that runs none of them (an
    // ignored event) then never writes the mark.
    constexpr bool running() const {
        if constexpr (Policy::refuse_reentry)
            return (bits(status_) & running_bit) != 0;
        else
            return false;  // the caller's promise: never called back
    }
    constexpr void mark_running() {
        if constexpr (Policy::refuse_reentry) status_ = static_cast<run_status>(bits(status_) | running_bit);
    }
    // The outcome of the last run as kept (outcome::ignored if the policy keeps none).
    constexpr outcome kept_outcome() const { return static_cast<outcome>(bits(status_) & ~(running_bit | failed_bit)); }

    // Evaluates guard(args...) (true if it holds) or calls action(args...): what either throws
    // goes to fail(), and a guard that throws does not hold (SCXML: a condition that raises an
    // error is false). The callable and its arguments come separately, not as a lambda around
    // the call, and the try blocks are written out, not handed a handler as the table engine's
    // run_block is: two functions less to instantiate for every guard and action of the chart
    // (three: the arguments are forwarded with a cast, not with std::forward).
    template <class Guard, class... Args>
    constexpr bool test(Guard const& guard, Args&&... args) {
#if defined(__cpp_exceptions)
        try {
            return static_cast<bool>(guard(static_cast<Args&&>(args)...));
        } catch (...) {
            fail(std::current_exception());
            return false;
        }
#else
        return static_cast<bool>(guard(static_cast<Args&&>(args)...));
#endif
    }
    template <class Action, class... Args>
    constexpr void run(Action const& action, Args&&... args) {
#if defined(__cpp_exceptions)
        try {
            action(static_cast<Args&&>(args)...);
        } catch (...) {
            fail(std::current_exception());
        }
#else
        action(static_cast<Args&&>(args)...);
#endif
    }
    // The same, for code that knows the machine only by address (the table engine's thunks).
    failure_sink sink() {
        return {this, [](void* machine, std::exception_ptr error) {
                    static_cast<run_control*>(machine)->fail(std::move(error));
                }};
    }

    // Whether the chart takes bsc::action_failed: then failures go on the internal queue.
    static constexpr bool takes_failures = model::template trigger_of<action_failed>::value >= 0;

    // A guard or action threw: raise bsc::action_failed if the chart takes it (and the queue
    // has room), else keep it for the caller. (Where nothing can throw, nothing gets here: a
    // noexcept function that throws has already ended the program.)
    // (noexcept: what could throw here is recording a failure, an allocation; the program then
    // ends, as it would if a destructor threw while unwinding.)
    void fail(std::exception_ptr error) noexcept {
        if constexpr (may_throw) {
            if constexpr (takes_failures)
                if (queue_(action_failed{error})) return;
            keep_failure(std::move(error));
        } else {
            (void)error;
            std::terminate();
        }
    }
    void keep_failure(std::exception_ptr error) noexcept {
        if constexpr (may_throw) {
            failure_.keep(std::move(error));
            status_ = static_cast<run_status>(bits(status_) | failed_bit);
        } else {
            (void)error;
        }
    }

    // The end of a run, the machine consistent and its outputs committed: records the outcome
    // (which ends the run), and then rethrows a failure no transition took, or reports it as
    // outcome::failed.
    constexpr outcome end_run(outcome result) {
        // (A test of the status byte, not of failure_: where every guard and action of the run
        // is inlined and cannot throw, the compiler sees that nothing set the bit, and the test
        // is gone; see start_without_failure.)
        if constexpr (may_throw)
            if ((bits(status_) & failed_bit) != 0) [[unlikely]]
                return failed_run(result);
        return record(result);  // where nothing can throw nothing can have failed: no test
    }
    outcome failed_run(outcome result) {
        // (Cleared here too: a policy that keeps no outcome has record() write nothing.)
        status_ = static_cast<run_status>(bits(status_) & ~failed_bit);
        if constexpr (Policy::rethrow_failures) {
            record(result);
            std::rethrow_exception(failure_.take());
        } else {
            report_failure(failure_.take());
            return record(outcome::failed);
        }
    }
    // (noexcept, as fail(): keeping a failure allocates, and running out of memory there ends
    // the program rather than leave the machine marked running for good.)
    void report_failure(std::exception_ptr error) noexcept {
        reported_.reset();
        reported_.keep(std::move(error));
    }

    // A dispatch starts with failed_bit clear: every end of a run clears it (record,
    // end_run_by_exception) and only a run sets it, inside the running mark, which a dispatch
    // has just found clear. Said to the compiler, so that where every guard and action of the
    // run is inlined and cannot throw it sees that nothing set the bit, and end_run's test is
    // gone. GCC takes it as a range it may assume (it follows a range through the bit tests);
    // Clang, which drops an assumption at the first join of paths, and any compiler not known
    // to follow one (BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS, detail/config.hpp), as a store of the
    // cleared byte, which merges with the running mark or the recorded outcome. (Only where
    // the running mark is kept: a policy without it never reads the byte at the start.) A
    // machine assigned to from inside its own run loses its running mark mid-run and breaks
    // this, as it breaks run to completion: docs/semantics.md, "Reentrancy", says not to.
    constexpr void start_without_failure() {
        if constexpr (may_throw && Policy::refuse_reentry) {
#if BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS
            detail::assume(bits(status_) < failed_bit);
#else
            status_ = static_cast<run_status>(bits(status_) & ~failed_bit);
#endif
        }
    }

    // A run starts with the queue idle (event_queue.hpp, assume_idle): said to the optimiser.
    // It holds unless the machine is called back from inside its own run under a policy that
    // does not refuse it, or copied, assigned to or destroyed there (docs/semantics.md,
    // "Reentrancy"); builds without NDEBUG check it instead.
    constexpr void assume_idle_queue() const {
        if constexpr (requires { assume_idle(queue_); }) assume_idle(queue_);
    }

    // The outcome of a dispatch that ran no guard, action or observer: recorded, and returned.
    constexpr outcome record(outcome result) {
        if constexpr (Policy::keep_last_outcome || Policy::refuse_reentry) status_ = static_cast<run_status>(result);
        return result;
    }

    // Runs the body of a dispatch, a cycle or the construction, whose caller records the
    // outcome it returns (record() ends the run). If the body ends by an exception instead (a
    // rethrown failure, a throwing observer), the run ends here and the last outcome stays.
    // (A try block and not an object whose destructor ends the run: the object would have to
    // live on the stack of every dispatch.)
    template <class Body>
    BSC_DETAIL_ALWAYS_INLINE constexpr outcome run_to_end(Body&& body) {
#if defined(__cpp_exceptions)
        try {
            return body();
        } catch (...) {
            end_run_by_exception();
            throw;
        }
#else
        return body();
#endif
    }
    constexpr void end_run_by_exception() {
        // A failure the run kept goes with it: the exception that ended the run is what the
        // caller sees.
        if constexpr (may_throw) failure_.reset();
        queue_.clear();  // and what it had raised: nothing leaks into the next run
        queue_.clear_overflow();
        status_ = static_cast<run_status>(bits(status_) & ~(running_bit | failed_bit));
        if constexpr (completion::parallel_count > 0) entering_ = {};  // the run is over, whatever it was entering
    }

    friend struct access;
};

}  // namespace bsc::detail
