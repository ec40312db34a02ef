// Twin of duplicate_state.fail.cpp: the second declaration of Busy is removed.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Work;
struct Step;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>,
                         bsc::composite<Work>(bsc::initial<Step>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Work>,
    bsc::state<Work> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
