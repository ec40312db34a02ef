// EXPECT: (bsc::error::last_outcome_not_kept<bsc::lean_policy>.*bsc: this machine's policy has keep_last_outcome = false|bsc: this machine's policy has keep_last_outcome = false.*bsc::error::last_outcome_not_kept<bsc::lean_policy>)
// A machine under bsc::lean_policy keeps no outcome: asking for the last one does not compile.
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
    m.dispatch(go{});
    return m.last_outcome() == bsc::outcome::consumed;
}
}  // namespace cf
