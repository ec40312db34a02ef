// EXPECT: (bsc::error::at_row<1, bsc::error::in_row<cf::Idle, cf::go, cf::Busy, bsc::error::guard_signature_not_supported<cf::bad_guard> ?>.*bsc: a guard must be callable as|bsc: a guard must be callable as.*bsc::error::at_row<1, bsc::error::in_row<cf::Idle, cf::go, cf::Busy, bsc::error::guard_signature_not_supported<cf::bad_guard> ?>)
// The guard takes a cf::unrelated, which is neither the context nor the event, so it
// cannot be called with (context, event), (context) or (). make_chart reports it with its
// row, bsc::error::in_row<cf::Idle, cf::go, cf::Busy, ...>.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct stop {};
struct unrelated {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    int error = 0;
};
struct bad_guard {
    bool operator()(unrelated const&) const { return true; }
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go>[bad_guard{}] = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<stop> = bsc::state<Idle>);

void run() {
    bsc::machine m{chart, ctx{}};
    m.dispatch(go{});
}
}  // namespace cf
