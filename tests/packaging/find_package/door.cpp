// A chart compiled from an SCXML document by bsc_add_scxml (door.scxml): the door opens, and
// closes by itself 5 s later.
#include <chrono>

#include "door.hpp"

int main() {
    using namespace std::chrono_literals;
    door::machine m{door::chart};
    bool ok = m.dispatch(door::events::open{}) == bsc::outcome::consumed && m.is<door::states::opened>();
    m.step(0s);
    m.step(5s);  // the delayed close
    ok = ok && m.is<door::states::closed>() && m.context().openings == 1;
    ok = ok && m.dispatch(door::events::lock{}) == bsc::outcome::consumed && m.is<door::states::locked>();
    return ok ? 0 : 1;
}
