// EXPECT: defect=clock_not_kept<bsc::lean_policy>
// A machine under bsc::lean_policy whose chart needs no time keeps no clock: asking for the time
// of its last cycle does not compile.
#include "two_states.hpp"

namespace cf {
bool run() {
    bsc::machine<decltype(chart), bsc::lean_policy> m{chart};
    m.step(bsc::duration{5});
    return m.now() == bsc::duration{5};
}
}  // namespace cf
