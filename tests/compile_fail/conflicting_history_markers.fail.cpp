// EXPECT: defect=conflicting_history_markers<cf::Busy>
// Busy is marked with both shallow and deep history.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Sub1;
struct Sub2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Busy>(bsc::shallow_history, bsc::deep_history,
                                                                  bsc::initial<Sub1>, bsc::state<Sub2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>, bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>,
    bsc::state<Sub1> + bsc::event<go> = bsc::state<Sub2>);
}  // namespace cf
