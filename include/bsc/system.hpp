#pragma once
// Systems of actors (the COMDES-II paper [COMDES]; the modules of the ECA paper [ECA]; see
// docs/references.md): several machines — controllers and plant models — wired by typed signals
// from output channels to input channels, stepped in a declared order with the time given from
// outside. The wiring is one list, the system's actor diagram.

#include <cstddef>
#include <tuple>
#include <type_traits>

#include <bsc/data/timer.hpp>
#include <bsc/outcome.hpp>

namespace bsc {

/// What the consumer of a link reads while the link's publisher is silent, when the two actors
/// run on different nodes (<bsc/net/node.hpp>). In one process a link is never stale, and the
/// policy changes nothing.
///
/// `hold_last` (the default): the last value received stays, as a latched level would.
struct hold_last {};

/// `fail_safe<V>`: the consumer reads `V` until the publisher is heard again, e.g. a motor
/// command that reads "stop" when its controller is lost. V is a structural value of the link's
/// type (a number, an enumerator, an aggregate of those).
template <auto V>
struct fail_safe {
    static constexpr auto value = V;
};

/// `lossless`: the link is never stale; the consumer waits for every value, however long its
/// publisher is silent, and the publisher waits for the consumer. For the couplings of a
/// simulated plant (a brick handed from one machine to the next), where a missed value is a
/// lost object, not a late one.
struct lossless {};

/// A signal: the published value of output channel `FromChannel` of actor `FromActor` is
/// written into input channel `ToChannel` of actor `ToActor` just before `ToActor` steps.
/// Actors are members of the system's aggregate; channels are members of their contexts.
/// `WhenStale` (hold_last, fail_safe<V> or lossless) says what the consumer reads when the two
/// run on different nodes and the publisher falls silent.
template <auto FromActor, auto FromChannel, auto ToActor, auto ToChannel, class WhenStale = hold_last>
struct link {
    static constexpr auto from_actor = FromActor;
    static constexpr auto from_channel = FromChannel;
    static constexpr auto to_actor = ToActor;
    static constexpr auto to_channel = ToChannel;
    using when_stale = WhenStale;

    template <class Actors>
    static constexpr void transfer(Actors& actors) {
        auto const& source = (actors.*FromActor).context().*FromChannel;
        ((actors.*ToActor).context().*ToChannel).set(source.get());
    }
    template <auto Actor>
    static constexpr bool targets() {
        if constexpr (std::is_same_v<decltype(Actor), decltype(ToActor)>)
            return Actor == ToActor;
        else
            return false;
    }
};

/// The order in which a system steps its actors, as pointers to the aggregate's members.
template <auto... Actors>
struct order {};

/// What one system step did.
struct system_report {
    int transitions = 0;  ///< condition-driven transitions fired by all actors
    bool queue_overflow = false;
    bool livelock = false;
    bool halted = false;  ///< some actor is halted (a final child of its root is active)
};

template <class Actors, class Order, class... Links>
struct system;

/// A system: the aggregate `Actors` of machines (anything with `context()` and `step(now)`),
/// stepped in `Order`, with `Links` delivering signals. `actors` is a public member, so a
/// system is itself an aggregate that the explorer can encode. No heap.
template <class Actors, auto... Steps, class... Links>
struct system<Actors, order<Steps...>, Links...> {
    using actors_type = Actors;
    using order_type = order<Steps...>;
    using links_type = std::tuple<Links...>;

    Actors actors;

    /// One step of every actor, in order: each first receives the signals linked to it (the
    /// outputs its senders published, this step for senders earlier in the order, the last
    /// step for the others), then runs one cycle at `now`.
    constexpr system_report step(duration now) {
        system_report report;
        (step_one<Steps>(now, report), ...);
        return report;
    }

private:
    template <auto Actor>
    constexpr void step_one(duration now, system_report& report) {
        ((Links::template targets<Actor>() ? Links::transfer(actors) : void()), ...);
        auto const r = (actors.*Actor).step(now);
        report.transitions += r.transitions;
        report.queue_overflow = report.queue_overflow || r.status == outcome::queue_overflow;
        report.livelock = report.livelock || r.status == outcome::livelock;
        report.halted = report.halted || r.status == outcome::halted || (actors.*Actor).halted();
    }
};

}  // namespace bsc
