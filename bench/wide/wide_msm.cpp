// Workload wide, Boost.MSM: one back::state_machine with 8 orthogonal regions, as MSM declares
// them: initial_state is an mpl::vector of the 8 initial states, and the 48 rows share one
// transition table. MSM offers every event to every region. no_exception_thrown and
// no_message_queue are set. C++17 (bench/CMakeLists.txt).

// 48 rows: raise MPL's limits as MSM's documentation says, before any Boost header.
#define BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS
#define BOOST_MPL_LIMIT_VECTOR_SIZE 50
#define BOOST_MPL_LIMIT_MAP_SIZE 50

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>

#include "wide_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;
using namespace wide_bench;

struct step {};
struct reset {};
struct flip {};

template <int R, int J>
struct A : msm::front::state<> {};

template <int R, int V>
struct add {
    template <class E, class F, class S, class T>
    void operator()(E const&, F& fsm, S&, T&) const {
        fsm.n[R] += V;
    }
};

template <int R>
using region_rows = mpl::vector<
    Row<A<R, 0>, step, A<R, 1>, add<R, 1>, none>, Row<A<R, 1>, step, A<R, 2>, add<R, 1>, none>,
    Row<A<R, 2>, step, A<R, 0>, add<R, 1>, none>, Row<A<R, 1>, reset, A<R, 0>, add<R, 16>, none>,
    Row<A<R, 2>, reset, A<R, 0>, add<R, 16>, none>, Row<A<R, 0>, flip, A<R, flip_target(R)>, add<R, 4>, none>>;

template <class Seq>
struct all_rows;
template <int... R>
struct all_rows<std::integer_sequence<int, R...>> {
    using type = typename mpl::fold<mpl::vector<region_rows<R>...>, mpl::vector<>,
                                    mpl::copy<mpl::_2, mpl::back_inserter<mpl::_1>>>::type;
};

struct W_ : msm::front::state_machine_def<W_> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    using initial_state =
        mpl::vector<A<0, initial_of(0)>, A<1, initial_of(1)>, A<2, initial_of(2)>, A<3, initial_of(3)>,
                    A<4, initial_of(4)>, A<5, initial_of(5)>, A<6, initial_of(6)>, A<7, initial_of(7)>>;
    using transition_table = typename all_rows<std::make_integer_sequence<int, int(regions)>>::type;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
    std::array<std::uint64_t, regions> n{};
};
using W = msm::back::state_machine<W_>;

class wide_machine {
public:
    wide_machine() { m_.start(); }
    wide_machine(wide_machine const&) = delete;
    wide_machine& operator=(wide_machine const&) = delete;

    void on(std::uint8_t event) {
        switch (event) {
        case 0: m_.process_event(step{}); break;
        case 1: m_.process_event(reset{}); break;
        default: m_.process_event(flip{}); break;
        }
    }

    workload::observation observe() const {
        workload::observation o{{}, m_.n};
        fill(o, std::make_integer_sequence<int, int(regions)>{});
        return o;
    }

private:
    template <int... R>
    void fill(workload::observation& o, std::integer_sequence<int, R...>) const {
        ((o.state[R] = state_of<R>(m_.current_state()[R])), ...);
    }
    template <int R>
    static std::uint8_t state_of(int id) {
        using stt = W::stt;
        return id == msm::back::get_state_id<stt, A<R, 0>>::value   ? 0
               : id == msm::back::get_state_id<stt, A<R, 1>>::value ? 1
                                                                    : 2;
    }

    W m_;
};

}  // namespace

BENCH_IMPL(wide_bench::workload, "boost_msm", wide_machine);
