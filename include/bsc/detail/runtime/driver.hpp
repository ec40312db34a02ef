#pragma once
// The driver: what both back ends share, and the public interface of a machine (step, dispatch,
// is<S>, halted, active_states, ...). It is built in layers, each a class template deriving
// from the one below and doing one job (their headers say which):
//
//   machine_data       what a machine holds, and the chart's types and facts
//   explorer_queries   what only the explorer asks (through detail::access)
//   run_control        a run's bracket: reentrancy, guarded calls, failures, the recorded outcome
//   deferral           deferred events, kept and retried
//   done_raising       done<S> events, and the exits when the machine halts
//   settling           run to completion; a cycle's components and raised events
//   driver             the public interface, the construction and the BSC cycle's shell
//
// A back end (bsc::machine, bsc::table::machine) derives from the driver (CRTP) and supplies
// the hooks of detail/runtime/backend.hpp, which the driver checks (machine_backend).

#include <cstddef>
#include <string_view>
#include <type_traits>
#include <utility>

#include <bsc/detail/config.hpp>
#include <bsc/detail/runtime/backend.hpp>
#include <bsc/detail/runtime/context_data.hpp>
#include <bsc/detail/runtime/notify.hpp>
#include <bsc/detail/runtime/settling.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/event_set.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>

namespace bsc::detail {

// The observer type a machine's deduction guide takes from its constructor's arguments
// (chart[, context[, observer]]): both back ends deduce through this one rule.
template <class... Arguments>
struct observer_argument {
    using type = no_observer;
};
template <class Context, class Observer>
struct observer_argument<Context, Observer> {
    using type = Observer;
};
template <class... Arguments>
using observer_argument_t = typename observer_argument<Arguments...>::type;

// The decoder of dispatch_by_name when none is given: builds no event (each is default-constructed).
struct no_decoder {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class driver : public settling<Backend, Chart, Policy, Observer, Queue> {
    using base = settling<Backend, Chart, Policy, Observer, Queue>;

protected:
    using typename base::model;
    using typename base::layout;
    using base::tree;
    using base::root;
    using base::state_count;
    using base::observed;
    using base::keeps_clock;
    using base::delays_events;
    using base::may_throw;
    using base::config_;
    using base::queue_;
    using base::armed_;
    using base::context_;
    using base::observer_;
    using base::reported_;
    using base::clock_;
    using base::clock_started_;
    using base::backend;
    using base::active_flags;
    using base::cycle_time;
    using base::running;
    using base::mark_running;
    using base::kept_outcome;
    using base::record;
    using base::end_run;
    using base::run_to_end;
    using base::assume_idle_queue;
    using base::process;
    using base::finish;
    using base::drain_queue;
    using base::run_components;

public:
    using typename base::chart_type;
    using typename base::context_type;
    using typename base::configuration_type;
    using typename base::event_types;
    using typename base::policy_type;
    using typename base::observer_type;
    using base::queue_capacity;

    /// One BSC execution cycle at time `now` (the BSC paper's execution cycle): timers are
    /// updated, input channels latched; then each component (the root and every region of a
    /// parallel state), in document order, fires at most one eventless or timeout transition,
    /// its actions' writes visible at once to the components after it; events raised meanwhile
    /// are processed; output channels are committed. Components entered during the cycle first
    /// run in the next one. Time never runs backwards for the machine: an earlier `now` is
    /// reported and ignored.
    constexpr step_report step(duration now) {
        step_report report;
        if (running()) {
            report.status = outcome::reentrant;
            return report;
        }
        if (halted()) {
            report.status = record(outcome::halted);
            return report;
        }
        assume_idle_queue();
        mark_running();
        report.status = end_run(run_to_end([&] { return cycle(now, report); }));
        return report;
    }

private:
    // The cycle of step(now), which has marked the machine running; returns its outcome.
    // Out of line, so that step stays small enough to be inlined where it is called: GCC 12,
    // inlining the cycle into step instead, returns the report from a call, assembled in
    // memory by narrow stores and read back by wider loads, which stall (docs/performance.md,
    // rule "The cycle out of line").
    BSC_DETAIL_NOINLINE constexpr outcome cycle(duration now, step_report& report) {
        if constexpr (keeps_clock) {
            if (!clock_started_) {
                // The clock starts at the first cycle, wherever the caller's time starts; what was
                // armed before it (at construction, by a dispatch) counts from this cycle too.
                clock_started_ = true;
                clock_ = now;
                for (auto& armed : armed_) armed = now;
                if constexpr (delays_events) queue_.start_clock(now);
            } else if (now < clock_) {
                report.clock_went_backwards = true;  // the cycle runs at the clock's time
            } else {
                clock_ = now;
                if constexpr (delays_events) queue_.set_clock(now);
            }
            now = clock_;
        }
        notify<model, Observer>::cycle_begins(observer_.value, now);
        update_timers(context_.value, now);
        latch_inputs(context_.value);
        if constexpr (layout::has_trigger(any_condition)) report.transitions = run_components();
        // The delayed events due now, as raised events (bsc::raise_after).
        if constexpr (delays_events) queue_.release_due(now);
        outcome const drained = drain_queue(report.transitions > 0);
        commit_outputs(context_.value);
        notify<model, Observer>::cycle_ends(observer_.value);
        return drained;
    }

public:
    /// The time of the last cycle (the machine's clock; zero before the first cycle). A machine
    /// keeps a clock when its chart has timeouts, timers or delayed events, or when its policy
    /// says keep_clock (bsc::default_policy does; bsc::lean_policy does not).
    constexpr duration now() const {
        if constexpr (!keeps_clock) detail::report<error::clock_not_kept<Policy>>();
        return cycle_time();
    }

    /// Processes e to completion: the transitions it enables, then eventless transitions and
    /// raised events until none remain. Fails to compile if no transition handles E, or if E
    /// is an event the environment cannot send (bsc::done<S>, bsc::action_failed,
    /// bsc::any_event: bsc::error::event_not_dispatchable).
    template <class E>
    constexpr outcome dispatch(E const& e) {
        constexpr int trigger = model::template trigger_of<E>::value;
        if constexpr (reserved_event<E>) {
            detail::report<error::event_not_dispatchable<E>>();
            return outcome::ignored;
        } else if constexpr (trigger == -2) {
            detail::report<error::event_in_two_families<E>>();
            return outcome::ignored;
        } else if constexpr (trigger < 0) {
            detail::report<error::unhandled_event<E>>();
            return outcome::ignored;
        } else {
            return this->template process<trigger>(e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    constexpr outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = model::template trigger_of<E>::value;
        if constexpr (reserved_event<E>) {
            detail::report<error::event_not_dispatchable<E>>();
            return outcome::ignored;
        } else if constexpr (trigger == -2) {
            detail::report<error::event_in_two_families<E>>();
            return outcome::ignored;
        } else if constexpr (trigger < 0) {
            if (running()) return outcome::ignored;  // inside a run: nothing to record
            if (!halted()) notify<model, Observer>::dispatching(observer_.value, e);
            return record(outcome::ignored);
        } else {
            return this->template process<trigger>(e);
        }
    }

    /// Dispatches the event of the chart called `name` (bsc::event_set: its static member
    /// `name`, or its type's name), built by `decode(std::type_identity<E>{})` when the decoder
    /// accepts that call and default-constructed otherwise. outcome::unknown_event, and nothing
    /// processed, if no event of the chart the environment may send is so named (so for
    /// "done.state.S" and "*": bsc::event_set leaves them out); outcome::reentrant, as dispatch,
    /// from inside one of the machine's own guards or actions.
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_name(std::string_view name, Decode&& decode = {}) {
        // An unknown name is a number past the last event: dispatch_by_number refuses both alike.
        return dispatch_by_number(event_set<Chart>::find(name).value_or(event_set<Chart>::size), decode);
    }

    /// As dispatch_by_name, for the event numbered `number` (bsc::event_set<Chart>::number_of).
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_number(std::size_t number, Decode&& decode = {}) {
        if (running()) return outcome::reentrant;
        if (number >= event_set<Chart>::size) return record(outcome::unknown_event);
        if constexpr (event_set<Chart>::size > 0)
            return event_set<Chart>::visit(number, [&]<class E>(std::type_identity<E> event) {
                if constexpr (std::is_invocable_r_v<E, Decode&, std::type_identity<E>>) {
                    return dispatch(static_cast<E>(decode(event)));
                } else if constexpr (std::is_default_constructible_v<E>) {
                    return dispatch(E{});
                } else {
                    detail::report<error::event_not_constructible<E>>();
                    return outcome::ignored;
                }
            });
        else
            return (void)decode, record(outcome::unknown_event);  // not reached: no number is below 0
    }

    /// True if state S is active.
    template <class S>
    constexpr bool is() const {
        constexpr int s = model::template index_of_state<S>::value;
        if constexpr (s < 0) {
            detail::report<error::queried_state_not_in_chart<S>>();
            return false;
        } else {
            return backend().template is_active<s>();
        }
    }

    /// True once a final child of the root is active: the machine processes nothing more.
    using base::halted;

    /// The names of the active states, outermost first, in document order.
    constexpr auto active_states() const {
        bsc::state_names<state_count> names;
        auto const active = active_flags();
        for (std::size_t s = 1; s < state_count; ++s)
            if (active[s]) names.push_back(state_names_of<model>[s]);
        return names;
    }

    /// The outcome of the last dispatch (or of construction).
    constexpr outcome last_outcome() const {
        if constexpr (!Policy::keep_last_outcome) detail::report<error::last_outcome_not_kept<Policy>>();
        return kept_outcome();
    }

    /// The exception of the last dispatch, cycle or construction whose outcome was
    /// outcome::failed (a policy whose rethrow_failures is false); null otherwise.
    std::exception_ptr last_failure() const {
        if constexpr (!Policy::keep_last_outcome) detail::report<error::last_outcome_not_kept<Policy>>();
        if constexpr (!Policy::rethrow_failures && may_throw)
            if (kept_outcome() == outcome::failed) return reported_.get();
        return nullptr;
    }

    /// The context as the environment sees it: const. Inputs are set through it (input::set is
    /// const: the plant's wire), outputs and variables read; only the chart's actions write
    /// outputs and variables (docs/api.md, "Data").
    constexpr context_type const& context() const { return context_.value; }
    constexpr configuration_type const& active_configuration() const { return config_; }
    constexpr Observer& observer() { return observer_.value; }
    constexpr Observer const& observer() const { return observer_.value; }

protected:
    // Checks the back end's side of the contract (detail/runtime/backend.hpp) where Backend is
    // complete: a back end without a hook fails here, naming machine_backend and the hook.
    constexpr driver(Chart const& chart, context_type context, Observer observer)
        : base(chart, std::move(context), std::move(observer)) {
        static_assert(machine_backend<Backend>, "a bsc back end supplies every hook of detail/runtime/backend.hpp");
    }


    // Enters the initial configuration (entry actions run) and settles eventless transitions.
    // Called by the back end's constructor, once the back end exists.
    constexpr void start() {
        mark_running();
        end_run(run_to_end([&] {
            if constexpr (tree.slots > 0) config_.active = layout::initial_bytes;
            latch_inputs(context_.value);
            backend().enter_initial();
            outcome const settled = finish(false);
            commit_outputs(context_.value);
            return settled;
        }));
    }

private:
    using driver_type = driver;  // what detail::access reaches a machine's data through
    friend struct access;
};

}  // namespace bsc::detail
