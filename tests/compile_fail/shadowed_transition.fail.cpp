// EXPECT: (bsc::error::at_row<2, bsc::error::shadowed_transition<cf::Idle, cf::go, cf::Other>.*bsc: shadowed transition|bsc: shadowed transition.*bsc::error::at_row<2, bsc::error::shadowed_transition<cf::Idle, cf::go, cf::Other>)
// The unguarded transition Idle -go-> Busy comes first, so the guarded Idle -go-> Other
// after it can never fire.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct Root;
struct Idle;
struct Busy;
struct Other;
struct ctx {
    int error = 0;
};
inline constexpr auto failed = bsc::guard([](ctx const& c) { return c.error != 0; });

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Other>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Idle> + bsc::event<go>[failed] = bsc::state<Other>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>,
    bsc::state<Other> + bsc::event<stop> = bsc::state<Idle>);
}  // namespace cf
