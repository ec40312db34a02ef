// The twin of lean_now.fail.cpp: the same machine under a lean policy that keeps the clock.
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

struct lean_with_clock : bsc::lean_policy {
    static constexpr bool keep_clock = true;
};

bool run() {
    bsc::machine<decltype(chart), lean_with_clock> m{chart};
    m.step(bsc::duration{5});
    return m.now() == bsc::duration{5};
}
}  // namespace cf
