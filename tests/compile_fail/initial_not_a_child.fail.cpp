// EXPECT: (bsc::error::initial_not_a_child<cf::Busy, cf::Sub1>.*bsc: the initial state named by this composite is declared elsewhere|bsc: the initial state named by this composite is declared elsewhere.*bsc::error::initial_not_a_child<cf::Busy, cf::Sub1>)
// Busy names Sub1 as its initial child, but Sub1 is declared as a child of Root.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct Sub1;
struct Sub2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Sub1>,
                         bsc::composite<Busy>(bsc::initial<Sub1>, bsc::state<Sub2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Sub2> + bsc::event<go> = bsc::state<Sub1>,
    bsc::state<Sub1> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
