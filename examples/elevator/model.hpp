#pragma once
// The car closed for the explorer: at each one-second step, one of the things that can happen
// (nothing, a call for either floor, the load going over or back within limits), then the
// step. The explorer follows the calls the car keeps deferred and the dwell and travel times it
// keeps pending.

#include <bsc/verify.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>

#include "door.hpp"

namespace elevator {

inline constexpr std::array<char const*, 5> happenings = {"nothing", "call 0", "call 1", "overload", "load ok"};

template <class Machine>
struct car {
    Machine door;
};

// The closed model of a car whose door is a Machine of Chart (door.hpp: flawed, deferring, fixed).
template <class Machine, auto const& Chart>
auto closed_car() {
    auto step = [](car<Machine>& c, std::size_t choice, bsc::duration now) {
        switch (choice) {
            case 1: c.door.dispatch(call{0}, bsc::allow_unhandled); break;
            case 2: c.door.dispatch(call{1}, bsc::allow_unhandled); break;
            case 3: c.door.dispatch(overload{}, bsc::allow_unhandled); break;
            case 4: c.door.dispatch(load_ok{}, bsc::allow_unhandled); break;
            default: break;
        }
        c.door.step(now);
    };
    auto describe = [](car<Machine> const& c) { return c.door.active_states().joined(); };
    auto label = [](std::size_t choice) { return std::string{happenings[choice]}; };
    return bsc::verify::system_model{
        car<Machine>{Machine{Chart}}, bsc::duration{std::chrono::seconds{1}}, happenings.size(), step, describe, label};
}

// What the door must always be able to do again, from any state the car can reach.
template <class Machine>
bool door_closed(car<Machine> const& c) {
    return !c.door.template is<DoorOpen>();
}

}  // namespace elevator
