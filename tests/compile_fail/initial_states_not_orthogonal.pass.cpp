// Twin of initial_states_not_orthogonal.fail.cpp: Work's initial states are A2 in R1 and B2 in R2.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct back {};
struct Root;
struct Idle;
struct Work;
struct P;
struct R1;
struct R2;
struct A1;
struct A2;
struct B1;
struct B2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Work>(bsc::initial<A2, B2>,
                             bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A1>, bsc::state<A1>, bsc::state<A2>),
                                              bsc::composite<R2>(bsc::initial<B1>, bsc::state<B1>, bsc::state<B2>)))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<A1> + bsc::event<go> = bsc::state<A2>,
    bsc::state<B1> + bsc::event<go> = bsc::state<B2>, bsc::state<A2> + bsc::event<go> = bsc::state<A1>,
    bsc::state<B2> + bsc::event<go> = bsc::state<B1>, bsc::state<Work> + bsc::event<back> = bsc::state<Idle>);
}  // namespace cf
