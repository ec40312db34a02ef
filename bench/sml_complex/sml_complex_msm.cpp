// Workload sml_complex, Boost.MSM: back::state_machine with the functor front end, the ring of
// 50 states generated with templates: one Row per state, with the guard `holds` (a functor that
// returns true) and the action `nothing` (a functor that does nothing), as in Boost.SML's
// benchmark. no_exception_thrown and no_message_queue are set. C++17 (bench/CMakeLists.txt).

// 50 rows, states and events: raise MPL's limits as MSM's documentation says, before any Boost
// header.
#define BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS
#define BOOST_MPL_LIMIT_VECTOR_SIZE 50
#define BOOST_MPL_LIMIT_MAP_SIZE 50

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>
#include <utility>

#include "sml_complex_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::Row;

constexpr std::size_t N = sml_complex_bench::workload::states;

template <std::size_t K>
struct S : msm::front::state<> {};  // S<0> is idle
template <std::size_t K>
struct E {};  // E<K> is e(K+1)

struct holds {
    template <class Ev, class F, class Src, class Tgt>
    bool operator()(Ev const&, F&, Src&, Tgt&) const {
        return true;
    }
};
struct nothing {
    template <class Ev, class F, class Src, class Tgt>
    void operator()(Ev const&, F&, Src&, Tgt&) const {}
};

template <class Seq>
struct ring_rows;
template <std::size_t... K>
struct ring_rows<std::index_sequence<K...>> {
    using type = mpl::vector<Row<S<K>, E<K>, S<(K + 1) % N>, nothing, holds>...>;
};

struct ring_ : msm::front::state_machine_def<ring_> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    using initial_state = S<0>;
    using transition_table = typename ring_rows<std::make_index_sequence<N>>::type;
    template <class Ev, class F>
    void no_transition(Ev const&, F&, int) {}
};
using ring = msm::back::state_machine<ring_>;

class ring_machine {
public:
    ring_machine() { m_.start(); }
    ring_machine(ring_machine const&) = delete;
    ring_machine& operator=(ring_machine const&) = delete;

    void on(std::uint8_t e) {
        bench::with_index<N>(e, [&](auto k) { m_.process_event(E<decltype(k)::value>{}); });
    }

    sml_complex_bench::workload::observation observe() const {
        std::size_t state = 0;
        find(m_.current_state()[0], state, std::make_index_sequence<N>{});
        return {state};
    }

private:
    template <std::size_t... K>
    static void find(int id, std::size_t& state, std::index_sequence<K...>) {
        ((id == msm::back::get_state_id<ring::stt, S<K>>::value ? (void)(state = K) : (void)0), ...);
    }

    ring m_;
};

}  // namespace

BENCH_IMPL(sml_complex_bench::workload, "boost_msm", ring_machine);
