// The twin of lean_last_outcome.fail.cpp: under bsc::lean_policy the outcome is read from what
// dispatch returns.
#include "two_states.hpp"

namespace cf {
bool run() {
    bsc::machine<decltype(chart), bsc::lean_policy> m{chart};
    return m.dispatch(go{}) == bsc::outcome::consumed;
}
}  // namespace cf
