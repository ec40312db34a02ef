// The twin: the lambda wrapped in bsc::guard, so that `!` negates the condition.
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
    bsc::state<Idle> + bsc::event<go>[!bsc::guard(ready)] = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace cf
