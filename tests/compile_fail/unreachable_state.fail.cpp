// EXPECT: (bsc::error::unreachable_state<cf::Orphan>.*bsc: unreachable state|bsc: unreachable state.*bsc::error::unreachable_state<cf::Orphan>)
// Orphan is declared in the tree and has a transition out, but no initial entry and no
// transition leads into it, so it can never become active.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Orphan;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Orphan>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Orphan> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
