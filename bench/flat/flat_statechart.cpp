// Workload flat, Boost.Statechart: 50 sc::simple_state, each with one sc::transition whose
// action (a member of the machine) adds to the count; generated from N with templates.

#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "flat_workload.hpp"

namespace {

namespace sc = boost::statechart;
constexpr std::size_t N = flat_bench::workload::states;

template <std::size_t K>
struct E : sc::event<E<K>> {};
template <std::size_t I>
struct S;

struct Machine : sc::state_machine<Machine, S<0>> {
    std::uint64_t count = 0;
    template <std::size_t I>
    void act(E<flat_bench::handled_by(I, N)> const&) {
        count += I + 1;
    }
};

template <std::size_t I>
struct S : sc::simple_state<S<I>, Machine> {
    using reactions =
        sc::transition<E<flat_bench::handled_by(I, N)>, S<flat_bench::next_of(I, N)>, Machine, &Machine::act<I>>;
};

template <class Seq>
struct events_of;
template <std::size_t... K>
struct events_of<std::index_sequence<K...>> {
    using type = std::tuple<E<K>...>;
};

class flat_machine {
public:
    flat_machine() { m_.initiate(); }
    flat_machine(flat_machine const&) = delete;
    flat_machine& operator=(flat_machine const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<N>(event, [&](auto i) { m_.process_event(std::get<decltype(i)::value>(events_)); });
    }

    flat_bench::workload::observation observe() const {
        std::size_t state = 0;
        find(state, std::make_index_sequence<N>{});
        return {state, m_.count};
    }

private:
    template <std::size_t... I>
    void find(std::size_t& state, std::index_sequence<I...>) const {
        ((m_.state_cast<S<I> const*>() ? (void)(state = I) : (void)0), ...);
    }

    Machine m_;
    typename events_of<std::make_index_sequence<N>>::type events_;
};

}  // namespace

BENCH_IMPL(flat_bench::workload, "boost_statechart", flat_machine);
