// Twin of shadowed_by_family.fail.cpp: the row on error_send comes first, so it takes
// error_send, and the row on its family `error` takes the other errors.
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
    bsc::state<Idle> + bsc::event<error_send> = bsc::state<Retry>,
    bsc::state<Idle> + bsc::event<error> = bsc::state<Fault>, bsc::state<Fault> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Retry> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
