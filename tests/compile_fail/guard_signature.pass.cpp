// Twin of guard_signature.fail.cpp: the guard takes the context.
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
    bool operator()(ctx const&) const { return true; }
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
