// EXPECT: defect=last_outcome_not_kept<bsc::lean_policy>
// A machine under bsc::lean_policy keeps no outcome: asking for the last one does not compile.
#include "two_states.hpp"

namespace cf {
bool run() {
    bsc::machine<decltype(chart), bsc::lean_policy> m{chart};
    m.dispatch(go{});
    return m.last_outcome() == bsc::outcome::consumed;
}
}  // namespace cf
