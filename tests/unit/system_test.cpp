// Systems of actors: signals, step order, and exploration of a closed loop. The cases that
// step a system run with the actors on either back end; one puts the controller and the plant
// on different ones.

#include <doctest/doctest.h>

#include <chrono>
#include <type_traits>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "backends.hpp"
#include "conveyor.hpp"

using namespace std::chrono_literals;
using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;

namespace sys {
using conveyor::Idle;
using conveyor::Root;
using conveyor::Running;
using conveyor::controller;
using conveyor::controller_io;
struct Still;
struct Moving;
struct At;

// The plant: a part moves while the motor runs and reaches the sensor after 300 ms; the
// environment takes it away (reset).
struct plant_io {
    bsc::input<bool> motor;
    bsc::output<bool> arrived;
    bsc::input<bool> reset;
};
inline constexpr auto plant = bsc::make_chart<plant_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>, bsc::state<At>),
    bsc::state<Still>[([](plant_io const& p) { return p.motor.get(); })] = bsc::state<Moving>,
    bsc::state<Moving>[([](plant_io const& p) { return !p.motor.get(); })] = bsc::state<Still>,
    bsc::state<Moving> + bsc::after(300ms) / [](plant_io& p) { p.arrived.set(true); } = bsc::state<At>,
    bsc::state<At>[([](plant_io const& p) { return p.reset.get(); })] /
        [](plant_io& p) { p.arrived.set(false); } = bsc::state<Still>);

template <class ControlBackend, class BeltBackend>
struct actors {
    machine_t<ControlBackend, decltype(controller)> control{controller};
    machine_t<BeltBackend, decltype(plant)> belt{plant};
};
// The actor diagram: who sends what to whom, and the inputs the environment sets.
template <class ControlBackend, class BeltBackend = ControlBackend, class Actors = actors<ControlBackend, BeltBackend>>
using cell = bsc::system<Actors, bsc::order<&Actors::control, &Actors::belt>,
                         bsc::link<&Actors::control, &controller_io::motor, &Actors::belt, &plant_io::motor>,
                         bsc::link<&Actors::belt, &plant_io::arrived, &Actors::control, &controller_io::arrived>,
                         bsc::from_outside<&Actors::control, &controller_io::request>,
                         bsc::from_outside<&Actors::belt, &plant_io::reset>>;

template <class Backend>
using other_backend = std::conditional_t<std::is_same_v<Backend, compiled>, table, compiled>;
}  // namespace sys

TEST_CASE_TEMPLATE("a system steps its actors in order and delivers signals between them", Backend, compiled, table) {
    sys::cell<Backend> s{};
    s.actors.control.context().request.set(true);
    s.step(0ms);  // control: Idle -> Running, motor published at the end of its step
    CHECK(s.actors.control.template is<sys::Running>());
    CHECK(s.actors.belt.template is<sys::Moving>());  // the belt, later in the order, sees it this step
    s.step(100ms);
    s.step(200ms);
    CHECK(s.actors.belt.template is<sys::Moving>());
    s.step(300ms);  // 300 ms in Moving: arrived, published at the end of the belt's step
    CHECK(s.actors.belt.template is<sys::At>());
    CHECK(s.actors.control.template is<sys::Running>());  // the controller, earlier, sees it next step
    auto const r = s.step(400ms);
    CHECK(s.actors.control.template is<sys::Idle>());
    CHECK(r.transitions == 1);
    CHECK_FALSE(s.actors.control.context().motor.get());
}

// The instance's back end is the controller's; the plant runs on the other one.
TEST_CASE_TEMPLATE("a system may mix back ends: the controller on one, the plant on the other", ControlBackend,
                   compiled, table) {
    sys::cell<ControlBackend, sys::other_backend<ControlBackend>> s{};
    s.actors.control.context().request.set(true);
    s.step(0ms);
    CHECK(s.actors.belt.template is<sys::Moving>());  // the motor, published by the controller earlier in the order
    s.step(299ms);
    CHECK(s.actors.belt.template is<sys::Moving>());
    s.step(300ms);  // the plant's timeout
    CHECK(s.actors.belt.template is<sys::At>());
    s.actors.belt.context().reset.set(true);
    auto const r = s.step(400ms);  // the controller sees `arrived` and stops the motor; the plant sees that at once
    CHECK(s.actors.control.template is<sys::Idle>());
    CHECK_FALSE(s.actors.belt.context().motor.get());
    CHECK(s.actors.belt.template is<sys::Still>());
    CHECK(r.transitions == 2);
}

TEST_CASE_TEMPLATE("a closed-loop system is explored like a single machine", Backend, compiled, table) {
    using cell = sys::cell<Backend>;
    auto step = [](cell& s, std::size_t choice, bsc::duration now) {
        s.actors.control.context().request.set(choice & 1);
        s.actors.belt.context().reset.set((choice & 2) != 0);
        s.step(now);
    };
    auto describe = [](cell const& s) {
        return s.actors.control.active_states().joined() + " | " + s.actors.belt.active_states().joined();
    };
    auto label = [](std::uint16_t c) {
        return "request=" + std::to_string(c & 1) + " reset=" + std::to_string(c >> 1);
    };
    bsc::verify::system_model model{cell{}, 100ms, 4, step, describe, label};
    bsc::verify::explorer ex{model};
    auto const& st = ex.run();
    CHECK(st.complete);
    CHECK(st.states > 5);
    CHECK(bsc::verify::deadlock_free(ex).holds());
    CHECK(bsc::verify::reinitiable(ex).holds());
    // Safety: the motor is never on while the part is at the sensor for more than a step.
    auto const safe = bsc::verify::always(ex, "motor off once arrived and seen", [](cell const& s) {
        return !(s.actors.control.context().arrived.get() && s.actors.control.context().motor.get() &&
                 s.actors.control.template is<sys::Idle>());
    });
    CHECK(safe.holds());
    auto const witness = bsc::verify::reachable(ex, "At",
                                                [](cell const& s) { return s.actors.belt.template is<sys::At>(); });
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
template <class Backend>
struct fragile_actors {
    machine_t<Backend, decltype(controller)> control{controller};
    machine_t<Backend, decltype(fragile)> part{fragile};
};
template <class Backend, class Actors = fragile_actors<Backend>>
using fragile_cell = bsc::system<Actors, bsc::order<&Actors::control, &Actors::part>,
                                 bsc::link<&Actors::control, &controller_io::motor, &Actors::part, &fragile_io::motor>,
                                 bsc::from_outside<&Actors::control, &controller_io::request>,
                                 bsc::from_outside<&Actors::control, &controller_io::arrived>>;
}  // namespace sys

TEST_CASE_TEMPLATE("the system report flags an actor that has halted", Backend, compiled, table) {
    sys::fragile_cell<Backend> s{};
    CHECK_FALSE(s.step(0ms).halted);
    s.actors.control.context().request.set(true);
    auto const r = s.step(100ms);
    CHECK(r.halted);
    CHECK(s.actors.part.halted());
}

namespace sys {
struct Even;
struct Odd;
struct Dark;
struct Lit;

// A counter that counts the steps in which it is enabled, and a display of the count that
// reads it three ways: as it is, converted to tenths, and converted to whether it is odd.
struct counter_io {
    bsc::input<bool> enable;
    bsc::output<int> count;
};
inline constexpr auto counter_chart = bsc::make_chart<counter_io>(
    bsc::composite<Root>(bsc::initial<Even>, bsc::state<Odd>),
    bsc::state<Even>[([](counter_io const& c) { return c.enable.get(); })] /
        [](counter_io& c) { c.count.set(c.count.pending() + 1); } = bsc::state<Odd>,
    bsc::state<Odd>[([](counter_io const& c) { return c.enable.get(); })] /
        [](counter_io& c) { c.count.set(c.count.pending() + 1); } = bsc::state<Even>);

struct display_io {
    bsc::input<int> raw;
    bsc::input<double> tenths;
    bsc::input<bool> odd;
    bsc::output<bool> lamp;
};
inline constexpr auto display_chart = bsc::make_chart<display_io>(
    bsc::composite<Root>(bsc::initial<Dark>, bsc::state<Lit>),
    bsc::state<Dark>[([](display_io const& d) { return d.odd.get(); })] /
        [](display_io& d) { d.lamp.set(true); } = bsc::state<Lit>,
    bsc::state<Lit>[([](display_io const& d) { return !d.odd.get(); })] /
        [](display_io& d) { d.lamp.set(false); } = bsc::state<Dark>);

inline constexpr auto is_odd = [](int n) { return n % 2 != 0; };  // a captureless lambda
constexpr double to_tenths(int n) { return n / 10.0; }            // a function

template <class CounterBackend, class DisplayBackend>
struct counting_actors {
    machine_t<CounterBackend, decltype(counter_chart)> counter{counter_chart};
    machine_t<DisplayBackend, decltype(display_chart)> display{display_chart};
};
template <class CounterBackend, class DisplayBackend = other_backend<CounterBackend>,
          class Actors = counting_actors<CounterBackend, DisplayBackend>>
using counting = bsc::system<
    Actors, bsc::order<&Actors::counter, &Actors::display>, bsc::from_outside<&Actors::counter, &counter_io::enable>,
    bsc::link<&Actors::counter, &counter_io::count, &Actors::display, &display_io::raw>,
    bsc::link<&Actors::counter, &counter_io::count, &Actors::display, &display_io::tenths, bsc::convert<&to_tenths>>,
    bsc::link<&Actors::counter, &counter_io::count, &Actors::display, &display_io::odd, bsc::lossless,
              bsc::convert<is_odd>>>;

// The options of a link, in any order: its staleness policy and its conversion.
using odd_link = std::tuple_element_t<2, counting<compiled>::links_type>;
static_assert(std::is_same_v<odd_link::when_stale, bsc::lossless>);
static_assert(std::is_same_v<odd_link::conversion, bsc::convert<is_odd>>);
static_assert(std::is_same_v<std::tuple_element_t<0, counting<compiled>::links_type>::when_stale, bsc::hold_last>);
static_assert(std::tuple_size_v<counting<compiled>::links_type> == 3);
static_assert(std::tuple_size_v<counting<compiled>::from_outside_type> == 1);
static_assert(counting<compiled>::well_formed);
}  // namespace sys

// The counter runs on the instance's back end, the display on the other one.
TEST_CASE_TEMPLATE("bsc::convert: the consumer of a link reads the converted value", Backend, compiled, table) {
    sys::counting<Backend> s{};
    auto const& shown = s.actors.display.context();
    s.actors.counter.context().enable.set(true);
    s.step(0ms);  // count 1, published before the display steps, which reads it in the same step
    CHECK(s.actors.counter.context().count.get() == 1);
    CHECK(shown.raw.get() == 1);
    CHECK(shown.tenths.get() == doctest::Approx(0.1));
    CHECK(shown.odd.get());
    CHECK(shown.lamp.get());
    s.step(100ms);  // count 2
    CHECK(shown.raw.get() == 2);
    CHECK(shown.tenths.get() == doctest::Approx(0.2));
    CHECK_FALSE(shown.odd.get());
    CHECK_FALSE(shown.lamp.get());
    s.step(200ms);  // count 3
    CHECK(shown.tenths.get() == doctest::Approx(0.3));
    CHECK(shown.odd.get());
}

TEST_CASE_TEMPLATE("bsc::from_outside: an input the environment sets keeps its value across steps", Backend, compiled,
                   table) {
    sys::counting<Backend> s{};
    s.step(0ms);
    CHECK(s.actors.counter.context().count.get() == 0);  // not enabled: nothing counts
    s.actors.counter.context().enable.set(true);         // set once, between steps
    for (int k = 1; k <= 4; ++k) s.step(k * 100ms);
    CHECK(s.actors.counter.context().enable.get());  // no link wrote it
    CHECK(s.actors.counter.context().count.get() == 4);
    s.actors.counter.context().enable.set(false);
    s.step(500ms);
    s.step(600ms);
    CHECK(s.actors.counter.context().count.get() == 4);
    CHECK(s.actors.display.context().raw.get() == 4);
}
