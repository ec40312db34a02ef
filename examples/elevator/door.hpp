#pragma once
// The door of an elevator car, as a chart that defers and delays events: calls that come while
// the car moves or its door is open wait (deferred) until it is idle again, and the door closes
// a dwell time after it opened (a delayed event to self). The load sensor holds the door open
// while the car is overloaded.
//
// Two versions of one chart. In `flawed`, nothing takes the dwell timer's event while the car is
// overloaded: it comes, and it is gone. Once the load clears, the door waits for an event that
// will never come again, and stays open for good. In `fixed`, the door that the load lets go
// starts its dwell time over (cancelling whatever is still pending under the timer's id). The
// explorer tells the two apart (main.cpp, tests/unit/elevator_test.cpp): only an exploration of
// the pending events themselves (the calls deferred, the travel and dwell times delayed) can.
//
// Deferring the dwell timer's event in Overloaded looks like a fix, and the explorer refutes it:
// with the deferred calls filling the car's deferred events (policy::deferred_capacity), the
// deferred dwell event has no room, is dropped, and the door stays open again.

#include <bsc/bsc.hpp>

#include <chrono>
#include <cstddef>

namespace elevator {

using namespace std::chrono_literals;

// ---- events ------------------------------------------------------------------------------------
struct call {  // a button pressed, inside the car or on a landing
    int floor = 0;
};
struct arrived {};     // the drive stopped at the target floor (raised by the car itself)
struct dwell_over {};  // the door has been open long enough (raised by the car itself)
struct overload {};    // the load sensor: more than the car may carry
struct load_ok {};     // the load sensor: back within limits

// ---- states ------------------------------------------------------------------------------------
struct Car;
struct Idle;
struct Moving;
struct DoorOpen;
struct Dwelling;
struct Overloaded;

struct data {
    int floor = 0;   // where the car is
    int target = 0;  // where it goes
    // Calls served (the door opened for them): statistics, which would make every state of the
    // car a new one for the explorer; not part of the state (docs/verification.md).
    bsc::transient_member<int> served{};
};

inline constexpr auto travel_time = 2s;
inline constexpr auto dwell_time = 3s;
inline constexpr int dwell_timer = 1;  // the id of the door's delayed event

// Few pending events are enough for a car with two floors; so the explorer's states stay few.
struct policy : bsc::default_policy {
    static constexpr std::size_t deferred_capacity = 2;
    static constexpr std::size_t delayed_capacity = 2;
};

inline constexpr auto here = bsc::guard([](data const& d, call const& c) { return c.floor == d.floor; });
inline constexpr auto go_to = bsc::action([](data& d, call const& c) { d.target = c.floor; });
inline constexpr auto stop = bsc::action([](data& d) { d.floor = d.target; });
inline constexpr auto serve = bsc::action([](data& d) { ++d.served.value; });

// The rows every version shares, with what Overloaded does when the load clears, and `extra`
// rows.
template <class LoadCleared, class... Extra>
constexpr auto door_chart(LoadCleared load_cleared, Extra... extra) {
    return bsc::make_chart<data>(
        bsc::composite<Car>(
            bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Moving>,
            bsc::composite<DoorOpen>(bsc::initial<Dwelling>, bsc::state<Dwelling>, bsc::state<Overloaded>)),
        bsc::state<Idle> + bsc::event<call>[here] = bsc::state<DoorOpen>,
        bsc::state<Idle> +
            bsc::event<call>[!here] / (go_to, bsc::raise_after(travel_time, arrived{})) = bsc::state<Moving>,
        bsc::state<Moving> + bsc::event<call> / bsc::defer,
        bsc::state<Moving> + bsc::event<arrived> / stop = bsc::state<DoorOpen>,
        bsc::state<DoorOpen> + bsc::on_entry / (serve, bsc::raise_after(dwell_time, dwell_over{}, dwell_timer)),
        bsc::state<DoorOpen> + bsc::event<call> / bsc::defer,
        bsc::state<Dwelling> + bsc::event<overload> = bsc::state<Overloaded>,
        bsc::state<Dwelling> + bsc::event<dwell_over> = bsc::state<Idle>, load_cleared, extra...);
}

// The door dwells again when the load clears.
inline constexpr auto dwell_again = bsc::state<Overloaded> + bsc::event<load_ok> = bsc::state<Dwelling>;

// Nothing takes the dwell timer's event while the car is overloaded: it is dropped.
inline constexpr auto flawed = door_chart(dwell_again);
// The load cleared: the dwell time starts over.
inline constexpr auto fixed = door_chart(
    bsc::state<Overloaded> +
        bsc::event<load_ok> / (bsc::cancel_delayed(dwell_timer),
                               bsc::raise_after(dwell_time, dwell_over{}, dwell_timer)) = bsc::state<Dwelling>);
// Deferring the dwell timer's event while overloaded: refuted (see above).
inline constexpr auto deferring = door_chart(dwell_again, bsc::state<Overloaded> + bsc::event<dwell_over> / bsc::defer);

using flawed_machine = bsc::machine<bsc::chart_ref<flawed>, policy>;
using fixed_machine = bsc::machine<bsc::chart_ref<fixed>, policy>;
using deferring_machine = bsc::machine<bsc::chart_ref<deferring>, policy>;

}  // namespace elevator
