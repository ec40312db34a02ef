// Workload sml_complex, Boost.Statechart: the ring of 50 sc::simple_state generated with
// templates. A transition with a guard is, in Statechart, a custom reaction: react() tests the
// guard `holds` (which returns true) and transits with the action Machine::nothing (which does
// nothing), as in Boost.SML's benchmark; were the guard false, it would discard the event.

#include <boost/statechart/custom_reaction.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <tuple>
#include <utility>

#include "sml_complex_workload.hpp"

namespace {

namespace sc = boost::statechart;
constexpr std::size_t N = sml_complex_bench::workload::states;

template <std::size_t K>
struct E : sc::event<E<K>> {};  // E<K> is e(K+1)
template <std::size_t K>
struct S;  // S<0> is idle

struct Machine : sc::state_machine<Machine, S<0>> {
    template <std::size_t K>
    bool holds(E<K> const&) const {
        return true;
    }
    template <std::size_t K>
    void nothing(E<K> const&) {}
};

template <std::size_t K>
struct S : sc::simple_state<S<K>, Machine> {
    using reactions = sc::custom_reaction<E<K>>;
    sc::result react(E<K> const& e) {
        if (this->outermost_context().holds(e)) return this->template transit<S<(K + 1) % N>>(&Machine::nothing<K>, e);
        return this->discard_event();
    }
};

template <class Seq>
struct events_of;
template <std::size_t... K>
struct events_of<std::index_sequence<K...>> {
    using type = std::tuple<E<K>...>;
};

class ring_machine {
public:
    ring_machine() { m_.initiate(); }
    ring_machine(ring_machine const&) = delete;
    ring_machine& operator=(ring_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<N>(e, [&](auto k) { m_.process_event(std::get<decltype(k)::value>(events_)); });
    }

    sml_complex_bench::workload::observation observe() const {
        std::size_t state = 0;
        find(state, std::make_index_sequence<N>{});
        return {state};
    }

private:
    template <std::size_t... K>
    void find(std::size_t& state, std::index_sequence<K...>) const {
        ((m_.state_cast<S<K> const*>() ? (void)(state = K) : (void)0), ...);
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    typename events_of<std::make_index_sequence<N>>::type events_;
};

}  // namespace

BENCH_IMPL(sml_complex_bench::workload, "boost_statechart", ring_machine);
