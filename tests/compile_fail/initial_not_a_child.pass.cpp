// Twin of initial_not_a_child.fail.cpp: Busy names its own child Sub2 as initial.
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
                         bsc::composite<Busy>(bsc::initial<Sub2>, bsc::state<Sub2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Sub2> + bsc::event<go> = bsc::state<Sub1>,
    bsc::state<Sub1> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
