#pragma once
// The internal event queue a machine of a chart needs: none if no action of the chart can raise
// an event (detail::raised_by_chart) and the chart takes neither bsc::action_failed nor a done
// event; otherwise one that holds only the events that can be raised (detail::queued_events).

#include <type_traits>

#include <bsc/events.hpp>
#include <bsc/detail/config.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/detail/model/chart_model.hpp>
#include <bsc/detail/model/completion.hpp>
#include <bsc/detail/model/layout.hpp>
#include <bsc/dsl/delayed.hpp>
#include <bsc/detail/runtime/delayed_events.hpp>
#include <bsc/detail/runtime/event_queue.hpp>

namespace bsc::detail {
// What the actions of the chart raise (detail::raised_by, one pass over the rows): type_list<>
// if none can raise (the machine then has no queue for them), raises_anything if one may raise
// whatever it likes, else the events the bsc::raise actions name.
// (A class, not an alias template: GCC 12 rejects the lambda in an alias template.)
template <class Model>
struct raised_by_chart {
    // clang-format off
    using type = typename decltype([]<class... Rows>(type_list<Rows...>) {
        using context = typename Model::chart_context;
        // (Entry and exit rows see no event; raised_by ignores it for them.)
        return std::type_identity<join_raised<decltype(raised_by<context, row_event_t<Rows>, raise_stand_in>(
            static_cast<decltype(Rows::action) const*>(nullptr)))...>>{};
    }(typename Model::row_types{}))::type;
    // clang-format on
};

// Whether an action of the chart sends or cancels delayed events (bsc::raise_after): then its
// queue keeps slots for them.
template <class Model>
constexpr bool chart_sends_delayed() {
    // clang-format off
    return []<class... Rows>(type_list<Rows...>) {
        return any_true({sends_delayed<std::remove_cv_t<decltype(Rows::action)>>..., false});
    }(typename Model::row_types{});
    // clang-format on
}

// The events the queue holds: those the actions raise, where each action says which
// (bsc::raise), and the done events and bsc::action_failed the chart takes (the machine raises
// those), in the chart's order; all the chart's events if an action may raise anything or
// raises an event the chart does not name (the queue then stores it as its family). Fewer
// events, fewer alternatives for the code that runs queued events to instantiate.
template <class Model, class Raised>
struct queued_events {
    using type = typename Model::events;
};
template <class Model, class... Raised>
struct queued_events<Model, type_list<Raised...>> {
    template <class E>
    static constexpr bool kept =
        is_done_event<E> || BSC_DETAIL_IS_SAME(E, action_failed) || position_in<E, type_list<Raised...>>::value >= 0;
    using type = std::conditional_t<(... && (position_in<Raised, typename Model::events>::value >= 0)),
                                    // clang-format off
                                    decltype([]<class... Es>(type_list<Es...>) {
                                        return concat_t<std::conditional_t<kept<Es>, type_list<Es>, type_list<>>...>{};
                                    }(typename Model::events{})),
                                    // clang-format on
                                    typename Model::events>;
};

// Whether E{} is a constant expression: a single_event_queue default-constructs its slots, and
// an empty event at each pop, where an event_queue constructs nothing but the events raised. An
// event whose default constructor is not constexpr would then keep a machine out of constant
// expressions, or run code of its own where none ran before.
template <class E>
concept constant_default = requires {
    typename std::bool_constant<(static_cast<void>(E{}), true)>;
};

// The queue of the events Events: a single_event_queue for one trivially copyable event type
// whose default construction is a constant, an event_queue otherwise.
template <std::size_t Capacity, class Events>
struct queue_of {
    using type = event_queue<Capacity, Events>;
};
template <std::size_t Capacity, class E>
    requires(Capacity > 0 && std::is_trivially_copyable_v<E> && constant_default<E>)
struct queue_of<Capacity, type_list<E>> {
    using type = single_event_queue<Capacity, E>;
};

// Whether a machine of the chart never holds more than one queued event: the queue holds done
// events only (no action raises, the chart takes no bsc::action_failed), no state is parallel
// (a microstep then enters at most one final state, and raises at most one done event), and no
// row is eventless, a timeout or deferring (an eventless transition is taken before the queued
// events, and could raise one more; a cycle's or a deferred event's microsteps alike). Every
// microstep is then followed by the one that takes what it raised, and a queue of one slot
// holds what a queue of the policy's capacity would: a completion costs a store and a load, not
// a ring's arithmetic (docs/performance.md, rule "A completion waits in one slot").
template <class Model, class Raised>
constexpr bool one_completion_at_a_time() {
    using layout = chart_layout<Model>;
    return std::is_same_v<Raised, type_list<>> && Model::template trigger_of<action_failed>::value < 0 &&
           !layout::has_parallel && !layout::has_trigger(any_condition) && !Model::has_deferral;
}

// The queue of raised events, worked out only for a chart that has one.
template <bool Needed, class Model, class Policy, class Raised>
struct raise_queue {
    using type = no_event_queue;
};
template <class Model, class Policy, class Raised>
struct raise_queue<true, Model, Policy, Raised> {
    static constexpr std::size_t capacity = Policy::queue_capacity > 0 && one_completion_at_a_time<Model, Raised>()
                                                ? 1
                                                : Policy::queue_capacity;
    using type = typename queue_of<capacity, typename queued_events<Model, Raised>::type>::type;
};

template <class Policy, bool Sends>
inline constexpr std::size_t delayed_capacity_of = 0;
template <class Policy>
inline constexpr std::size_t delayed_capacity_of<Policy, true> = Policy::delayed_capacity;

// The queue of a machine of the chart (either back end): with slots for delayed events if an
// action sends them; a bounded queue of the events the chart raises if an action can raise, or
// the chart takes bsc::action_failed or a bsc::done event (which the machine raises); otherwise
// none, and no test for raised events after a microstep.
template <class Chart, class Policy, class Model = chart_model<std::remove_cv_t<Chart>>,
          bool Delays = chart_sends_delayed<Model>(), class Raised = typename raised_by_chart<Model>::type>
using queue_for = std::conditional_t<
    Delays, delaying_queue<Policy::queue_capacity, delayed_capacity_of<Policy, Delays>, typename Model::events>,
    typename raise_queue<!std::is_same_v<Raised, type_list<>> ||
                             Model::template trigger_of<action_failed>::value >= 0 || completion<Model>::raises,
                         Model, Policy, Raised>::type>;
}  // namespace bsc::detail
