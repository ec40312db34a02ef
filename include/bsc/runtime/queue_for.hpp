#pragma once
// The internal event queue a machine of a chart needs: none if no action of the chart can raise
// an event (detail::may_raise) and the chart takes neither bsc::action_failed nor a done event.

#include <type_traits>

#include <bsc/action_failed.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/model/chart_model.hpp>
#include <bsc/model/completion.hpp>
#include <bsc/dsl/delayed.hpp>
#include <bsc/runtime/delayed_events.hpp>
#include <bsc/runtime/event_queue.hpp>

namespace bsc::detail {
// Whether any action of the chart can raise an event; if none can, the machine has no queue.
template <class Model, class Policy>
constexpr bool chart_may_raise() {
    using context = typename Model::chart_context;
    using raise = event_queue<Policy::queue_capacity, typename Model::events>;
    return []<class... Rows>(type_list<Rows...>) {
        // (Entry and exit rows see no event; may_raise ignores it for them.)
        return (may_raise<context, row_event_t<Rows>, raise>(static_cast<decltype(Rows::action) const*>(nullptr)) || ...);
    }(typename Model::row_types{});
}

// Whether an action of the chart sends or cancels delayed events (bsc::raise_after): then its
// queue keeps slots for them.
template <class Model>
constexpr bool chart_sends_delayed() {
    return []<class... Rows>(type_list<Rows...>) {
        return (sends_delayed<std::remove_cv_t<decltype(Rows::action)>> || ...);
    }(typename Model::row_types{});
}
// The events the queue of a machine of the chart holds: those its actions raise, where each
// action says which (bsc::raise), the done events and bsc::action_failed the chart takes (the
// machine raises those), in the chart's order; all the chart's events if an action may raise
// anything or raises an event the chart does not name (the queue then stores it as its family).
// Fewer events, fewer alternatives for the code that runs queued events to instantiate.
template <class Model, class Policy>
struct queued_events {
    using context = typename Model::chart_context;
    using full_queue = event_queue<Policy::queue_capacity, typename Model::events>;
    using raised = typename decltype([]<class... Rows>(type_list<Rows...>) {
        return std::type_identity<typename join_raised<decltype(raised_by<context, row_event_t<Rows>, full_queue>(
            static_cast<decltype(Rows::action) const*>(nullptr)))...>::type>{};
    }(typename Model::row_types{}))::type;

    template <class E>
    static constexpr bool machine_raises = is_done_event<E> || __is_same(E, action_failed);
    template <class List>
    struct chosen {
        using type = typename Model::events;
    };
    template <class... Raised>
    struct chosen<type_list<Raised...>> {
        template <class E>
        static constexpr bool kept = machine_raises<E> || index_in<E, Raised...>() >= 0;
        using type = std::conditional_t<
            (... && (index_of<Raised, typename Model::events> >= 0)),
            decltype([]<class... Es>(type_list<Es...>) {
                return (type_list<>{} + ... + std::conditional_t<kept<Es>, type_list<Es>, type_list<>>{});
            }(typename Model::events{})),
            typename Model::events>;
    };
    using type = typename chosen<raised>::type;
};

template <class Policy, bool Sends>
inline constexpr std::size_t delayed_capacity_of = 0;
template <class Policy>
inline constexpr std::size_t delayed_capacity_of<Policy, true> = Policy::delayed_capacity;

// The queue of a machine of the chart (either back end): with slots for delayed events if an
// action sends them; a bounded queue of the chart's events if an action can raise, or the chart
// takes bsc::action_failed or a bsc::done event (which the machine raises); otherwise none, and
// no test for raised events after a microstep.
template <class Chart, class Policy, class Model = chart_model<std::remove_cv_t<Chart>>,
          bool Delays = chart_sends_delayed<Model>()>
using queue_for = std::conditional_t<
    Delays, delaying_queue<Policy::queue_capacity, delayed_capacity_of<Policy, Delays>, typename Model::events>,
    std::conditional_t<chart_may_raise<chart_model<std::remove_cv_t<Chart>>, Policy>() ||
                           chart_model<std::remove_cv_t<Chart>>::template trigger_of<action_failed> >= 0 ||
                           completion<chart_model<std::remove_cv_t<Chart>>>::raises,
                       event_queue<Policy::queue_capacity, typename queued_events<Model, Policy>::type>,
                       no_event_queue>>;
}  // namespace bsc::detail
