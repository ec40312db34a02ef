// Twin of in_of_history_state.fail.cpp: the guard tests bsc::in<Step2>, a state Work's history
// restores, so a pause leaves Work only from its first step.
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
    bsc::state<Work> + bsc::event<pause>[!bsc::in<Step2>] = bsc::state<Idle>,
    bsc::state<Step2> + bsc::event<go> = bsc::state<Step1>);

static_assert([] {
    bsc::machine m{chart};
    m.dispatch(go{});     // Idle -> Resume: never active before, Step1
    m.dispatch(go{});     // Step2
    m.dispatch(pause{});  // In(Step2): stays
    bool const kept = m.is<Step2>();
    m.dispatch(go{});  // Step1
    m.dispatch(pause{});
    return kept && m.is<Idle>();
}());
}  // namespace cf
