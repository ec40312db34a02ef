// Workload fsmb_large, Boost.Statechart: the 25 states are sc::simple_state generated with
// templates. A state's sevent is a custom reaction (react() tests the guard two >= 0, then
// transits with the action Machine::grow), its ievent an sc::in_state_reaction with the action
// Machine::halve. Every state's exit() raises ievent with post_event: Statechart queues a posted
// event and processes it once the current event is done, in the new state. The raised ievent is
// built once, held by the machine through an intrusive_ptr, and posted by that pointer (posting
// a temporary would copy it to the heap every time).

#include <boost/intrusive_ptr.hpp>
#include <boost/mpl/list.hpp>
#include <boost/statechart/custom_reaction.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/in_state_reaction.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <tuple>
#include <utility>

#include "fsmb_large_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;
constexpr std::size_t N = fsmb_large_bench::workload::states;

template <std::size_t K>
struct sevent : sc::event<sevent<K>> {
    int two = 2;
};
struct ievent : sc::event<ievent> {
    int two = 2;
};

template <std::size_t K>
struct State;

struct Machine : sc::state_machine<Machine, State<0>> {
    int counter = 0;
    boost::intrusive_ptr<ievent const> const raised{new ievent};
    template <std::size_t K>
    void grow(sevent<K> const& e) {
        counter = (counter + 1) * e.two;
    }
    void halve(ievent const& e) { counter /= e.two; }
};

template <std::size_t K>
struct State : sc::simple_state<State<K>, Machine> {
    using reactions =
        mpl::list<sc::custom_reaction<sevent<K>>, sc::in_state_reaction<ievent, Machine, &Machine::halve>>;
    sc::result react(sevent<K> const& e) {
        if (e.two >= 0) return this->template transit<State<(K + 1) % N>>(&Machine::grow<K>, e);
        return this->discard_event();
    }
    void exit() { this->post_event(this->outermost_context().raised); }
};

template <class Seq>
struct events_of;
template <std::size_t... K>
struct events_of<std::index_sequence<K...>> {
    using type = std::tuple<sevent<K>...>;
};

class large_machine {
public:
    large_machine() { m_.initiate(); }
    large_machine(large_machine const&) = delete;
    large_machine& operator=(large_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<N>(e, [&](auto k) { m_.process_event(std::get<decltype(k)::value>(events_)); });
    }

    fsmb_large_bench::workload::observation observe() const {
        std::size_t state = 0;
        find(state, std::make_index_sequence<N>{});
        return {state, m_.counter};
    }

private:
    template <std::size_t... K>
    void find(std::size_t& state, std::index_sequence<K...>) const {
        ((m_.state_cast<State<K> const*>() ? (void)(state = K) : (void)0), ...);
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    typename events_of<std::make_index_sequence<N>>::type events_;
};

}  // namespace

BENCH_IMPL(fsmb_large_bench::workload, "boost_statechart", large_machine);
