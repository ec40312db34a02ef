// EXPECT: (bsc::error::empty_parallel_state<cf::P>.*bsc: this parallel state has no regions|bsc: this parallel state has no regions.*bsc::error::empty_parallel_state<cf::P>)
// P is declared parallel but has no regions.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct P;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::parallel<P>()),
    bsc::state<Idle> + bsc::event<go> = bsc::state<P>,
    bsc::state<P> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
