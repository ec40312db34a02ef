// Twin of event_not_dispatchable.fail.cpp: Work completes the way it does, by entering its final
// state; the machine raises bsc::done<Work> itself.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct finish {};
struct Root;
struct Idle;
struct Work;
struct Busy;
struct Finished;
struct Next;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<Busy>, bsc::final_state<Finished>),
                         bsc::state<Next>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Busy> + bsc::event<finish> = bsc::state<Finished>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
    m.dispatch(finish{});
}
}  // namespace cf
