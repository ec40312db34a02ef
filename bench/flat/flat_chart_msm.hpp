#pragma once
// The flat chart of bench/flat/flat_workload.hpp for Boost.MSM, for N = BENCH_FLAT_N states
// (a macro: MSM's transition table is an MPL vector of N rows, and MPL names its vectors of
// N elements vectorN). Include this header before any Boost header.
//
// MSM's tables are MPL vectors of at most 20 entries by default. As MSM's documentation says,
// BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS and BOOST_MPL_LIMIT_VECTOR_SIZE/BOOST_MPL_LIMIT_MAP_SIZE
// raise the limit, up to the 50 of MPL's headers; above 50 the numbered vectors vector51 ..
// vectorN are generated the way MPL's own vector50.hpp generates vector41 .. vector50.

#ifndef BENCH_FLAT_N
#error "define BENCH_FLAT_N, the number of states"
#endif

#define BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS
#define BOOST_MPL_LIMIT_VECTOR_SIZE 50
#define BOOST_MPL_LIMIT_MAP_SIZE 50

#include <boost/mpl/vector.hpp>
#if BENCH_FLAT_N > 50
#include <boost/mpl/aux_/config/ctps.hpp>
#include <boost/mpl/aux_/config/typeof.hpp>
#include <boost/preprocessor/iterate.hpp>
namespace boost {
namespace mpl {
#define BOOST_PP_ITERATION_PARAMS_1 (3, (51, BENCH_FLAT_N, <boost / mpl / vector / aux_ / numbered.hpp>))
#include BOOST_PP_ITERATE()
}  // namespace mpl
}  // namespace boost
#endif

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>
#include <boost/preprocessor/cat.hpp>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace flat_msm {

namespace msm = boost::msm;
namespace mpl = boost::mpl;

inline constexpr std::size_t N = BENCH_FLAT_N;

template <std::size_t I>
struct S : msm::front::state<> {};
template <std::size_t I>
struct E {};

template <std::size_t I>
struct count_action {
    template <class Ev, class F, class Src, class Tgt>
    void operator()(Ev const&, F& fsm, Src&, Tgt&) const {
        fsm.count += I + 1;
    }
};

constexpr std::size_t handled_by(std::size_t i) { return (7 * i + 3) % N; }

template <std::size_t I>
using row = msm::front::Row<S<I>, E<handled_by(I)>, S<(I + 1) % N>, count_action<I>, msm::front::none>;

template <class Seq>
struct table_of;
template <std::size_t... I>
struct table_of<std::index_sequence<I...>> {
    using type = BOOST_PP_CAT(mpl::vector, BENCH_FLAT_N)<row<I>...>;
};

struct flat_ : msm::front::state_machine_def<flat_> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    using initial_state = S<0>;
    using transition_table = typename table_of<std::make_index_sequence<N>>::type;
    template <class Ev, class F>
    void no_transition(Ev const&, F&, int) {}
    std::uint64_t count = 0;
};

using machine = msm::back::state_machine<flat_>;

}  // namespace flat_msm
