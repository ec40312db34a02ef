// Twin of invalid_deferral.fail.cpp: the deferring row has no target.
#include <bsc/bsc.hpp>

namespace cf {
struct start {};
struct job {};
struct finish {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<job> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<job> / bsc::defer,
    bsc::state<Busy> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace cf
