// Workload deep, Boost.Statechart: D1..D8 are sc::state nested eight deep (sc::state so that
// the entry action can reach the machine), P1..P8 sc::simple_state; each transition is an
// sc::transition declared on the state of its level, its action a member of the machine.
// Statechart looks for a reaction from the innermost state outwards.

#include <boost/mpl/list.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "deep_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;

template <int K>
struct L : sc::event<L<K>> {};

struct R;
template <int K>
struct D;
template <int K>
struct P;

struct Machine : sc::state_machine<Machine, R> {
    std::uint64_t count = 0;
    std::uint64_t entries = 0;
    template <int K>
    void leave(L<K> const&) {
        count += static_cast<std::uint64_t>(K);
    }
    template <int K>
    void come_back(L<K> const&) {
        count += 100u * static_cast<std::uint64_t>(K);
    }
};

struct R : sc::simple_state<R, Machine, D<1>> {};

// The levels are written out (a class template D<K> would need D<K-1> complete while D<K-1>
// itself is being defined).
#define BENCH_DEEP_LEVEL(K, OUTER, INNER)                                              \
    template <>                                                                        \
    struct D<K> : sc::state<D<K>, OUTER, INNER> {                                      \
        using reactions = sc::transition<L<K>, P<K>, Machine, &Machine::leave<K>>;     \
        explicit D(my_context ctx) : my_base(ctx) { ++outermost_context().entries; }   \
    };                                                                                 \
    template <>                                                                        \
    struct P<K> : sc::simple_state<P<K>, OUTER> {                                      \
        using reactions = sc::transition<L<K>, D<K>, Machine, &Machine::come_back<K>>; \
    };

BENCH_DEEP_LEVEL(1, R, D<2>)
BENCH_DEEP_LEVEL(2, D<1>, D<3>)
BENCH_DEEP_LEVEL(3, D<2>, D<4>)
BENCH_DEEP_LEVEL(4, D<3>, D<5>)
BENCH_DEEP_LEVEL(5, D<4>, D<6>)
BENCH_DEEP_LEVEL(6, D<5>, D<7>)
BENCH_DEEP_LEVEL(7, D<6>, D<8>)
BENCH_DEEP_LEVEL(8, D<7>, mpl::list<>)
#undef BENCH_DEEP_LEVEL

class deep_machine {
public:
    deep_machine() { m_.initiate(); }
    deep_machine(deep_machine const&) = delete;
    deep_machine& operator=(deep_machine const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<deep_bench::levels>(event,
                                              [&](auto i) { m_.process_event(std::get<decltype(i)::value>(events_)); });
    }

    deep_bench::workload::observation observe() const {
        int depth = 8;
        find(depth, std::make_integer_sequence<int, 8>{});
        return {depth, m_.count, m_.entries};
    }

private:
    template <int... K>
    void find(int& depth, std::integer_sequence<int, K...>) const {
        ((m_.state_cast<P<K + 1> const*>() ? (void)(depth = K) : (void)0), ...);
    }

    Machine m_;
    std::tuple<L<1>, L<2>, L<3>, L<4>, L<5>, L<6>, L<7>, L<8>> events_;
};

}  // namespace

BENCH_IMPL(deep_bench::workload, "boost_statechart", deep_machine);
