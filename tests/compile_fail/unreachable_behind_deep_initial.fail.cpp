// EXPECT: defect=unreachable_state<cf::Other>
// Work's deep initial enters Mid on the way to Deep, without Mid's own initial transition: Other,
// Mid's initial child, is entered by nothing.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct back {};
struct Root;
struct Idle;
struct Work;
struct Mid;
struct Other;
struct Deep;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Work>(bsc::initial<Deep>,
                             bsc::composite<Mid>(bsc::initial<Other>, bsc::state<Other>, bsc::state<Deep>))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Other> + bsc::event<go> = bsc::state<Deep>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Idle>);
}  // namespace cf
