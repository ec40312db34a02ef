// The elevator door, explored: the flawed chart (door.hpp) leaves the door open for good after
// an overload that outlasts the dwell time, and so does the one that defers the dwell timer's
// event (when deferred calls fill its room); the fixed one always closes it again. The car is
// driven by a closed model: at each one-second step, one of the things that can happen (nothing,
// a call for either floor, the load going over or back within limits), then the step. The
// explorer follows the calls the car keeps deferred and the dwell and travel times it keeps
// pending, which is where the flaw lives. Exits 0 when the explorer finds the flaw in the first
// two and proves the third.

#include <bsc/verify.hpp>

#include <array>
#include <chrono>
#include <cstdio>
#include <string>

#include "door.hpp"

namespace {

using namespace std::chrono_literals;

inline constexpr std::array<char const*, 5> happenings = {"nothing", "call 0", "call 1", "overload", "load ok"};

template <class Machine>
struct car {
    Machine door;
};

template <class Machine, auto const& Chart>
auto model() {
    auto step = [](car<Machine>& c, std::size_t choice, bsc::duration now) {
        switch (choice) {
            case 1: c.door.dispatch(elevator::call{0}, bsc::allow_unhandled); break;
            case 2: c.door.dispatch(elevator::call{1}, bsc::allow_unhandled); break;
            case 3: c.door.dispatch(elevator::overload{}, bsc::allow_unhandled); break;
            case 4: c.door.dispatch(elevator::load_ok{}, bsc::allow_unhandled); break;
            default: break;
        }
        c.door.step(now);
    };
    auto describe = [](car<Machine> const& c) {
        return c.door.active_states().joined() + " floor=" + std::to_string(c.door.context().floor);
    };
    auto label = [](std::size_t choice) { return std::string{happenings[choice]}; };
    return bsc::verify::system_model{car<Machine>{Machine{Chart}}, bsc::duration{1s}, happenings.size(), step, describe, label};
}

// From every state the car can reach, the door can close again.
template <class Machine, auto const& Chart>
bsc::verify::verdict door_closes() {
    bsc::verify::explorer ex{model<Machine, Chart>()};
    auto v = bsc::verify::always_reachable(ex, "door closed", [](car<Machine> const& c) {
        return !c.door.template is<elevator::DoorOpen>();
    });
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
