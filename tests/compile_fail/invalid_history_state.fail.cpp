// EXPECT: bsc::error::invalid_history_state<cf::Resume>.*bsc: invalid history state|bsc: invalid history state.*bsc::error::invalid_history_state<cf::Resume>
// The default of Work's history state Resume is Idle, which lies outside Work: a history state
// restores its own composite, so its default must be inside it.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct back {};
struct Root;
struct Idle;
struct Work;
struct Resume;
struct Step1;
struct Step2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Work>(bsc::initial<Step1>, bsc::shallow_history_state<Resume, Idle>,
                                              bsc::state<Step1>, bsc::state<Step2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Resume>,
    bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Idle>);
}  // namespace cf
