// The whole state of a machine that defers and delays events: the elevator door
// (examples/elevator/door.hpp) saved and restored with calls deferred and the travel and dwell
// times pending, on both back ends, continues exactly as the original; the explorer follows those
// pending events, finds the flaw of the door that drops its dwell timer's event, refutes the door
// that defers it, and proves the fixed one; and an exploration that a bound stops says which
// member multiplied the states.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>
#include <bsc/verify.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "backends.hpp"
#include "inside.hpp"
#include "../../examples/elevator/door.hpp"
#include "../../examples/elevator/model.hpp"

namespace elevator_test {

using namespace std::chrono_literals;

// One scripted step: a happening, then a cycle a second later.
template <class M>
std::string drive(M& m, int k) {
    switch ((k * 7 + k / 5) % 6) {
        case 1: m.dispatch(elevator::call{0}, bsc::allow_unhandled); break;
        case 2: m.dispatch(elevator::call{1}, bsc::allow_unhandled); break;
        case 3: m.dispatch(elevator::overload{}, bsc::allow_unhandled); break;
        case 4: m.dispatch(elevator::load_ok{}, bsc::allow_unhandled); break;
        default: break;
    }
    m.step(bsc::duration{std::chrono::milliseconds{700 * k}});
    return m.active_states().joined() + " floor=" + std::to_string(m.context().floor) +
           " target=" + std::to_string(m.context().target) +
           " outcome=" + std::to_string(static_cast<int>(m.last_outcome()));
}

template <class M>
std::size_t deferred(M const& m) {
    return inside::deferred_count(m);
}
template <class M>
std::size_t delayed(M const& m) {
    return inside::delayed_count(m);
}

}  // namespace elevator_test

namespace {
// A machine whose chart defers and sends delayed events, in a global: constant-initialised.
constinit elevator::deferring_machine global_car{elevator::deferring};
}  // namespace

TEST_CASE("elevator: a machine that defers and delays, in a global, is constant-initialised (constinit)") {
    CHECK(global_car.active_states().joined() ==
          elevator::deferring_machine{elevator::deferring}.active_states().joined());
}

TEST_CASE_TEMPLATE("retain: a machine saved with deferred and delayed events pending continues exactly as the original",
                   Backend, bsc_test::compiled, bsc_test::table) {
    using namespace elevator_test;
    using machine = bsc_test::machine_t<Backend, decltype(elevator::fixed), elevator::policy>;
    std::size_t cuts_with_deferred = 0;
    std::size_t cuts_with_delayed = 0;
    for (int save_at = 0; save_at < 60; ++save_at) {
        machine original{elevator::fixed};
        for (int k = 0; k < save_at; ++k) drive(original, k);
        if (deferred(original) > 0) ++cuts_with_deferred;
        if (delayed(original) > 0) ++cuts_with_delayed;
        auto const bytes = bsc::save(original);
        REQUIRE(bytes.size() == bsc::saved_size<machine>);

        elevator::data counted{};
        counted.served.value = 1000;  // the copy's own count, given where it is built
        machine copy{elevator::fixed, counted};
        auto const result = bsc::restore(copy, bytes);
        REQUIRE_MESSAGE(result, bsc::to_string(result));
        CHECK(bsc::save(copy) == bytes);
        CHECK(deferred(copy) == deferred(original));
        CHECK(delayed(copy) == delayed(original));
        CHECK(copy.context().served.value == 1000);  // transient: the copy keeps its own
        for (int k = save_at; k < 90; ++k) {
            CAPTURE(save_at);
            CAPTURE(k);
            REQUIRE(drive(copy, k) == drive(original, k));
        }
    }
    // The cuts fall where events wait, or the test would show nothing.
    CHECK(cuts_with_deferred >= 5);
    CHECK(cuts_with_delayed >= 10);
}

TEST_CASE("retain: the two back ends save the same bytes with events pending, and a deferred call survives") {
    using namespace elevator_test;
    bsc::machine<decltype(elevator::fixed), elevator::policy> compiled{elevator::fixed};
    bsc::table::machine<decltype(elevator::fixed), elevator::policy> table{elevator::fixed};
    for (int k = 0; k < 40; ++k) {
        drive(compiled, k);
        drive(table, k);
        REQUIRE(bsc::save(compiled) == bsc::save(table));
    }
    // A call deferred while the car moves is taken after a restart, once the car is idle again.
    bsc::machine<decltype(elevator::fixed), elevator::policy> car{elevator::fixed};
    car.dispatch(elevator::call{1});
    car.step(0s);
    REQUIRE(car.is<elevator::Moving>());
    car.dispatch(elevator::call{0});  // deferred
    REQUIRE(deferred(car) == 1);
    auto const bytes = bsc::save(car);
    bsc::machine<decltype(elevator::fixed), elevator::policy> restarted{elevator::fixed};
    REQUIRE(bsc::restore(restarted, bytes));
    CHECK(deferred(restarted) == 1);
    CHECK(delayed(restarted) == 1);  // the travel time
    restarted.step(2s);              // arrived at floor 1: the door opens
    CHECK(restarted.is<elevator::DoorOpen>());
    CHECK(restarted.context().floor == 1);
    restarted.step(5s);  // the dwell time is over: the door closes, the deferred call is taken
    CHECK(restarted.is<elevator::Moving>());
    CHECK(restarted.context().target == 0);
}

TEST_CASE("retain: bytes of format version 1, which held no pending events, are refused") {
    using namespace elevator_test;
    bsc::machine<decltype(elevator::fixed), elevator::policy> m{elevator::fixed};
    auto bytes = bsc::save(m);
    bytes[4] = std::byte{1};
    auto const result = bsc::restore(m, bytes);
    CHECK(result.error == bsc::restore_error::unsupported_version);
    CHECK(result.offset == 4);
}

TEST_CASE("verify: the explorer follows deferred and delayed events, finds the door left open and proves the fix") {
    using namespace elevator_test;
    {
        bsc::verify::explorer ex{elevator::closed_car<elevator::flawed_machine, elevator::flawed>()};
        auto const v = bsc::verify::always_reachable(ex, "door closed",
                                                     elevator::door_closed<elevator::flawed_machine>);
        REQUIRE(v.fails());
        // A shortest counterexample: the door opens, the car is overloaded when the dwell time ends.
        REQUIRE(v.trace.size() == 4);
        CHECK(v.trace[1].label == "call 0");
        CHECK(v.trace.back().label == "overload");
        CHECK(v.trace.back().configuration == "Car DoorOpen Overloaded");
        CHECK(ex.stats().complete);
    }
    {
        bsc::verify::explorer ex{elevator::closed_car<elevator::deferring_machine, elevator::deferring>()};
        auto const v = bsc::verify::always_reachable(ex, "door closed",
                                                     elevator::door_closed<elevator::deferring_machine>);
        REQUIRE(v.fails());
        // Two calls deferred while the door is open fill the room the dwell event would need.
        std::size_t calls = 0;
        for (auto const& s : v.trace)
            if (s.label.rfind("call", 0) == 0) ++calls;
        CHECK(calls >= 1 + elevator::policy::deferred_capacity);
    }
    {
        bsc::verify::explorer ex{elevator::closed_car<elevator::fixed_machine, elevator::fixed>()};
        auto const v = bsc::verify::always_reachable(ex, "door closed", elevator::door_closed<elevator::fixed_machine>);
        CHECK_MESSAGE(v.holds(), v.to_string());
        CHECK(ex.stats().complete);
        // Calls wait: some explored state holds a deferred call and a pending delayed event.
        bool waiting = false;
        for (std::size_t i = 0; i < ex.count() && !waiting; ++i) {
            auto s = ex.at(i);
            waiting = deferred(s.door) > 0 && delayed(s.door) > 0;
        }
        CHECK(waiting);
    }
}

namespace elevator_test {
// The door with its statistics kept as a plain member: every call served is a new state.
struct counted {
    int floor = 0;
    int served = 0;
};
struct Car;
struct Idle;
struct Open;
inline constexpr auto counting = bsc::make_chart<counted>(
    bsc::composite<Car>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Open>),
    bsc::state<Idle> +
        bsc::event<elevator::call> / [](counted& c, elevator::call const& e) { c.floor = e.floor; } = bsc::state<Open>,
    bsc::state<Open> + bsc::on_entry / [](counted& c) { ++c.served; },
    bsc::state<Open> + bsc::event<elevator::dwell_over> = bsc::state<Idle>);
}  // namespace elevator_test

TEST_CASE("verify: an exploration stopped by its bound names the members that took the most values") {
    using namespace elevator_test;
    using machine = bsc::machine<decltype(counting)>;
    bsc::verify::explorer ex{bsc::verify::event_model<machine, elevator::call, elevator::dwell_over>{machine{counting}},
                             bsc::verify::limits{.max_states = 500}};
    auto const v = bsc::verify::always(ex, "anything", [](machine const&) { return true; });
    CHECK(v.result == bsc::verify::verdict::status::inconclusive);
    REQUIRE_FALSE(ex.stats().widest.empty());
    CHECK(ex.stats().widest.front().name == "served");
    CHECK(ex.stats().widest.front().values >= 250);
    CHECK(v.detail.find("served: ") != std::string::npos);
    // The configuration took two values, the floor one: they come after.
    bool configuration_listed = false;
    for (auto const& w : ex.stats().widest)
        if (w.name == "configuration") configuration_listed = w.values == 2;
    CHECK(configuration_listed);
}
