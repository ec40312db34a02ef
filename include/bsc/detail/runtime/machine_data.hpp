#pragma once
// What a machine holds, and where: the chart (or nothing, for a chart every machine shares), the
// queue, the clock, the timeouts' entry times, the failures, the observer, the context, the
// configuration bytes, the deferred events and the run's status; the types and facts of the
// chart the rest of the driver reads; and the layout helpers that make a member take no room
// where the chart does not need it. The bottom layer of the driver (detail/runtime/driver.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <type_traits>
#include <utility>

#include <bsc/chart_ref.hpp>
#include <bsc/configuration.hpp>
#include <bsc/detail/machine_base.hpp>
#include <bsc/detail/invoke.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/model/completion.hpp>
#include <bsc/detail/model/layout.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/detail/runtime/context_data.hpp>
#include <bsc/detail/runtime/event_queue.hpp>
#include <bsc/detail/runtime/failures.hpp>
#include <bsc/duration.hpp>
#include <bsc/observer.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>

namespace bsc::detail {

// Whether a row's guard or action can throw, called as a machine calls it: a transition's
// guard with (context, event), or (context, event, configuration) if it tests the configuration
// (bsc::in<S>), and its action with (context, event, queue), an entry or exit action with
// (context, queue).
template <class Context, class Queue, class Row>
struct row_nothrow {  // an entry or exit row
    static constexpr bool value = nothrow_callable_with<decltype(Row::action), Context&, Queue&>;
};
template <class G, class Context, class E, bool = tests_configuration<G>>
inline constexpr bool guard_call_nothrow = nothrow_callable_with<G, Context const&, E const&>;
template <class G, class Context, class E>
inline constexpr bool guard_call_nothrow<G, Context, E, true> =
    nothrow_callable_with<G, Context const&, E const&, any_configuration const&>;
template <class Context, class Queue, class S, class Trigger, class G, class A, class T>
struct row_nothrow<Context, Queue, transition_row<S, Trigger, G, A, T>> {
    using event = row_event_t<transition_row<S, Trigger, G, A, T>>;
    static constexpr bool value = guard_call_nothrow<G, Context, event> &&
                                  nothrow_callable_with<A, Context&, event const&, Queue&>;
};

// Whether any guard or action of the chart can throw. If none can (each is noexcept, or the
// code is built without exceptions), a machine keeps no record of failures and never checks
// for one: containing failures costs nothing where nothing can fail.
template <class Model, class Queue>
constexpr bool chart_may_throw() {
#if defined(__cpp_exceptions)
    // clang-format off
    return []<class... Rows>(type_list<Rows...>) {
        return !all_true({row_nothrow<typename Model::chart_context, Queue, Rows>::value...});
    }(typename Model::row_types{});
    // clang-format on
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
    is_chart_ref<Chart> || (all_true({(std::is_empty_v<Rows> && std::is_default_constructible_v<Rows>)...}) &&
                            std::is_default_constructible_v<Chart>);
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

// The clock and its started flag of a machine that keeps no clock (machine_data::keeps_clock): two
// types, so that both members take no room.
struct no_clock {};
struct no_clock_start {};

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class machine_data : public machine_base {
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
    using configuration_type = configuration<static_cast<std::size_t>(tree.slots), typename model::ordinal_type>;
    using event_types = typename model::events;
    using policy_type = Policy;
    using observer_type = Observer;
    /// How many raised events the internal queue holds: Policy::queue_capacity; 0 where no
    /// action of the chart can raise and it takes no done event or bsc::action_failed; 1 where
    /// only done events are queued, one at a time (detail/runtime/queue_for.hpp).
    static constexpr std::size_t queue_capacity = Queue::capacity();

protected:
    constexpr machine_data(Chart const& chart, context_type context, Observer observer)
        : chart_(stored_chart(chart)), observer_{std::move(observer)}, context_{std::move(context)} {}

    // The chart: the machine's copy, or, for a shared chart (is_shared_chart), the one every machine shares.
    constexpr chart_type const& chart() const {
        if constexpr (is_shared_chart<chart_type>)
            return shared_chart<chart_type>;
        else
            return chart_;
    }


    // Whether the chart sends delayed events (bsc::raise_after): its queue keeps them.
    static constexpr bool delays_events = requires(Queue & q) { q.release_due(duration{}); };
    // Whether the machine keeps the time of its last cycle. Timeouts count from it (their entry
    // times are the clock's), and timers and delayed events run on it, so that a caller's time
    // that goes backwards does not reach them; without any of these, only now() and the report
    // of a clock that went backwards read it, and a policy may leave it out (keep_clock).
    static constexpr bool keeps_clock = Policy::keep_clock || layout::timeout_slots > 0 || has_timers<context_type> ||
                                        delays_events;

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

    // Whether the chart defers events (`/ bsc::defer`): then the machine keeps them.
    static constexpr bool defers = model::has_deferral;
    using completion = detail::completion<model>;
    // Whether a guard or action of the chart can throw (detail::chart_may_throw).
    static constexpr bool may_throw = chart_may_throw<model, Queue>();

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
                active[s] = active[p] && (tree.slot[p] < 0 ||
                                          config_.active[static_cast<std::size_t>(tree.slot[p])] == tree.ordinal[s]);
            }
        else
            for (std::size_t s = 1; s < state_count; ++s) active[s] = true;
        return active;
    }

    // True once a final child of the root is active (the driver's halted()).
    constexpr bool halted() const {
        if constexpr (layout::can_halt)
            return layout::final_root_children[config_.active[static_cast<std::size_t>(tree.slot[root])]];
        else
            return false;
    }

    // The back end this driver is the base of.
    constexpr Backend& backend() { return static_cast<Backend&>(*this); }
    constexpr Backend const& backend() const { return static_cast<Backend const&>(*this); }

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
    // The first failure of the current run that no transition took.
    [[no_unique_address]] std::conditional_t<may_throw, failure_slot, no_failure_slot> failure_;
    // The failure of the last run, for last_failure(), under a policy that does not rethrow.
    [[no_unique_address]] std::conditional_t<Policy::rethrow_failures || !may_throw, no_failure_slot, failure_slot>
        reported_;
    [[no_unique_address]] whole<Observer> observer_;
    [[no_unique_address]] whole<context_type> context_;
    configuration_type config_{};
    [[no_unique_address]] entering_flags<completion::parallel_count> entering_;
    // The events deferred (`/ bsc::defer`), oldest first, and the state of their retries.
    [[no_unique_address]] std::conditional_t<
        defers, event_queue<deferred_capacity_of<Policy, defers>, typename model::events>, no_deferral>
        deferred_;
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
