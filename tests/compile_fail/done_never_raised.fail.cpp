// EXPECT: bsc::error::done_never_raised<cf::Work>
// Work has no final child, so it never completes and bsc::done<Work> is never raised: the row
// on it can never fire.
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
    bsc::composite<Root>(bsc::initial<Work>, bsc::composite<Work>(bsc::initial<Busy>, bsc::state<Idle>),
                         bsc::state<Next>),
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Work>);
}  // namespace cf
