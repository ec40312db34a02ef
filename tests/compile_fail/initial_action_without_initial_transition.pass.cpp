// Twin of initial_action_without_initial_transition.fail.cpp: without the history marker, Work
// is entered through its initial transition, whose action counts the starts.
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
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step1>, bsc::state<Step2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Work> + bsc::on_initial / [](ctx& c) { ++c.starts; },
    bsc::state<Step2> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
