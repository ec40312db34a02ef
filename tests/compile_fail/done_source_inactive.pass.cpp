// The twin: the row on bsc::done<Work> leaves Work itself, active when Work completes.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Work;
struct Busy;
struct Finished;
struct Next;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Work>, bsc::composite<Work>(bsc::initial<Busy>, bsc::final_state<Finished>),
                         bsc::state<Next>),
    bsc::state<Busy> + bsc::event<go> = bsc::state<Finished>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Work>);
}  // namespace cf
