// EXPECT: transition_row<cf::C, bsc::detail::timeout_trigger, [^>]*, cf::OutC>::~transition_row|timeout_row_never_fires\(1, 2\)
// C's and P's timeouts come due together (C, in a region of Q, is entered with P), and P's
// component, the root, takes its turn in the cycle before C's region: P's row leaves P, and C's
// never fires, child first as parent first.
#include <bsc/bsc.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace cf {
struct go {};
struct Root;
struct P;
struct Q;
struct R1;
struct R2;
struct C;
struct X;
struct OutC;
struct OutP;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<P>,
                         bsc::composite<P>(bsc::initial<Q>, bsc::parallel<Q>(bsc::composite<R1>(bsc::initial<C>),
                                                                             bsc::composite<R2>(bsc::initial<X>))),
                         bsc::state<OutC>, bsc::state<OutP>),
    bsc::state<C> + bsc::after(1s) = bsc::state<OutC>, bsc::state<P> + bsc::after(1s) = bsc::state<OutP>,
    bsc::state<OutC> + bsc::event<go> = bsc::state<P>, bsc::state<OutP> + bsc::event<go> = bsc::state<P>);
}  // namespace cf
