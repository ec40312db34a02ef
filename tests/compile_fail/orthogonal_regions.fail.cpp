// EXPECT: (bsc::error::at_row<1, bsc::error::transition_between_orthogonal_regions<cf::A, cf::B>.*bsc: transition between orthogonal regions|bsc: transition between orthogonal regions.*bsc::error::at_row<1, bsc::error::transition_between_orthogonal_regions<cf::A, cf::B>)
// A and B lie in the two regions of the parallel state P, which are always active
// together, so a transition from A to B has no meaning.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct P;
struct R1;
struct R2;
struct A;
struct B;
struct Done;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<P>,
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A>), bsc::composite<R2>(bsc::initial<B>)),
                         bsc::state<Done>),
    bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<B> + bsc::event<stop> = bsc::state<Done>,
    bsc::state<Done> + bsc::event<go> = bsc::state<P>);
}  // namespace cf
