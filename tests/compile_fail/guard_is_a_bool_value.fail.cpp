// EXPECT: bsc::error::guard_is_a_bool_value<bool>
// `!` applied to a plain lambda (a forgotten bsc::guard) makes the guard a bool value: the
// lambda converts to a function pointer, and that to true.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {
    bool ready = false;
};
inline constexpr auto ready = [](ctx const& c) { return c.ready; };

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<go>[!ready] = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
