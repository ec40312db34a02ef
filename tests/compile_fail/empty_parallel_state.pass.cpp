// The twin of empty_parallel_state.fail.cpp: P has a region.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct P;
struct R1;
struct A;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A>))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<P>,
    bsc::state<P> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
