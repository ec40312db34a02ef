// Workload wide, Boost.Statechart: W is an sc::simple_state with 8 orthogonal regions
// (its inner initial states as an mpl::list); each region's states are sc::simple_state of
// W::orthogonal<r>. Statechart does not broadcast: process_event offers the event to the leaf
// states in turn and stops at the first reaction that consumes it. So a broadcast event is
// processed as 8 events, one per region (its own event types step_r, reset_r, flip_r); the
// cost of an event below is that of the 8 process_event calls.

#include <boost/mpl/list.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "wide_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;
using namespace wide_bench;

template <int R>
struct step : sc::event<step<R>> {};
template <int R>
struct reset : sc::event<reset<R>> {};
template <int R>
struct flip : sc::event<flip<R>> {};

struct W;
template <int R, int J>
struct A;

struct Machine : sc::state_machine<Machine, W> {
    std::array<std::uint64_t, regions> n{};
    template <int R>
    void stepped(step<R> const&) {
        n[R] += 1;
    }
    template <int R>
    void was_reset(reset<R> const&) {
        n[R] += 16;
    }
    template <int R>
    void flipped(flip<R> const&) {
        n[R] += 4;
    }
};

struct W
    : sc::simple_state<W, Machine,
                       mpl::list<A<0, initial_of(0)>, A<1, initial_of(1)>, A<2, initial_of(2)>, A<3, initial_of(3)>,
                                 A<4, initial_of(4)>, A<5, initial_of(5)>, A<6, initial_of(6)>, A<7, initial_of(7)>>> {
};

template <int R>
struct A<R, 0> : sc::simple_state<A<R, 0>, W::orthogonal<R>> {
    using reactions = mpl::list<sc::transition<step<R>, A<R, 1>, Machine, &Machine::stepped<R>>,
                                sc::transition<flip<R>, A<R, flip_target(R)>, Machine, &Machine::flipped<R>>>;
};
template <int R>
struct A<R, 1> : sc::simple_state<A<R, 1>, W::orthogonal<R>> {
    using reactions = mpl::list<sc::transition<step<R>, A<R, 2>, Machine, &Machine::stepped<R>>,
                                sc::transition<reset<R>, A<R, 0>, Machine, &Machine::was_reset<R>>>;
};
template <int R>
struct A<R, 2> : sc::simple_state<A<R, 2>, W::orthogonal<R>> {
    using reactions = mpl::list<sc::transition<step<R>, A<R, 0>, Machine, &Machine::stepped<R>>,
                                sc::transition<reset<R>, A<R, 0>, Machine, &Machine::was_reset<R>>>;
};

template <template <int> class Ev, class Seq>
struct per_region;
template <template <int> class Ev, int... R>
struct per_region<Ev, std::integer_sequence<int, R...>> {
    using type = std::tuple<Ev<R>...>;
};
template <template <int> class Ev>
using events_of = typename per_region<Ev, std::make_integer_sequence<int, int(regions)>>::type;

class wide_machine {
public:
    wide_machine() { m_.initiate(); }
    wide_machine(wide_machine const&) = delete;
    wide_machine& operator=(wide_machine const&) = delete;

    void on(std::uint8_t event) {
        switch (event) {
        case 0: broadcast(steps_); break;
        case 1: broadcast(resets_); break;
        default: broadcast(flips_); break;
        }
    }

    workload::observation observe() const {
        workload::observation o{{}, m_.n};
        fill(o, std::make_integer_sequence<int, int(regions)>{});
        return o;
    }

private:
    template <class Tuple>
    void broadcast(Tuple const& events) {
        std::apply([&](auto const&... e) { (m_.process_event(e), ...); }, events);
    }
    template <int... R>
    void fill(workload::observation& o, std::integer_sequence<int, R...>) const {
        ((o.state[R] = m_.state_cast<A<R, 0> const*>() ? 0 : m_.state_cast<A<R, 1> const*>() ? 1 : 2), ...);
    }

    Machine m_;
    events_of<step> steps_;
    events_of<reset> resets_;
    events_of<flip> flips_;
};

}  // namespace

BENCH_IMPL(wide_bench::workload, "boost_statechart", wide_machine);
