#pragma once
// What both back ends share: the public interface of a machine and everything that does not
// depend on how a transition is selected and fired. The driver owns the machine's data (chart,
// context, configuration, queue, clock, timeout slots, outcome, observer), runs an event to
// completion (settling eventless transitions and raised events, with the policy's limits),
// runs a BSC cycle's shell (time, timers, latched inputs, the components' turns, committed
// outputs), and answers is<S>, halted and active_states from the configuration bytes.
//
// A back end derives from it (CRTP) and supplies only what differs:
//   void enter_initial();                        enters the root and its default completion
//   template <int Trigger, class E>
//   bool microstep(E const& e);                  selects and fires the transitions on e
//   template <int Component> bool component_step();  one component's turn in a cycle
//   template <int S> bool is_active() const;     whether state S is active

#include <array>
#include <boost/hana/at.hpp>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include <bsc/action_failed.hpp>
#include <bsc/configuration.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/event_set.hpp>
#include <bsc/model/layout.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/runtime/context_data.hpp>
#include <bsc/runtime/failures.hpp>
#include <bsc/runtime/notify.hpp>

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

// What every machine derives from, whatever its back end (an empty base: it costs nothing).
struct machine_base {};
template <class T>
inline constexpr bool is_machine = std::is_base_of_v<machine_base, T>;

// The decoder of dispatch_by_name when none is given: builds no event (each is default-constructed).
struct no_decoder {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class driver : public machine_base {
protected:
    using model = chart_model<std::remove_cv_t<Chart>>;
    using layout = chart_layout<model>;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;
    static constexpr int root = layout::root;
    static constexpr auto state_count = static_cast<std::size_t>(model::N);

public:
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    using configuration_type = configuration<static_cast<std::size_t>(tree.slots)>;
    using event_types = typename model::events;
    using policy_type = Policy;
    using observer_type = Observer;
    /// How many raised events the internal queue holds: Policy::queue_capacity, or 0 where
    /// the compiled back end finds that no action of the chart can raise.
    static constexpr std::size_t queue_capacity = Queue::capacity();

    /// One BSC execution cycle at time `now` (the BSC paper's execution cycle): timers are
    /// updated, input channels latched; then each component (the root and every region of a
    /// parallel state), in document order, fires at most one eventless or timeout transition,
    /// its actions' writes visible at once to the components after it; events raised meanwhile
    /// are processed; output channels are committed. Components entered during the cycle first
    /// run in the next one. Time never runs backwards for the machine: an earlier `now` is
    /// reported and ignored.
    constexpr step_report step(duration now) {
        step_report report;
        if (running_) {
            report.status = outcome::reentrant;
            return report;
        }
        run_guard const guard{running_};
        if (halted()) {
            report.status = last_ = outcome::halted;
            return report;
        }
        if (!clock_started_) {
            // The clock starts at the first cycle, wherever the caller's time starts; what was
            // armed before it (at construction, by a dispatch) counts from this cycle too.
            clock_started_ = true;
            clock_ = now;
            for (auto& armed : armed_) armed = now;
        } else if (now < clock_) {
            report.clock_went_backwards = true;
        } else {
            clock_ = now;
        }
        notify<model, Observer>::cycle_begins(observer_, clock_);
        update_timers(context_, clock_);
        latch_inputs(context_);
        if constexpr (layout::has_trigger(any_condition))
            report.transitions = run_components();
        report.status = last_ = drain_queue(report.transitions > 0);
        commit_outputs(context_);
        notify<model, Observer>::cycle_ends(observer_);
        report.status = last_ = conclude(last_);
        return report;
    }

    /// The time of the last cycle (the machine's clock; zero before the first cycle).
    constexpr duration now() const { return clock_; }

    /// Processes e to completion: the transitions it enables, then eventless transitions and
    /// raised events until none remain. Fails to compile if no transition handles E.
    template <class E>
    constexpr outcome dispatch(E const& e) {
        constexpr int trigger = model::template trigger_of<E>;
        if constexpr (trigger < 0) {
            detail::report<error::unhandled_event<E>>();
            return outcome::ignored;
        } else {
            return process<trigger>(e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    constexpr outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = model::template trigger_of<E>;
        if constexpr (trigger < 0) {
            if (!running_ && !halted()) notify<model, Observer>::dispatching(observer_, e);
            return last_ = outcome::ignored;
        } else {
            return process<trigger>(e);
        }
    }

    /// Dispatches the event of the chart called `name` (bsc::event_set: its static member
    /// `name`, or its type's name), built by `decode(std::type_identity<E>{})` when the decoder
    /// accepts that call and default-constructed otherwise. outcome::unknown_event, and nothing
    /// processed, if no event of the chart is so named; outcome::reentrant, as dispatch, from
    /// inside one of the machine's own guards or actions.
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_name(std::string_view name, Decode&& decode = {}) {
        // An unknown name is a number past the last event: dispatch_by_number refuses both alike.
        return dispatch_by_number(event_set<Chart>::find(name).value_or(event_set<Chart>::size), decode);
    }

    /// As dispatch_by_name, for the event numbered `number` (bsc::event_set<Chart>::number_of).
    template <class Decode = no_decoder>
    constexpr outcome dispatch_by_number(std::size_t number, Decode&& decode = {}) {
        if (running_) return outcome::reentrant;
        if (number >= event_set<Chart>::size) return last_ = outcome::unknown_event;
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
            return (void)decode, last_ = outcome::unknown_event;  // not reached: no number is below 0
    }

    /// True if state S is active.
    template <class S>
    constexpr bool is() const {
        constexpr int s = model::template index_of_state<S>;
        if constexpr (s < 0) {
            detail::report<error::state_not_in_chart<S>>();
            return false;
        } else {
            return backend().template is_active<s>();
        }
    }

    /// True once a final child of the root is active: the machine processes nothing more.
    constexpr bool halted() const {
        if constexpr (layout::can_halt)
            return layout::final_root_children[config_.active[static_cast<std::size_t>(tree.slot[root])]];
        else
            return false;
    }

    /// The names of the active states, outermost first, in document order.
    constexpr auto active_states() const {
        bsc::state_names<state_count> names;
        auto const active = active_flags();
        for (std::size_t s = 1; s < state_count; ++s)
            if (active[s]) names.push_back(state_names_of<model>[s]);
        return names;
    }

    /// The outcome of the last dispatch (or of construction).
    constexpr outcome last_outcome() const { return last_; }

    /// The exception of the last dispatch, cycle or construction whose outcome was
    /// outcome::failed (a policy whose rethrow_failures is false); null otherwise.
    std::exception_ptr last_failure() const {
        if constexpr (!Policy::rethrow_failures)
            if (last_ == outcome::failed) return reported_.get();
        return nullptr;
    }

    constexpr context_type& context() { return context_; }
    constexpr context_type const& context() const { return context_; }
    constexpr configuration_type const& active_configuration() const { return config_; }
    constexpr Observer& observer() { return observer_; }
    constexpr Observer const& observer() const { return observer_; }

protected:
    constexpr driver(Chart const& chart, context_type context, Observer observer)
        : chart_(chart), context_(std::move(context)), observer_(std::move(observer)) {}

    // Enters the initial configuration (entry actions run) and settles eventless transitions.
    // Called by the back end's constructor, once the back end exists.
    constexpr void start() {
        run_guard const guard{running_};
        if constexpr (tree.slots > 0)
            config_.active = layout::initial_bytes;
        latch_inputs(context_);
        backend().enter_initial();
        last_ = finish(false);
        commit_outputs(context_);
        last_ = conclude(last_);
    }

    // Runs a guard (true if it holds) or a block of an action: what either throws goes to fail().
    template <class Guard>
    constexpr bool test(Guard&& guard) {
        return test_guard(guard, [this](std::exception_ptr error) { fail(std::move(error)); });
    }
    template <class Block>
    constexpr void run(Block&& block) {
        run_block(block, [this](std::exception_ptr error) { fail(std::move(error)); });
    }
    // The same, for code that knows the machine only by address (the table engine's thunks).
    failure_sink sink() {
        return {this, [](void* machine, std::exception_ptr error) { static_cast<driver*>(machine)->fail(std::move(error)); }};
    }

    template <int Row>
    constexpr auto const& row() const {
        return boost::hana::at_c<static_cast<std::size_t>(Row)>(chart_.rows);
    }

    // Whether state s is active, read from the bytes; outermost first, so one pass suffices.
    constexpr std::array<bool, state_count> active_flags() const {
        std::array<bool, state_count> active{};
        active[0] = true;
        if constexpr (tree.slots > 0)
            for (std::size_t s = 1; s < state_count; ++s) {
                auto const p = static_cast<std::size_t>(tree.parent[s]);
                active[s] = active[p] && (tree.slot[p] < 0 || config_.active[static_cast<std::size_t>(tree.slot[p])] ==
                                                                  static_cast<std::uint8_t>(tree.ordinal[s]));
            }
        else
            for (std::size_t s = 1; s < state_count; ++s) active[s] = true;
        return active;
    }

private:
    using driver_type = driver;  // what detail::access reaches a machine's data through

    constexpr Backend& backend() { return static_cast<Backend&>(*this); }
    constexpr Backend const& backend() const { return static_cast<Backend const&>(*this); }

    template <class E>
    constexpr void microstep_on(E const& e) {
        bool const fired = backend().template microstep<model::template trigger_of<E>>(e);
        if constexpr (std::is_same_v<E, action_failed>)
            if (!fired) keep_failure(e.error);  // raised, but no transition takes it here
    }

    // Whether the chart takes bsc::action_failed: then failures go on the internal queue.
    static constexpr bool takes_failures = model::template trigger_of<action_failed> >= 0;

    // A guard or action threw: raise bsc::action_failed if the chart takes it (and the queue
    // has room), else keep it for the caller.
    void fail(std::exception_ptr error) {
        if constexpr (takes_failures)
            if (queue_(action_failed{error})) return;
        keep_failure(std::move(error));
    }
    void keep_failure(std::exception_ptr error) { failure_.keep(std::move(error)); }

    // The end of a run, the machine consistent and its outputs committed: a failure no
    // transition took is rethrown, or reported as outcome::failed.
    constexpr outcome conclude(outcome result) {
#if defined(__cpp_exceptions)
        if (failure_) return failed_run();
#endif
        return result;  // without exceptions nothing can have failed: no test
    }
    outcome failed_run() {
        if constexpr (Policy::rethrow_failures) {
            std::rethrow_exception(failure_.take());
        } else {
            reported_.reset();
            reported_.keep(failure_.take());
            return outcome::failed;
        }
    }

    // Marks the machine as running for the time of a dispatch, a cycle or the construction: a
    // dispatch or step called meanwhile from one of its guards or actions is refused.
    struct run_guard {
        bool& running;
        constexpr explicit run_guard(bool& flag) : running(flag) { running = true; }
        constexpr ~run_guard() { running = false; }
        run_guard(run_guard const&) = delete;
        run_guard& operator=(run_guard const&) = delete;
    };

    template <int Trigger, class E>
    constexpr outcome process(E const& e) {
        if (running_)
            return outcome::reentrant;
        run_guard const guard{running_};
        if (halted())
            return last_ = outcome::halted;
        notify<model, Observer>::dispatching(observer_, e);
        latch_inputs(context_);
        last_ = finish(backend().template microstep<Trigger>(e));
        commit_outputs(context_);
        return last_ = conclude(last_);
    }

    // The components' turns in a cycle: a component takes its turn if it was active when the
    // cycle began and still is (an earlier component may have left it); one entered during
    // the cycle waits for the next. Returns the number of transitions fired.
    constexpr int run_components() {
        constexpr auto const& components = layout::components;
        std::array<bool, components.size()> active_at_start{};
        int fired = 0;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((active_at_start[I] = backend().template is_active<components[I]>()), ...);
            ((fired += active_at_start[I] && backend().template is_active<components[I]>() &&
                       backend().template component_step<components[I]>()),
             ...);
        }(std::make_index_sequence<components.size()>{});
        return fired;
    }

    // Settles the machine after a microstep: eventless transitions until none is enabled,
    // then the raised events one by one, each followed by its eventless transitions. Under a
    // scan policy eventless transitions are left to step(), and only raised events are processed.
    constexpr outcome finish(bool consumed) {
        if constexpr (!Policy::settle_eventless)
            return drain_queue(consumed);
        // The common case, kept inline: nothing raised, and no eventless transition to try.
        if constexpr (!layout::has_trigger(eventless_id))
            if (queue_.empty() && !queue_.overflowed())
                return consumed ? outcome::consumed : outcome::ignored;
        return settle(consumed);
    }

    constexpr outcome settle(bool consumed) {
        std::size_t internal_events = 0;
        for (;;) {
            if constexpr (layout::has_trigger(eventless_id)) {
                // Up to max_eventless_steps transitions settle; one more means the chart cycles.
                for (std::size_t steps = 0; !halted() && backend().template microstep<eventless_id>(eventless{});)
                    if (++steps > Policy::max_eventless_steps)
                        return abandon();
            }
            if (queue_.empty() || halted())
                break;
            if (++internal_events > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { microstep_on(ev); });
        }
        return settled(consumed);
    }

    // The raised events of a cycle, each one microstep and no eventless settling, so that no
    // component fires twice in a cycle.
    constexpr outcome drain_queue(bool consumed) {
        for (std::size_t n = 0; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { microstep_on(ev); });
        }
        return settled(consumed);
    }

    constexpr outcome settled(bool consumed) {
        if (queue_.overflowed()) {
            queue_.clear_overflow();
            return outcome::queue_overflow;
        }
        return consumed ? outcome::consumed : outcome::ignored;
    }

    constexpr outcome abandon() {
        queue_.clear();
        queue_.clear_overflow();
        return outcome::livelock;
    }

    // ---- for the explorer (through detail::access) -------------------------------------------
    // The configuration with every byte that can never matter again reset to its initial
    // child: the byte of an inactive composite that neither has history nor lies below a
    // deep history. Two machines with equal canonical configurations behave the same.
    constexpr configuration_type canonical_configuration() const {
        configuration_type c = config_;
        if constexpr (tree.slots > 0) {
            auto const active = active_flags();
            for (std::size_t s = 1; s < state_count; ++s) {
                if (tree.slot[s] < 0 || active[s]) continue;
                bool remembered = tree.hist[s] != history::none;
                for (int a = tree.parent[s]; a > 0 && !remembered; a = tree.parent[static_cast<std::size_t>(a)])
                    remembered = tree.hist[static_cast<std::size_t>(a)] == history::deep;
                if (!remembered)
                    c.active[static_cast<std::size_t>(tree.slot[s])] =
                        static_cast<std::uint8_t>(tree.ordinal[static_cast<std::size_t>(tree.initial[s])]);
            }
        }
        return c;
    }

    // A timeout slot's age matters only while its state is active.
    constexpr bool timeout_armed(std::size_t slot) const {
        auto const active = active_flags();
        if constexpr (layout::timeout_slots > 0)
            return slot < layout::timeout_slot_state.size() &&
                   active[static_cast<std::size_t>(layout::timeout_slot_state[slot])];
        else
            return false;
    }

    // The longest delay of any timeout row: past it, a state's age no longer matters.
    constexpr duration longest_timeout() const {
        duration longest{};
        for (duration delay : row_delays())
            if (delay > longest) longest = delay;
        return longest;
    }

    // Each row's delay: a timeout row's, zero for the others.
    constexpr std::array<duration, static_cast<std::size_t>(model::R)> row_delays() const {
        std::array<duration, static_cast<std::size_t>(model::R)> delays{};
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (
                [&] {
                    if constexpr (layout::is_timeout_row(static_cast<int>(I)))
                        delays[I] = row<static_cast<int>(I)>().trigger_value.delay;
                }(),
                ...);
        }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
        return delays;
    }

    friend struct access;

protected:
    [[no_unique_address]] chart_type chart_;
    context_type context_;
    configuration_type config_{};
    [[no_unique_address]] Queue queue_{};
    duration clock_{};
    std::array<duration, static_cast<std::size_t>(layout::timeout_slots)> armed_{};  // entry times
    outcome last_ = outcome::ignored;
    bool running_ = false;        // inside a dispatch, a cycle or the constructor
    bool clock_started_ = false;  // a cycle has run: clock_ is the caller's time
    [[no_unique_address]] Observer observer_;
    failure_slot failure_;  // the first failure of the current run that no transition took
    struct nothing_reported {
        static std::exception_ptr get() { return nullptr; }
    };
    // The failure of the last run, for last_failure(), under a policy that does not rethrow.
    [[no_unique_address]] std::conditional_t<Policy::rethrow_failures, nothing_reported, failure_slot> reported_;
};

}  // namespace bsc::detail
