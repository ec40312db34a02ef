// The elevator door, explored: the flawed chart (door.hpp) leaves the door open for good after
// an overload that outlasts the dwell time, and so does the one that defers the dwell timer's
// event (when deferred calls fill its room); the fixed one always closes it again. The car is
// driven by a closed model (model.hpp). Exits 0 when the explorer finds the flaw in the first two
// and proves the third.

#include <bsc/verify.hpp>

#include <cstdio>

#include "door.hpp"
#include "model.hpp"

namespace {

// From every state the car can reach, the door can close again.
template <class Machine, auto const& Chart>
bsc::verify::verdict door_closes() {
    bsc::verify::explorer ex{elevator::closed_car<Machine, Chart>()};
    auto v = bsc::verify::always_reachable(ex, "door closed", elevator::door_closed<Machine>);
    std::printf("%zu states explored\n", ex.stats().states);
    return v;
}

}  // namespace

int main() {
    auto const flawed = door_closes<elevator::flawed_machine, elevator::flawed>();
    std::printf("flawed door: %s\n", flawed.to_string().c_str());
    auto const deferring = door_closes<elevator::deferring_machine, elevator::deferring>();
    std::printf("deferring door: %s\n", deferring.to_string().c_str());
    auto const fixed = door_closes<elevator::fixed_machine, elevator::fixed>();
    std::printf("fixed door: %s\n", fixed.to_string().c_str());
    bool const as_expected = flawed.fails() && deferring.fails() && fixed.holds();
    std::puts(as_expected ? "the explorer finds the flaw and proves the fix" : "UNEXPECTED VERDICTS");
    return as_expected ? 0 : 1;
}
