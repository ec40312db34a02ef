// Twin of eventless_livelock_parallel.fail.cpp: X waits for a guard, which breaks the cycle.
#include <bsc/bsc.hpp>

namespace cf {
struct Root;
struct P;
struct R1;
struct R2;
struct X;
struct Y;
struct A;
struct ctx {
    bool leave = false;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>,
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<Y>), bsc::composite<R2>(bsc::initial<X>))),
    bsc::state<A> = bsc::state<P>, bsc::state<X>[([](ctx const& c) { return c.leave; })] = bsc::state<A>);
}  // namespace cf
