// bsc::system_inspector (<bsc/system_inspector.hpp>) asked over a real loopback socket, in one
// thread: the system's description (actors, charts, links), one trace stream per traced actor,
// and the commands that name an actor, with an input that a link drives refused.

#include <doctest/doctest.h>

// First: a header that defines bsc::order before the machine's templates are read, which once
// made `s.order < t.order` in one of them parse as a template argument list.
#include <bsc/system.hpp>

#include <bsc/bsc.hpp>
#include <bsc/system_inspector.hpp>
#include <bsc/trace.hpp>
#include <bsc/trace_reader.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

#include "conveyor.hpp"
#include "inspector_client.hpp"

namespace system_inspector_test {

using namespace std::chrono_literals;
using conveyor::controller;
using conveyor::controller_io;
struct Root;
struct Still;
struct Moving;
struct Dark;
struct Lit;

// The belt: moves while the motor runs; the environment may hold it (a brake).
struct belt_io {
    bsc::input<bool> motor;
    bsc::input<bool> brake;
};
inline constexpr auto belt = bsc::make_chart<belt_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>),
    bsc::state<Still>[([](belt_io const& b) { return b.motor.get() && !b.brake.get(); })] = bsc::state<Moving>,
    bsc::state<Moving>[([](belt_io const& b) { return !b.motor.get(); })] = bsc::state<Still>);
// A lamp that shows the motor: an actor without a tracer.
struct lamp_io {
    bsc::input<bool> on;
};
inline constexpr auto lamp = bsc::make_chart<lamp_io>(
    bsc::composite<Root>(bsc::initial<Dark>, bsc::state<Lit>),
    bsc::state<Dark>[([](lamp_io const& l) { return l.on.get(); })] = bsc::state<Lit>,
    bsc::state<Lit>[([](lamp_io const& l) { return !l.on.get(); })] = bsc::state<Dark>);

using control_tracer = bsc::tracer<decltype(controller) const>;
using belt_tracer = bsc::tracer<decltype(belt) const>;

// The rings the traced actors write into: they must outlive the actors.
inline std::array<std::byte, 1 << 14> control_storage{};
inline std::array<std::byte, 1 << 14> belt_storage{};
inline bsc::trace_buffer control_ring{control_storage};
inline bsc::trace_buffer belt_ring{belt_storage};

struct actors {
    bsc::machine<decltype(controller), bsc::scan_policy, control_tracer> control{
        controller, controller_io{}, control_tracer{controller, control_ring}};
    bsc::machine<decltype(belt), bsc::scan_policy, belt_tracer> conveyor{belt, belt_io{}, belt_tracer{belt, belt_ring}};
    bsc::machine<decltype(lamp), bsc::scan_policy> light{lamp};
};
using line = bsc::system<actors, bsc::order<&actors::control, &actors::conveyor, &actors::light>,
                         bsc::link<&actors::control, &controller_io::motor, &actors::conveyor, &belt_io::motor>,
                         bsc::link<&actors::control, &controller_io::motor, &actors::light, &lamp_io::on>,
                         bsc::from_outside<&actors::control, &controller_io::request>,
                         bsc::from_outside<&actors::control, &controller_io::arrived>,
                         bsc::from_outside<&actors::conveyor, &belt_io::brake>>;

// The lines of an actor's trace as the page gets them.
template <class View>
std::string lines(View& view, std::size_t actor) {
    auto const a = inspector_client::ask(view, "GET", "/trace?actor=" + std::to_string(actor) + "&from=0");
    REQUIRE(a.status == 200);
    bsc::trace_reader reader;
    reader.feed(std::as_bytes(std::span{a.body}));
    std::string out;
    while (auto r = reader.next()) out += reader.describe(*r) + "\n";
    CHECK(reader.missing() == 0);
    CHECK(reader.skipped_bytes() == 0);
    return out;
}

// A belt whose context is not an aggregate (a constructor): described by bsc::fields, so that
// its members' names are the description's, not known from the class itself.
class held_belt_io {
public:
    held_belt_io() = default;
    bsc::input<bool> motor;
    bsc::input<bool> brake;
};
}  // namespace system_inspector_test

template <>
struct bsc::fields<system_inspector_test::held_belt_io> {
    static constexpr std::array<std::string_view, 2> names{"motor", "brake"};
    template <class Self, class F>
    static constexpr decltype(auto) apply(Self& self, F&& f) {
        return f(self.motor, self.brake);
    }
};

namespace system_inspector_test {
inline constexpr auto held_belt = bsc::make_chart<held_belt_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>),
    bsc::state<Still>[([](held_belt_io const& b) { return b.motor.get(); })] = bsc::state<Moving>,
    bsc::state<Moving>[([](held_belt_io const& b) { return !b.motor.get(); })] = bsc::state<Still>);
using held_tracer = bsc::tracer<decltype(held_belt) const>;

inline std::array<std::byte, 1 << 12> held_storage{};
inline bsc::trace_buffer held_ring{held_storage};

struct held_actors {
    bsc::machine<decltype(controller), bsc::scan_policy> control{controller};
    bsc::machine<decltype(held_belt), bsc::scan_policy, held_tracer> conveyor{held_belt, held_belt_io{},
                                                                              held_tracer{held_belt, held_ring}};
};
using held_line =
    bsc::system<held_actors, bsc::order<&held_actors::control, &held_actors::conveyor>,
                bsc::link<&held_actors::control, &controller_io::motor, &held_actors::conveyor, &held_belt_io::motor>,
                bsc::from_outside<&held_actors::control, &controller_io::request>,
                bsc::from_outside<&held_actors::control, &controller_io::arrived>,
                bsc::from_outside<&held_actors::conveyor, &held_belt_io::brake>>;

// Two actors whose tracers share one ring: refused.
inline std::array<std::byte, 1 << 12> shared_storage{};
inline bsc::trace_buffer shared_ring{shared_storage};
struct sharing_actors {
    bsc::machine<decltype(controller), bsc::scan_policy, control_tracer> control{
        controller, controller_io{}, control_tracer{controller, shared_ring}};
    bsc::machine<decltype(belt), bsc::scan_policy, belt_tracer> conveyor{belt, belt_io{},
                                                                         belt_tracer{belt, shared_ring}};
};
using sharing_line =
    bsc::system<sharing_actors, bsc::order<&sharing_actors::control, &sharing_actors::conveyor>,
                bsc::link<&sharing_actors::control, &controller_io::motor, &sharing_actors::conveyor, &belt_io::motor>,
                bsc::from_outside<&sharing_actors::control, &controller_io::request>,
                bsc::from_outside<&sharing_actors::control, &controller_io::arrived>,
                bsc::from_outside<&sharing_actors::conveyor, &belt_io::brake>>;
}  // namespace system_inspector_test

TEST_CASE("a system inspector describes the system and serves one trace per traced actor") {
    using namespace system_inspector_test;
    using inspector_client::ask;
    line cell{};
    bsc::inspector_options options;
    options.commands = true;
    options.stepping = true;
    std::string log;
    options.on_command = [&](std::string_view c, std::string_view a) {
        log += std::string{c} + " -> " + std::string{a} + "\n";
    };
    bsc::system_inspector view{cell, std::move(options)};

    auto const info = ask(view, "GET", "/info");
    CHECK(info.status == 200);
    CHECK(
        info.body.starts_with("{\"system\": true, \"actors\": [{\"name\": \"control\", \"chart\": \"Root\", "
                              "\"traced\": true}, {\"name\": \"conveyor\", \"chart\": \"Root\", \"traced\": true}, "
                              "{\"name\": \"light\", \"chart\": \"Root\", \"traced\": false}], \"links\": ["));
    CHECK(info.body.find("{\"from\": 0, \"from_channel\": \"motor\", \"to\": 1, \"to_channel\": \"motor\", "
                         "\"lossless\": false}") != std::string::npos);
    CHECK(info.body.find("{\"from\": 0, \"from_channel\": \"motor\", \"to\": 2, \"to_channel\": \"on\", "
                         "\"lossless\": false}") != std::string::npos);
    CHECK(info.body.ends_with("\"commands\": true, \"paused\": false, \"scan\": true}"));
    // The description a recording keeps: /info without the run's fields.
    auto const description = bsc::system_inspector<line>::description();
    static_assert(bsc::system_inspector<line>::actor_names().size() == 3);
    CHECK(bsc::system_inspector<line>::actor_names()[2] == "light");
    CHECK(description.ends_with("]}"));
    CHECK(info.body ==
          description.substr(0, description.size() - 1) + ", \"commands\": true, \"paused\": false, \"scan\": true}");

    // Each traced actor's stream begins with its own dictionary; the lamp has none.
    CHECK(lines(view, 0).find("state 2 Idle") != std::string::npos);
    CHECK(lines(view, 1).find("state 2 Still") != std::string::npos);
    CHECK(ask(view, "GET", "/trace?actor=2&from=0").status == 404);
    CHECK(ask(view, "GET", "/trace?actor=3&from=0").status == 404);
    CHECK(ask(view, "GET", "/trace?from=0").status == 404);
    // Past the end (a page that read an earlier run): an empty answer at the end, no bytes beyond.
    auto const beyond = ask(view, "GET", "/trace?actor=1&from=99999999");
    CHECK(beyond.status == 200);
    CHECK(beyond.body.empty());
    CHECK(inspector_client::header(beyond, "X-Trace-Start") == std::to_string(view.trace_end(1)));
    CHECK(inspector_client::header(beyond, "X-Trace-End") == std::to_string(view.trace_end(1)));

    // A from_outside input is set and latched at the next step; the link carries the motor on.
    auto const set = ask(view, "POST", "/command", "set control request true");
    CHECK(set.status == 200);
    CHECK(set.body == "ok control.request = true (latched at the next step)");
    REQUIRE(view.may_step());
    cell.step(0ms);
    view.sample();
    CHECK(cell.actors.control.is<conveyor::Running>());
    CHECK(cell.actors.conveyor.is<Moving>());
    CHECK(cell.actors.light.is<Lit>());
    CHECK(lines(view, 0).find("transition Idle -> Running on condition (row 0)\n[0s] entry Running") !=
          std::string::npos);
    CHECK(lines(view, 0).find("values request=true arrived=false motor=true") != std::string::npos);
    CHECK(lines(view, 1).find("entry Moving") != std::string::npos);

    // An input a link drives would be overwritten at the next step: refused, with the link named.
    auto const driven = ask(view, "POST", "/command", "set conveyor motor false");
    CHECK(driven.status == 400);
    CHECK(driven.body ==
          "conveyor.motor is driven by the link from control.motor: only inputs no link drives can be set");
    CHECK(ask(view, "POST", "/command", "set light on false").body.find("driven by the link from control.motor") !=
          std::string::npos);
    CHECK(ask(view, "POST", "/command", "set nobody on true").body == "no actor of this system is named 'nobody'");
    CHECK(ask(view, "POST", "/command", "set conveyor brake maybe").body ==
          "conveyor: 'maybe' is not a value of brake");
    CHECK(ask(view, "POST", "/command", "dispatch control press").body ==
          "no event of control's chart is named 'press'");
    auto const unknown = ask(view, "POST", "/command", "dispatch control");
    CHECK(unknown.status == 400);
    CHECK(unknown.body.starts_with("commands: dispatch <actor> <event>"));

    // Paused from the page, the program steps the whole system once per step command.
    CHECK(ask(view, "POST", "/command", "pause").status == 200);
    CHECK_FALSE(view.may_step());
    CHECK(ask(view, "POST", "/command", "set control arrived true").status == 200);
    CHECK(ask(view, "POST", "/command", "step").status == 200);
    REQUIRE(view.may_step());
    cell.step(100ms);
    view.sample();
    CHECK_FALSE(view.may_step());
    CHECK(cell.actors.control.is<conveyor::Idle>());
    CHECK(cell.actors.conveyor.is<Still>());  // the motor's stop reaches it in the same step
    CHECK(ask(view, "POST", "/command", "resume").status == 200);
    CHECK(view.may_step());
    CHECK(ask(view, "GET", "/info").body.find("\"paused\": false") != std::string::npos);
    CHECK(view.commands_run() == 10);  // not the one whose verb is incomplete
    CHECK(log.find("set conveyor motor false -> conveyor.motor is driven by the link") != std::string::npos);
    CHECK(view.trace_end(0) > 0);
    CHECK(view.trace_end(2) == 0);
}

TEST_CASE("a read-only system inspector refuses commands and other hosts") {
    using namespace system_inspector_test;
    using inspector_client::ask;
    line cell{};
    bsc::system_inspector view{cell, bsc::inspector_options{}};
    CHECK(ask(view, "POST", "/command", "set control request true").status == 403);
    CHECK(ask(view, "GET", "/info", {}, {.origin = {}, .host = "evil.example:80"}).status == 421);
    CHECK(ask(view, "GET", "/info").body.find("\"commands\": false") != std::string::npos);
    CHECK_FALSE(cell.actors.control.context().request.pending());
}

TEST_CASE("a system inspector refuses a linked input found by its address, whatever names the context has") {
    using namespace system_inspector_test;
    using inspector_client::ask;
    held_line cell{};
    bsc::inspector_options options;
    options.commands = true;
    bsc::system_inspector view{cell, std::move(options)};
    // The context is described by bsc::fields: its names are unknown to the link, but its address is not.
    CHECK(ask(view, "GET", "/info")
              .body.find("{\"from\": 0, \"from_channel\": \"motor\", \"to\": 1, \"to_channel\": "
                         "\"\", \"lossless\": false}") != std::string::npos);
    CHECK(ask(view, "POST", "/command", "set conveyor motor true").body ==
          "conveyor.motor is driven by the link from control.motor: only inputs no link drives can be set");
    CHECK_FALSE(cell.actors.conveyor.context().motor.pending());
    CHECK(ask(view, "POST", "/command", "set conveyor brake true").body == "ok conveyor.brake = true");
    CHECK(cell.actors.conveyor.context().brake.pending());
    // An actor without a tracer has no stream.
    CHECK(ask(view, "GET", "/trace?actor=0&from=0").status == 404);
    CHECK(ask(view, "GET", "/trace?actor=1&from=0").status == 200);
}

TEST_CASE("two actors that trace into one ring are refused") {
    using namespace system_inspector_test;
    sharing_line cell{};
    CHECK_THROWS_WITH_AS(bsc::system_inspector(cell, bsc::inspector_options{}),
                         "bsc::system_inspector: control and conveyor trace into the same ring", std::invalid_argument);
}
