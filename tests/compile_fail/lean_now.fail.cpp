// EXPECT: (bsc::error::clock_not_kept<bsc::lean_policy>.*bsc: this machine keeps no clock|bsc: this machine keeps no clock.*bsc::error::clock_not_kept<bsc::lean_policy>)
// A machine under bsc::lean_policy whose chart needs no time keeps no clock: asking for the time
// of its last cycle does not compile.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

bool run() {
    bsc::machine<decltype(chart), bsc::lean_policy> m{chart};
    m.step(bsc::duration{5});
    return m.now() == bsc::duration{5};
}
}  // namespace cf
