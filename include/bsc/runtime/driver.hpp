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
//   bool fire(E const& e);                       selects and fires the transitions on e,
//                                                without settling
//   template <int Trigger, class E>
//   bool fire_dispatched(E const& e);            fire() for the event a dispatch takes
//   template <int Component> bool component_step();  one component's turn in a cycle
//   template <int S> bool is_active() const;     whether state S is active

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include <bsc/action_failed.hpp>
#include <bsc/chart_ref.hpp>
#include <bsc/configuration.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/assume.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/machine_base.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/event_set.hpp>
#include <bsc/model/completion.hpp>
#include <bsc/model/layout.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/runtime/context_data.hpp>
#include <bsc/runtime/event_queue.hpp>
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

// The decoder of dispatch_by_name when none is given: builds no event (each is default-constructed).
struct no_decoder {};

// Whether a row's guard or action can throw, called as a machine calls it: a transition's
// guard with (context, event) and its action with (context, event, queue), an entry or exit
// action with (context, queue).
template <class Context, class Queue, class Row>
struct row_nothrow {  // an entry or exit row
    static constexpr bool value = std::is_nothrow_invocable_v<decltype(Row::action) const&, Context&, Queue&>;
};
template <class Context, class Queue, class S, class Trigger, class G, class A, class T>
struct row_nothrow<Context, Queue, transition_row<S, Trigger, G, A, T>> {
    using event = row_event_t<transition_row<S, Trigger, G, A, T>>;
    static constexpr bool value = std::is_nothrow_invocable_v<G const&, Context const&, event const&> &&
                                  std::is_nothrow_invocable_v<A const&, Context&, event const&, Queue&>;
};

// Whether any guard or action of the chart can throw. If none can (each is noexcept, or the
// code is built without exceptions), a machine keeps no record of failures and never checks
// for one: containing failures costs nothing where nothing can fail.
template <class Model, class Queue>
constexpr bool chart_may_throw() {
#if defined(__cpp_exceptions)
    return []<class... Rows>(type_list<Rows...>) {
        return !(row_nothrow<typename Model::chart_context, Queue, Rows>::value && ...);
    }(typename Model::row_types{});
#else
    return false;
#endif
}

// Whether every machine of a chart can share one constant instance of it instead of storing a
// copy: a chart that holds no data at all (each row is empty: its trigger, guard and action
// carry no value, no delay, no captures, and can be made again from nothing), or a
// bsc::chart_ref, which names the constexpr variable that holds the chart. A machine of such a
// chart calls the rows of shared_chart, whose values (delays, captures) are then constants the
// compiler folds into the code.
template <class Chart, class Rows = typename Chart::row_types>
inline constexpr bool is_shared_chart = false;
template <class Chart, class... Rows>
inline constexpr bool is_shared_chart<Chart, type_list<Rows...>> =
    is_chart_ref<Chart> ||
    (((std::is_empty_v<Rows> && std::is_default_constructible_v<Rows>) && ...) && std::is_default_constructible_v<Chart>);
template <class Chart>
inline constexpr Chart shared_chart{};

// The entry times of a chart without timeouts: none, and unlike std::array<duration, 0>, no
// byte. (No index is ever valid; operator[] exists for code that loops over zero slots.)
struct no_timeout_slots {
    static constexpr std::size_t size() { return 0; }
    constexpr duration* begin() { return nullptr; }
    constexpr duration* end() { return nullptr; }
    constexpr duration const* begin() const { return nullptr; }
    constexpr duration const* end() const { return nullptr; }
    constexpr duration& operator[](std::size_t) const { return unused; }

private:
    static inline duration unused{};
};
template <std::size_t Slots>
using timeout_slots = std::conditional_t<Slots == 0, no_timeout_slots, std::array<duration, Slots>>;

// A member handed out by reference (the context, the observer): no space when T is empty, and
// otherwise T whole. A [[no_unique_address]] T itself could lend its tail padding to the next
// members, and bytes copied over the reference (std::memcpy of a trivially copyable object)
// would then overwrite them.
template <class T, bool Empty = std::is_empty_v<T>>
struct whole {
    T value;
};
template <class T>
struct whole<T, true> {
    [[no_unique_address]] T value;
};

// The capacity of the deferred events of a machine: Policy::deferred_capacity for a chart that
// defers, and for any other no member read (a policy written before it existed still works).
template <class Policy, bool Defers>
inline constexpr std::size_t deferred_capacity_of = 0;
template <class Policy>
inline constexpr std::size_t deferred_capacity_of<Policy, true> = Policy::deferred_capacity;

// What a machine of a chart that defers keeps besides its deferred events: whether the
// microstep under way selected a deferring row, or fired another transition; whether a
// transition changed the configuration since the last round of retries; and how many deferred
// events the current round still retries.
struct deferral_state {
    bool requested = false;
    bool other_fired = false;
    bool changed = false;
    std::size_t retry = 0;
};
struct no_deferral {};

// The record of failures of a machine none of whose guards and actions can throw.
struct no_failure_slot {
    constexpr explicit operator bool() const { return false; }
    constexpr void reset() {}
    static std::exception_ptr get() { return nullptr; }
};

// The clock and its started flag of a machine that keeps no clock (driver::keeps_clock): two
// types, so that both members take no room.
struct no_clock {};
struct no_clock_start {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class driver : public machine_base {
protected:
    using model = chart_model<std::remove_cv_t<Chart>>;
    using layout = chart_layout<model>;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;
    static constexpr int root = layout::root;
    static constexpr auto state_count = static_cast<std::size_t>(model::N);
    // Whether the machine has an observer. Without one no hook is called, and the back ends do
    // not even instantiate the calls.
    static constexpr bool observed = !std::is_same_v<Observer, no_observer>;

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
        if constexpr (layout::has_trigger(any_condition))
            report.transitions = run_components();
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
        constexpr int trigger = model::template trigger_of<E>;
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
            return process<trigger>(e);
        }
    }

    /// As dispatch(e), but an event type that no transition handles is accepted and ignored.
    template <class E>
    constexpr outcome dispatch(E const& e, allow_unhandled_t) {
        constexpr int trigger = model::template trigger_of<E>;
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
            return process<trigger>(e);
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
        constexpr int s = model::template index_of_state<S>;
        if constexpr (s < 0) {
            detail::report<error::queried_state_not_in_chart<S>>();
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
    constexpr driver(Chart const& chart, context_type context, Observer observer)
        : chart_(stored_chart(chart)), observer_{std::move(observer)}, context_{std::move(context)} {}

    // The chart: the machine's copy, or, for a shared chart (is_shared_chart), the one every machine shares.
    constexpr chart_type const& chart() const {
        if constexpr (is_shared_chart<chart_type>)
            return shared_chart<chart_type>;
        else
            return chart_;
    }

    // Enters the initial configuration (entry actions run) and settles eventless transitions.
    // Called by the back end's constructor, once the back end exists.
    constexpr void start() {
        mark_running();
        end_run(run_to_end([&] {
            if constexpr (tree.slots > 0)
                config_.active = layout::initial_bytes;
            latch_inputs(context_.value);
            backend().enter_initial();
            outcome const settled = finish(false);
            commit_outputs(context_.value);
            return settled;
        }));
    }

    // Whether the chart sends delayed events (bsc::raise_after): its queue keeps them.
    static constexpr bool delays_events = requires(Queue& q) { q.release_due(duration{}); };
    // Whether the machine keeps the time of its last cycle. Timeouts count from it (their entry
    // times are the clock's), and timers and delayed events run on it, so that a caller's time
    // that goes backwards does not reach them; without any of these, only now() and the report
    // of a clock that went backwards read it, and a policy may leave it out (keep_clock).
    static constexpr bool keeps_clock =
        Policy::keep_clock || layout::timeout_slots > 0 || has_timers<context_type> || delays_events;

    // The time of the last cycle: the clock, or zero for a machine that keeps none.
    constexpr duration cycle_time() const {
        if constexpr (keeps_clock)
            return clock_;
        else
            return duration{};
    }
    // Whether a cycle has run (the clock is the caller's time); false without a clock.
    constexpr bool clock_started() const {
        if constexpr (keeps_clock)
            return clock_started_;
        else
            return false;
    }
    // Sets the clock as if a cycle had run at `now` (started = false: as if none had). A machine
    // without a clock has nothing to set.
    constexpr void set_clock([[maybe_unused]] duration now, [[maybe_unused]] bool started) {
        if constexpr (keeps_clock) {
            clock_ = now;
            clock_started_ = started;
        }
    }

    // ---- deferred events, called by the back ends ------------------------------------------
    static constexpr bool defers = model::has_deferral;

    // A deferring row was selected: its event is kept at the end of the microstep, unless
    // another transition fired in it.
    constexpr void deferral_selected() {
        if constexpr (defers) deferral_.requested = true;
    }
    // A transition that does not defer fired; `changes`: it has a target.
    constexpr void transition_fired(bool changes) {
        if constexpr (defers) {
            deferral_.other_fired = true;
            if (changes) deferral_.changed = true;
        } else {
            (void)changes;
        }
    }

    // ---- completion (model/completion.hpp), called by the back ends ----------------------
    using completion = detail::completion<model>;

    // After the entry actions of final state f: raises done for its parent, and for the
    // parallel state above the parent if every region of it is now in a final state (SCXML's
    // enterStates). A final child of the root raises nothing: the machine halts.
    constexpr void entered_final(int f) {
        if constexpr (completion::raises) {
            int const p = tree.parent[static_cast<std::size_t>(f)];
            if (p == root) return;
            raise_done(p);
            int const g = tree.parent[static_cast<std::size_t>(p)];
            if (tree.kinds[static_cast<std::size_t>(g)] == kind::parallel && !entering(g) && in_final(g)) raise_done(g);
        } else {
            (void)f;
        }
    }

    // Enters the regions of parallel state g (enter_regions(), the back end's loop). While it
    // does, a final state entered in a region does not look at the regions after its own, which
    // are not entered yet; once they all are, done for g is raised if they are all final and
    // the last was entered through a final state of its own (a composite region): where SCXML
    // raises it, after the last final state entered.
    template <class Enter>
    constexpr void enter_parallel(int g, Enter&& enter_regions) {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            if (n >= 0) {
                entering_.flag[static_cast<std::size_t>(n)] = true;
                enter_regions();
                entering_.flag[static_cast<std::size_t>(n)] = false;
                if (tree.kinds[static_cast<std::size_t>(last_child(g))] == kind::composite && in_final(g)) raise_done(g);
                return;
            }
        }
        enter_regions();
    }

    // Runs the exit actions of every active state, innermost first, when the machine halts
    // (SCXML's exitInterpreter).
    constexpr void halt_if_final() {
        if constexpr (layout::can_halt)
            if (halted()) {
                backend().exit_all();
                queue_.clear();
            }
    }

private:
    constexpr bool entering(int g) const {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            return n >= 0 && entering_.flag[static_cast<std::size_t>(n)];
        } else {
            return (void)g, false;
        }
    }
    static constexpr int last_child(int s) {
        int last = tree.first_child[static_cast<std::size_t>(s)];
        while (tree.next_sibling[static_cast<std::size_t>(last)] >= 0) last = tree.next_sibling[static_cast<std::size_t>(last)];
        return last;
    }
    // SCXML's isInFinalState: a composite whose active child is final, a parallel state all of
    // whose regions are.
    constexpr bool in_final(int s) const {
        auto const i = static_cast<std::size_t>(s);
        if (tree.kinds[i] == kind::composite) {
            auto const ordinal = config_.active[static_cast<std::size_t>(tree.slot[i])];
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (tree.ordinal[static_cast<std::size_t>(c)] == ordinal)
                    return tree.kinds[static_cast<std::size_t>(c)] == kind::final_state;
            return false;
        }
        if (tree.kinds[i] == kind::parallel) {
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (!in_final(c)) return false;
            return true;
        }
        return false;
    }
    // Queues done<S> for state s, if a row takes it.
    constexpr void raise_done(int s) {
        [&]<std::size_t... S>(std::index_sequence<S...>) {
            (void)((s == static_cast<int>(S) ? (raise_done_of<S>(), true) : false) || ...);
        }(std::make_index_sequence<state_count>{});
    }
    template <std::size_t S>
    constexpr void raise_done_of() {
        if constexpr (completion::trigger[S] >= 0) (void)queue_(done<typename model::template tag_at<static_cast<int>(S)>>{});
    }

protected:
    // The machine counts as running from the start of a run to its end, or, in a dispatch on a
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
        return {this, [](void* machine, std::exception_ptr error) { static_cast<driver*>(machine)->fail(std::move(error)); }};
    }

    // Row Row of the chart. (Read from the base that holds it, named directly: row_at would
    // be one more function to instantiate per row.)
    template <int Row>
    constexpr auto const& row() const {
        using slot = row_slot<static_cast<std::size_t>(Row), typename model::template row_at<Row>>;
        return static_cast<slot const&>(chart().rows).row;
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

    // Fires the transitions an event (not the eventless pseudo-event) enables where the chart
    // defers, and keeps the event if only deferring rows took it. (Elsewhere the callers go
    // straight to the back end's fire, without a function between to instantiate per event.)
    template <int Trigger, class E>
    constexpr bool fire_or_defer(E const& e) {
        deferral_.requested = false;
        deferral_.other_fired = false;
        bool const fired = backend().template fire<Trigger>(e);
        if (deferral_.requested && !deferral_.other_fired) (void)deferred_(e);
        return fired;
    }

    // Processes one deferred event again, if a round of retries is under way, or if a
    // transition has changed the configuration since the last round (which starts a round over
    // every event kept, in the order they came). True if it processed one.
    constexpr bool retry_deferred() {
        if constexpr (defers) {
            if (deferral_.retry == 0 && deferral_.changed) {
                deferral_.changed = false;
                deferral_.retry = deferred_.size();
            }
            if (deferral_.retry == 0) return false;
            --deferral_.retry;
            deferred_.pop([&](auto const& ev) { fire_queued(ev); });
            return true;
        } else {
            return false;
        }
    }

    // Fires the transitions an event taken from the queue or the deferred events enables,
    // without settling; a failure that no transition takes is kept for the caller.
    template <class E>
    constexpr void fire_queued(E const& e) {
        constexpr int trigger = model::template trigger_of<E>;
        bool fired = false;
        if constexpr (defers)
            fired = fire_or_defer<trigger>(e);
        else
            fired = backend().template fire<trigger>(e);
        if constexpr (std::is_same_v<E, action_failed>)
            if (!fired) keep_failure(e.error);  // raised, but no transition takes it here
    }

    // Whether the chart takes bsc::action_failed: then failures go on the internal queue.
    static constexpr bool takes_failures = model::template trigger_of<action_failed> >= 0;

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

    template <int Trigger, class E>
    constexpr outcome process(E const& e) {
        if (running())
            return outcome::reentrant;
        start_without_failure();
        if (halted())
            return record(outcome::halted);
        assume_idle_queue();
        if (!Backend::marks_running_lazily || observed) mark_running();
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
                fired = fire_or_defer<Trigger>(e);
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
        if constexpr (!Policy::settle_eventless)
            return drain_queue(consumed);
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
                    if (++steps > Policy::max_eventless_steps)
                        return abandon();
            }
            if (halted())
                break;
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
            if (++internal_events > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { fire_queued(ev); });
        }
        return settled(consumed);
    }

    // The raised events of a cycle, each one microstep and no eventless settling, so that no
    // component fires twice in a cycle.
    constexpr outcome drain_queue(bool consumed) {
        std::size_t n = 0;
        for (; !queue_.empty() && !halted();) {
            if (++n > Policy::max_internal_events)
                return abandon();
            queue_.pop([&](auto const& ev) { fire_queued(ev); });
        }
        if constexpr (defers) {
            // The deferred events a transition of this cycle released, each one microstep.
            while (!halted() && (deferral_.retry > 0 || deferral_.changed)) {
                if (++n > Policy::max_internal_events) return abandon();
                if (!retry_deferred()) break;
                for (; !queue_.empty() && !halted();) {
                    if (++n > Policy::max_internal_events) return abandon();
                    queue_.pop([&](auto const& ev) { fire_queued(ev); });
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

    // ---- for the explorer (through detail::access) -------------------------------------------
    // The configuration with every byte that can never matter again reset to its initial
    // value: the byte of an inactive composite that neither has history (a marker or a history
    // state) nor lies below a deep one. Two machines with equal canonical configurations behave
    // the same.
    constexpr configuration_type canonical_configuration() const {
        configuration_type c = config_;
        if constexpr (tree.slots > 0) {
            auto const active = active_flags();
            for (std::size_t s = 1; s < state_count; ++s) {
                if (tree.slot[s] < 0 || active[s]) continue;
                bool remembered = tree.hist[s] != history::none || layout::history_child[s] >= 0;
                for (int a = tree.parent[s]; a > 0 && !remembered; a = tree.parent[static_cast<std::size_t>(a)])
                    remembered = tree.hist[static_cast<std::size_t>(a)] == history::deep ||
                                 layout::deep_history_child[static_cast<std::size_t>(a)];
                if (!remembered)
                    c.active[static_cast<std::size_t>(tree.slot[s])] = layout::initial_bytes[static_cast<std::size_t>(tree.slot[s])];
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
    struct no_chart {};
    using stored_chart_type = std::conditional_t<is_shared_chart<chart_type>, no_chart, chart_type>;
    static constexpr stored_chart_type stored_chart(chart_type const& chart) {
        if constexpr (is_shared_chart<chart_type>)
            return (void)chart, no_chart{};
        else
            return chart;
    }
    // The members whose alignment is known to be large first, the context next to the bytes, so
    // that a small machine has no padding inside.
    [[no_unique_address]] stored_chart_type chart_;
    [[no_unique_address]] Queue queue_{};
    [[no_unique_address]] std::conditional_t<keeps_clock, duration, no_clock> clock_{};
    [[no_unique_address]] timeout_slots<static_cast<std::size_t>(layout::timeout_slots)> armed_{};  // entry times
    // Whether a guard or action of the chart can throw (detail::chart_may_throw).
    static constexpr bool may_throw = chart_may_throw<model, Queue>();
    // The first failure of the current run that no transition took.
    [[no_unique_address]] std::conditional_t<may_throw, failure_slot, no_failure_slot> failure_;
    // The failure of the last run, for last_failure(), under a policy that does not rethrow.
    [[no_unique_address]] std::conditional_t<Policy::rethrow_failures || !may_throw, no_failure_slot, failure_slot> reported_;
    [[no_unique_address]] whole<Observer> observer_;
    [[no_unique_address]] whole<context_type> context_;
    configuration_type config_{};
    [[no_unique_address]] entering_flags<completion::parallel_count> entering_;
    // The events deferred (`/ bsc::defer`), oldest first, and the state of their retries.
    [[no_unique_address]] std::conditional_t<
        defers, event_queue<deferred_capacity_of<Policy, defers>, typename model::events>, no_deferral> deferred_;
    [[no_unique_address]] std::conditional_t<defers, deferral_state, no_deferral> deferral_;
    // The outcome of the last run (low bits), the mark of a run under way (running_bit) and
    // whether the run under way has kept a failure (failed_bit: failure_ holds it). An
    // enumeration and not a std::uint8_t: a store through an unsigned char may alias any object,
    // so the compiler would reload the context after every mark.
    enum class run_status : std::uint8_t {};
    static constexpr std::uint8_t running_bit = 0x80;
    static constexpr std::uint8_t failed_bit = 0x40;
    static constexpr std::uint8_t bits(run_status s) { return static_cast<std::uint8_t>(s); }
    run_status status_ = static_cast<run_status>(outcome::ignored);
    // A cycle has run: clock_ is the caller's time.
    [[no_unique_address]] std::conditional_t<keeps_clock, bool, no_clock_start> clock_started_{};
};

}  // namespace bsc::detail
