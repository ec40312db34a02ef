// The twin of lean_now.fail.cpp: the same machine under a lean policy that keeps the clock.
#include "two_states.hpp"

namespace cf {
struct lean_with_clock : bsc::lean_policy {
    static constexpr bool keep_clock = true;
};

bool run() {
    bsc::machine<decltype(chart), lean_with_clock> m{chart};
    m.step(bsc::duration{5});
    return m.now() == bsc::duration{5};
}
}  // namespace cf
