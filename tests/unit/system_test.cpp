// Systems of actors: signals, step order, and exploration of a closed loop.

#include <doctest/doctest.h>

#include <chrono>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

using namespace std::chrono_literals;

namespace sys {
struct Root;
struct Idle;
struct Running;
struct Still;
struct Moving;
struct At;

// The controller: start the motor when asked, stop it when the sensor says the part arrived.
struct controller_io {
    bsc::input<bool> request;
    bsc::input<bool> arrived;
    bsc::output<bool> motor;
};
inline constexpr auto controller = bsc::make_chart<controller_io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Running>),
    bsc::state<Idle>[([](controller_io const& c) { return c.request.get() && !c.arrived.get(); })] /
            [](controller_io& c) { c.motor.set(true); } = bsc::state<Running>,
    bsc::state<Running>[([](controller_io const& c) { return c.arrived.get(); })] /
            [](controller_io& c) { c.motor.set(false); } = bsc::state<Idle>);

// The plant: a part moves while the motor runs and reaches the sensor after 300 ms.
struct plant_io {
    bsc::input<bool> motor;
    bsc::output<bool> arrived;
    bool reset = false;
};
inline constexpr auto plant = bsc::make_chart<plant_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>, bsc::state<At>),
    bsc::state<Still>[([](plant_io const& p) { return p.motor.get(); })] = bsc::state<Moving>,
    bsc::state<Moving>[([](plant_io const& p) { return !p.motor.get(); })] = bsc::state<Still>,
    bsc::state<Moving> + bsc::after(300ms) / [](plant_io& p) { p.arrived.set(true); } = bsc::state<At>,
    bsc::state<At>[([](plant_io const& p) { return p.reset; })] / [](plant_io& p) {
        p.arrived.set(false);
        p.reset = false;
    } = bsc::state<Still>);

struct actors {
    bsc::machine<decltype(controller)> control{controller};
    bsc::machine<decltype(plant)> belt{plant};
};
// The actor diagram: who sends what to whom.
using cell = bsc::system<actors, bsc::order<&actors::control, &actors::belt>,
                         bsc::link<&actors::control, &controller_io::motor, &actors::belt, &plant_io::motor>,
                         bsc::link<&actors::belt, &plant_io::arrived, &actors::control, &controller_io::arrived>>;
}  // namespace sys

TEST_CASE("a system steps its actors in order and delivers signals between them") {
    sys::cell s{};
    s.actors.control.context().request.set(true);
    s.step(0ms);  // control: Idle -> Running, motor published at the end of its step
    CHECK(s.actors.control.is<sys::Running>());
    CHECK(s.actors.belt.is<sys::Moving>());  // the belt, later in the order, sees it this step
    s.step(100ms);
    s.step(200ms);
    CHECK(s.actors.belt.is<sys::Moving>());
    s.step(300ms);  // 300 ms in Moving: arrived, published at the end of the belt's step
    CHECK(s.actors.belt.is<sys::At>());
    CHECK(s.actors.control.is<sys::Running>());  // the controller, earlier, sees it next step
    auto const r = s.step(400ms);
    CHECK(s.actors.control.is<sys::Idle>());
    CHECK(r.transitions == 1);
    CHECK_FALSE(s.actors.control.context().motor.get());
}

TEST_CASE("a closed-loop system is explored like a single machine") {
    auto step = [](sys::cell& s, std::size_t choice, bsc::duration now) {
        s.actors.control.context().request.set(choice & 1);
        s.actors.belt.context().reset = (choice & 2) != 0;
        s.step(now);
    };
    auto describe = [](sys::cell const& s) {
        return s.actors.control.active_states().joined() + " | " + s.actors.belt.active_states().joined();
    };
    auto label = [](std::uint16_t c) { return "request=" + std::to_string(c & 1) + " reset=" + std::to_string(c >> 1); };
    bsc::verify::system_model model{sys::cell{}, 100ms, 4, step, describe, label};
    bsc::verify::explorer ex{model};
    auto const& st = ex.run();
    CHECK(st.complete);
    CHECK(st.states > 5);
    CHECK(bsc::verify::deadlock_free(ex).holds());
    CHECK(bsc::verify::reinitiable(ex).holds());
    // Safety: the motor is never on while the part is at the sensor for more than a step.
    auto const safe = bsc::verify::always(ex, "motor off once arrived and seen", [](sys::cell const& s) {
        return !(s.actors.control.context().arrived.get() && s.actors.control.context().motor.get() &&
                 s.actors.control.is<sys::Idle>());
    });
    CHECK(safe.holds());
    auto const witness = bsc::verify::reachable(ex, "At", [](sys::cell const& s) { return s.actors.belt.is<sys::At>(); });
    REQUIRE(witness.holds());
    CHECK(witness.trace.back().configuration == "Root Running | Root At");
}

namespace sys {
struct Broken;
struct fragile_io {
    bsc::input<bool> motor;
};
// A plant that breaks if the motor runs: a final Damage state halts it.
inline constexpr auto fragile = bsc::make_chart<fragile_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::final_state<Broken>),
    bsc::state<Still>[([](fragile_io const& p) { return p.motor.get(); })] = bsc::state<Broken>);
struct fragile_actors {
    bsc::machine<decltype(controller)> control{controller};
    bsc::machine<decltype(fragile)> part{fragile};
};
using fragile_cell =
    bsc::system<fragile_actors, bsc::order<&fragile_actors::control, &fragile_actors::part>,
                bsc::link<&fragile_actors::control, &controller_io::motor, &fragile_actors::part, &fragile_io::motor>>;
}  // namespace sys

TEST_CASE("the system report flags an actor that has halted") {
    sys::fragile_cell s{};
    CHECK_FALSE(s.step(0ms).halted);
    s.actors.control.context().request.set(true);
    auto const r = s.step(100ms);
    CHECK(r.halted);
    CHECK(s.actors.part.halted());
}
