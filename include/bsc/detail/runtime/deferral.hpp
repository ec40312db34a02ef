#pragma once
// Deferred events (`/ bsc::defer`): what the back ends report while a microstep selects and
// fires (a deferring row, another transition), the event kept when only deferring rows took it,
// and the retries, in the order the events came, after a transition changes the configuration.
// A layer of the driver (detail/runtime/driver.hpp).

#include <type_traits>

#include <bsc/detail/runtime/backend.hpp>
#include <bsc/detail/runtime/run_control.hpp>
#include <bsc/events.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class deferral : public run_control<Backend, Chart, Policy, Observer, Queue> {
    using base = run_control<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using base::defers;
    using base::deferral_;
    using base::deferred_;
    using base::backend;
    using base::keep_failure;

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
        constexpr int trigger = model::template trigger_of<E>::value;
        bool fired = false;
        if constexpr (defers)
            fired = fire_or_defer<trigger>(e);
        else
            fired = backend().template fire<trigger>(e);
        if constexpr (std::is_same_v<E, action_failed>)
            if (!fired) keep_failure(e.error);  // raised, but no transition takes it here
    }
};

}  // namespace bsc::detail
