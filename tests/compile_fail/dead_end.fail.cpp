// EXPECT: (bsc::error::dead_end_state<cf::Stuck>.*bsc: dead end|bsc: dead end.*bsc::error::dead_end_state<cf::Stuck>)
// Stuck is a basic (non-final) state that no transition leaves: not one from Stuck, from
// an ancestor of Stuck, or from an orthogonal region.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Stuck;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Stuck>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Stuck>);
}  // namespace cf
