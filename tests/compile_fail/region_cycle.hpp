#pragma once
// A chart whose eventless livelock depends on the priority (bsc/priority.hpp): A and B, in a
// region of P, lead to each other without an event, and P itself leaves for Done without one.
// Child first, A's and B's rows are tried before P's, and the region cycles; parent first, P's
// row is, and the machine halts in Done. (tests/unit/priority_test.cpp runs the second.)
#include <bsc/bsc.hpp>

namespace cf {
struct Root;
struct P;
struct R1;
struct R2;
struct A;
struct B;
struct C;
struct Done;
struct region_ctx {};

template <bsc::priority Priority>
constexpr auto region_cycle() {
    return bsc::make_chart<region_ctx, Priority>(
        bsc::composite<Root>(bsc::initial<P>,
                             bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A>, bsc::state<A>, bsc::state<B>),
                                              bsc::composite<R2>(bsc::initial<C>)),
                             bsc::final_state<Done>),
        bsc::state<P> = bsc::state<Done>, bsc::state<A> = bsc::state<B>, bsc::state<B> = bsc::state<A>);
}
}  // namespace cf
