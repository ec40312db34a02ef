// EXPECT: defect=at_row<3, initial_action_without_initial_transition<cf::Work>
// Work remembers its last child (shallow_history): it is always entered through its history,
// never through its initial transition, so an on_initial action would never run.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Work;
struct Step1;
struct Step2;
struct ctx {
    int starts = 0;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Work>(bsc::shallow_history, bsc::initial<Step1>, bsc::state<Step1>, bsc::state<Step2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Work> + bsc::on_initial / [](ctx& c) { ++c.starts; },
    bsc::state<Step2> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
