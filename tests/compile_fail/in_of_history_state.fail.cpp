// EXPECT: defect=at_row<3, in_of_history_state<cf::Resume>
// The guard of the third row tests bsc::in<Resume>, Work's history pseudo-state, which is never
// active: the row could never fire.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct pause {};
struct Root;
struct Idle;
struct Work;
struct Resume;
struct Step1;
struct Step2;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step2>,
                                                                  bsc::shallow_history_state<Resume, Step1>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Resume>, bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Work> + bsc::event<pause>[!bsc::in<Resume>] = bsc::state<Idle>,
    bsc::state<Step2> + bsc::event<go> = bsc::state<Step1>);
}  // namespace cf
