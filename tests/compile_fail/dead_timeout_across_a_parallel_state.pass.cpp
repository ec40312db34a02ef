// The twin: P's timeout is guarded, so C's fires whenever P's guard is false.
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
struct ctx {
    bool leave = false;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<P>,
                         bsc::composite<P>(bsc::initial<Q>, bsc::parallel<Q>(bsc::composite<R1>(bsc::initial<C>),
                                                                             bsc::composite<R2>(bsc::initial<X>))),
                         bsc::state<OutC>, bsc::state<OutP>),
    bsc::state<C> + bsc::after(1s) = bsc::state<OutC>,
    bsc::state<P> + bsc::after(1s)[([](ctx const& c) { return c.leave; })] = bsc::state<OutP>,
    bsc::state<OutC> + bsc::event<go> = bsc::state<P>, bsc::state<OutP> + bsc::event<go> = bsc::state<P>);
}  // namespace cf
