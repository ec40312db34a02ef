// EXPECT: defect=at_row<2, shadowed_transition<cf::Idle, cf::error_send, cf::Retry>
// The unguarded row on `error` comes first and takes every error_send too (error_send derives
// from error), so the row on error_send can never fire.
#include <bsc/bsc.hpp>

namespace cf {
struct error {};
struct error_send : error {};
struct go {};
struct Root;
struct Idle;
struct Fault;
struct Retry;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Fault>, bsc::state<Retry>),
    bsc::state<Idle> + bsc::event<error> = bsc::state<Fault>,
    bsc::state<Idle> + bsc::event<error_send> = bsc::state<Retry>,
    bsc::state<Fault> + bsc::event<go> = bsc::state<Idle>, bsc::state<Retry> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
