// The twin: the row takes the completion of Work, spelt right.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Work;
struct Busy;
struct Idle;
struct Next;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Work>, bsc::composite<Work>(bsc::initial<Busy>, bsc::final_state<Idle>),
                         bsc::state<Next>),
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Work>);
}  // namespace cf
