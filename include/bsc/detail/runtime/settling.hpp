#pragma once
// Run to completion: a dispatched event's microstep, then eventless transitions, raised events and
// deferred events until none remains, within the policy's limits (outcome::livelock past them);
// in a BSC cycle, the components' turns and the raised events without eventless settling. A
// layer of the driver (detail/runtime/driver.hpp).

#include <cstddef>
#include <utility>

#include <bsc/detail/runtime/backend.hpp>
#include <bsc/detail/runtime/context_data.hpp>
#include <bsc/detail/runtime/done_raising.hpp>
#include <bsc/detail/runtime/notify.hpp>
#include <bsc/events.hpp>
#include <bsc/outcome.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class settling : public done_raising<Backend, Chart, Policy, Observer, Queue> {
    using base = done_raising<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::layout;
    using base::observed;
    using base::defers;
    using base::queue_;
    using base::deferral_;
    using base::deferred_;
    using base::context_;
    using base::observer_;
    using base::backend;
    using base::running;
    using base::mark_running;
    using base::start_without_failure;
    using base::assume_idle_queue;
    using base::record;
    using base::end_run;
    using base::end_run_by_exception;
    using base::fire_or_defer;
    using base::fire_queued;
    using base::retry_deferred;
    using base::halt_if_final;
    using base::halted;

    template <int Trigger, class E>
    constexpr outcome process(E const& e) {
        if (running()) return outcome::reentrant;
        start_without_failure();
        if (halted()) return record(outcome::halted);
        assume_idle_queue();
        if (!backend_hooks::marks_running_lazily<Backend> || observed) mark_running();
        // (As run_to_end, written out: a lambda holding the whole dispatch might not be inlined,
        // and a function for the body would be one more to instantiate per event type.)
        outcome settled = outcome::ignored;
#if defined(__cpp_exceptions)
        try {
#endif
            if constexpr (observed) notify<model, Observer>::dispatching(observer_.value, e);
            latch_inputs(context_.value);
            bool fired = false;
            if constexpr (defers)
                fired = this->template fire_or_defer<Trigger>(e);
            else
                fired = backend().template fire_dispatched<Trigger>(e);
            settled = finish(fired);
            commit_outputs(context_.value);
#if defined(__cpp_exceptions)
        } catch (...) {
            end_run_by_exception();
            throw;
        }
#endif
        return end_run(settled);
    }

    // The components' turns in a cycle: a component takes its turn if it was active when the
    // cycle began and still is (an earlier component may have left it); one entered during
    // the cycle waits for the next. Returns the number of transitions fired.
    constexpr int run_components() { return run_components(std::make_index_sequence<layout::components.size()>{}); }
    // (A function of its own and not a lambda: the flags and the count are then its locals, in
    // registers, not captures that every component's stores might overwrite, reloaded after each.)
    template <std::size_t... I>
    constexpr int run_components(std::index_sequence<I...>) {
        constexpr auto const& components = layout::components;
        bool const active_at_start[] = {backend().template is_active<components[I]>()...};
        int fired = 0;
        ((fired += active_at_start[I] && backend().template is_active<components[I]>() &&
                   backend().template component_step<components[I]>()),
         ...);
        return fired;
    }

    // Settles the machine after a microstep: eventless transitions until none is enabled,
    // then the raised events one by one, each followed by its eventless transitions. Under a
    // scan policy eventless transitions are left to step(), and only raised events are processed.
    constexpr outcome finish(bool consumed) {
        if constexpr (!Policy::settle_eventless) return drain_queue(consumed);
        // The common case, kept inline: nothing raised, and no eventless transition to try.
        if constexpr (!layout::has_trigger(eventless_id) && !defers)
            if (queue_.empty() && !queue_.overflowed() && !(layout::can_halt && halted()))
                return consumed ? outcome::consumed : outcome::ignored;
        return settle(consumed);
    }

    constexpr outcome settle(bool consumed) {
        std::size_t internal_events = 0;
        for (;;) {
            if constexpr (layout::has_trigger(eventless_id)) {
                // Up to max_eventless_steps transitions settle; one more means the chart cycles.
                for (std::size_t steps = 0; !halted() && backend().template fire<eventless_id>(eventless{});)
                    if (++steps > Policy::max_eventless_steps) return abandon();
            }
            if (halted()) break;
            if (queue_.empty()) {
                // Then the deferred events, one at a time, each followed by its eventless
                // transitions and what it raises.
                if constexpr (defers) {
                    if (deferral_.retry > 0 || deferral_.changed) {
                        if (++internal_events > Policy::max_internal_events) return abandon();
                        if (retry_deferred()) continue;
                    }
                }
                break;
            }
            if (++internal_events > Policy::max_internal_events) return abandon();
            queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
        }
        return settled(consumed);
    }

    // The raised events of a cycle, each one microstep and no eventless settling, so that no
    // component fires twice in a cycle.
    constexpr outcome drain_queue(bool consumed) {
        std::size_t n = 0;
        for (; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events) return abandon();
            queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
        }
        if constexpr (defers) {
            // The deferred events a transition of this cycle released, each one microstep.
            while (!halted() && (deferral_.retry > 0 || deferral_.changed)) {
                if (++n > Policy::max_internal_events) return abandon();
                if (!retry_deferred()) break;
                for (; !queue_.empty() && !halted();) {
                    if (++n > Policy::max_internal_events) return abandon();
                    queue_.pop([&](auto const& ev) { this->fire_queued(ev); });
                }
            }
        }
        return settled(consumed);
    }

    // The end of every run that settles. The queue is empty here, but for a machine that has
    // halted (halt_if_final drops what it holds): it is rewound to its first slot, for
    // assume_idle_queue.
    constexpr outcome settled(bool consumed) {
        halt_if_final();
        if constexpr (requires { rewind_empty(queue_); }) rewind_empty(queue_);
        if constexpr (defers) {
            if (deferred_.overflowed()) {
                deferred_.clear_overflow();
                queue_.clear_overflow();
                return outcome::queue_overflow;
            }
        }
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    constexpr outcome abandon() {
        queue_.clear();
        queue_.clear_overflow();
        if constexpr (defers) deferral_.retry = 0;  // the deferred events stay, for a later change
        return outcome::livelock;
    }
};

}  // namespace bsc::detail
