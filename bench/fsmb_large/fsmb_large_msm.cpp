// Workload fsmb_large, Boost.MSM: back::state_machine with the functor front end, the 25 states
// generated with templates: per state one Row for its sevent (guard two >= 0, action grow) and
// one internal Row (target none) for ievent (action halve). Every state's on_exit raises ievent
// with process_event on the machine: MSM puts an event sent to a machine that is processing
// another in the machine's message queue, and processes it once the transition is done, in the
// new state; so the machine keeps its message queue (no no_message_queue). no_exception_thrown
// is set.
// C++17 (bench/CMakeLists.txt).

// 50 rows: raise MPL's limits as MSM's documentation says, before any Boost header.
#define BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS
#define BOOST_MPL_LIMIT_VECTOR_SIZE 50
#define BOOST_MPL_LIMIT_MAP_SIZE 50

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>
#include <utility>

#include "fsmb_large_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;

constexpr std::size_t N = fsmb_large_bench::workload::states;

template <std::size_t K>
struct sevent {
    int two = 2;
};
struct ievent {
    int two = 2;
};

template <std::size_t K>
struct State : msm::front::state<> {
    template <class E, class F>
    void on_exit(E const&, F& fsm) {
        fsm.process_event(ievent{});
    }
};

struct two_positive {
    template <class E, class F, class S, class T>
    bool operator()(E const& e, F&, S&, T&) const {
        return e.two >= 0;
    }
};
struct grow {
    template <class E, class F, class S, class T>
    void operator()(E const& e, F& fsm, S&, T&) const {
        fsm.counter = (fsm.counter + 1) * e.two;
    }
};
struct halve {
    template <class F, class S, class T>
    void operator()(ievent const& e, F& fsm, S&, T&) const {
        fsm.counter /= e.two;
    }
};

template <class Seq>
struct large_rows;
template <std::size_t... K>
struct large_rows<std::index_sequence<K...>> {
    using type = mpl::vector<Row<State<K>, sevent<K>, State<(K + 1) % N>, grow, two_positive>...,
                             Row<State<K>, ievent, none, halve, none>...>;
};

struct large_ : msm::front::state_machine_def<large_> {
    using no_exception_thrown = int;
    using initial_state = State<0>;
    using transition_table = typename large_rows<std::make_index_sequence<N>>::type;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
    int counter = 0;
};
using large = msm::back::state_machine<large_>;

class large_machine {
public:
    large_machine() { m_.start(); }
    large_machine(large_machine const&) = delete;
    large_machine& operator=(large_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<N>(e, [&](auto k) { m_.process_event(sevent<decltype(k)::value>{}); });
    }

    fsmb_large_bench::workload::observation observe() const {
        std::size_t state = 0;
        find(m_.current_state()[0], state, std::make_index_sequence<N>{});
        return {state, m_.counter};
    }

private:
    template <std::size_t... K>
    static void find(int id, std::size_t& state, std::index_sequence<K...>) {
        ((id == msm::back::get_state_id<large::stt, State<K>>::value ? (void)(state = K) : (void)0), ...);
    }

    large m_;
};

}  // namespace

BENCH_IMPL(fsmb_large_bench::workload, "boost_msm", large_machine);
