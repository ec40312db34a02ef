// EXPECT: defect=eventless_livelock<cf::A>
// A enters the parallel state P without an event, and X, in P's second region, leads back to A:
// the error names the source of a transition on the cycle, not a state merely entered from it.
#include <bsc/bsc.hpp>

namespace cf {
struct Root;
struct P;
struct R1;
struct R2;
struct X;
struct Y;
struct A;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>,
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<Y>), bsc::composite<R2>(bsc::initial<X>))),
    bsc::state<A> = bsc::state<P>, bsc::state<X> = bsc::state<A>);
}  // namespace cf
