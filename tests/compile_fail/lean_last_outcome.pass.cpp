// The twin of lean_last_outcome.fail.cpp: under bsc::lean_policy the outcome is read from what
// dispatch returns.
#include <bsc/bsc.hpp>

namespace cf {
struct go {};
struct Root;
struct Idle;
struct Busy;
struct ctx {};

inline constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
                                                   bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
                                                   bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);

bool run() {
    bsc::machine<decltype(chart), bsc::lean_policy> m{chart};
    return m.dispatch(go{}) == bsc::outcome::consumed;
}
}  // namespace cf
