// Twin of local_target_outside_source.fail.cpp: the local transition now goes to Step1, below Work.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct reset {};
struct Root;
struct Idle;
struct Work;
struct Step1;
struct Step2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step1>, bsc::state<Step2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>,
    bsc::state<Work> + bsc::event<reset> = bsc::local(bsc::state<Step1>),
    bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Step2> + bsc::event<go> = bsc::state<Step1>);
}  // namespace cf
