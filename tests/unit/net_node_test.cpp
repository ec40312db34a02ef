// A system deployed across nodes (<bsc/net/node.hpp>) over the in-process transport: the same
// steps as in one process, staleness and its policies, refused and late messages, and an actor
// resumed from its saved state. The clock is the test's, so that deadlines pass when the test says.

#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <bsc/bsc.hpp>
#include <bsc/net/memory_transport.hpp>
#include <bsc/net/node.hpp>

#include "conveyor.hpp"

using namespace std::chrono_literals;

namespace net_test {
using conveyor::Idle;
using conveyor::Root;
using conveyor::Running;
using conveyor::controller;
using conveyor::controller_io;
struct Still;
struct Moving;
struct At;

// The plant: the part moves while the motor runs and arrives after 300 ms of it.
struct plant_io {
    bsc::input<bool> motor;
    bsc::output<bool> arrived;
};
inline constexpr auto plant = bsc::make_chart<plant_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>, bsc::state<At>),
    bsc::state<Still>[([](plant_io const& p) { return p.motor.get(); })] = bsc::state<Moving>,
    bsc::state<Moving>[([](plant_io const& p) { return !p.motor.get(); })] = bsc::state<Still>,
    bsc::state<Moving> + bsc::after(300ms) / [](plant_io& p) { p.arrived.set(true); } = bsc::state<At>,
    bsc::state<At>[([](plant_io const& p) { return !p.motor.get(); })] /
        [](plant_io& p) { p.arrived.set(false); } = bsc::state<Still>);

struct actors {
    bsc::machine<decltype(controller)> control{controller};
    bsc::machine<decltype(plant)> belt{plant};
};

template <class MotorPolicy, class ArrivedPolicy = bsc::hold_last>
using line =
    bsc::system<actors, bsc::order<&actors::control, &actors::belt>,
                bsc::link<&actors::control, &controller_io::motor, &actors::belt, &plant_io::motor, MotorPolicy>,
                bsc::link<&actors::belt, &plant_io::arrived, &actors::control, &controller_io::arrived, ArrivedPolicy>,
                bsc::from_outside<&actors::control, &controller_io::request>>;

// Two nodes, one actor each, on one bus, with the test's clock.
template <class System>
struct deployment {
    std::chrono::steady_clock::time_point now{};
    bsc::net::memory_bus bus;
    bsc::net::memory_transport control_link{bus};
    bsc::net::memory_transport belt_link{bus};
    System control_system{};
    System belt_system{};
    bsc::net::node<System> control_node;
    bsc::net::node<System> belt_node;

    explicit deployment(std::filesystem::path state = {})
        : control_node(control_system, control_link, options("control", state)),
          belt_node(belt_system, belt_link, options("belt", state)) {
        control_system.actors.control.context().request.set(true);
    }
    bsc::net::node_options options(std::string actor, std::filesystem::path state) {
        bsc::net::node_options o;
        o.name = actor;
        o.actors = {actor};
        o.deadline = 300ms;
        o.startup = 1s;
        o.state_dir = state;
        o.last_step = 0;
        o.clock = [this] { return now; };
        return o;
    }
    auto& control() { return control_system.actors.control; }
    auto& belt() { return belt_system.actors.belt; }
    // Both nodes run until neither can step.
    void settle() {
        for (int i = 0; i < 1000; ++i)
            if (control_node.run_once(0ms) + belt_node.run_once(0ms) == 0) return;
    }
    // Both nodes run through `step`.
    void advance(std::int64_t step) {
        control_node.stop_after(step);
        belt_node.stop_after(step);
        settle();
    }
};
}  // namespace net_test

using net_test::actors;

TEST_CASE("MQTT topic filters match as the protocol says") {
    using bsc::net::topic_matches;
    CHECK(topic_matches("a/b", "a/b"));
    CHECK_FALSE(topic_matches("a/b", "a/c"));
    CHECK(topic_matches("a/+/c", "a/x/c"));
    CHECK_FALSE(topic_matches("a/+", "a/x/c"));
    CHECK(topic_matches("a/#", "a/x/c"));
    CHECK(topic_matches("a/#", "a"));
    CHECK(topic_matches("#", "anything/at/all"));
    CHECK_FALSE(topic_matches("a/b/c", "a/b"));
}

TEST_CASE("a system deployed on two nodes takes the same steps as in one process") {
    using system = net_test::line<bsc::hold_last>;
    constexpr std::int64_t last = 30;
    bsc::net::memory_bus bus;
    bsc::net::memory_transport t1{bus}, t2{bus};
    system s1{}, s2{};
    bsc::net::node_options o1, o2;
    o1.actors = {"control"};
    o1.name = "one";
    o1.last_step = last;
    o2.actors = {"belt"};
    o2.name = "two";
    o2.last_step = last;
    bsc::net::node<system> n1{s1, t1, o1}, n2{s2, t2, o2};
    s1.actors.control.context().request.set(true);
    std::map<std::pair<std::size_t, std::int64_t>, std::vector<std::byte>> deployed;
    n1.on_step = [&](std::size_t, std::int64_t step) { deployed[{0, step}] = bsc::save(s1.actors.control); };
    n2.on_step = [&](std::size_t, std::int64_t step) { deployed[{1, step}] = bsc::save(s2.actors.belt); };
    // finished() also waits two heartbeats (100 ms of the real clock) after the last step.
    auto const give_up = std::chrono::steady_clock::now() + 10s;
    while (!(n1.finished() && n2.finished()) && std::chrono::steady_clock::now() < give_up) {
        n1.run_once(0ms);
        n2.run_once(0ms);
    }
    REQUIRE(n1.finished());
    REQUIRE(n2.finished());

    system reference{};
    reference.actors.control.context().request.set(true);
    int moves = 0;
    for (std::int64_t step = 0; step <= last; ++step) {
        reference.step(step * 100ms);
        moves += reference.actors.belt.is<net_test::Moving>() ? 1 : 0;
        CHECK(deployed[{0, step}] == bsc::save(reference.actors.control));
        CHECK(deployed[{1, step}] == bsc::save(reference.actors.belt));
    }
    CHECK(moves > 0);  // the run did something worth comparing
    CHECK(n1.stats().refused == 0);
    CHECK(n1.stats().stale_steps == 0);
    CHECK(n1.stats().jumps == 0);
}

TEST_CASE("an actor waits for its inputs and its readers, and goes on without a silent peer only after the deadline") {
    net_test::deployment<net_test::line<bsc::hold_last>> d;
    d.advance(5);
    CHECK(d.control_node.completed(0) == 5);
    CHECK(d.belt_node.completed(1) == 5);
    d.belt_link.fall_silent();  // no will: only the deadline tells
    d.control_node.stop_after(10);
    d.settle();
    CHECK(d.control_node.completed(0) == 6);  // step 6 reads the belt's step 5, which arrived; step 7 waits
    CHECK(d.control_node.waiting() == "control waits for belt to complete step 6 (has 5)");
    d.now += 299ms;
    CHECK(d.control_node.run_once(0ms) == 0);  // not yet stale
    CHECK_FALSE(d.control_node.is_stale(1));
    d.now += 2ms;
    CHECK(d.control_node.is_stale(1));
    CHECK(d.control_node.run_once(0ms) == 1);  // stale: the controller goes on, reading the last value
    CHECK(d.control_node.stepped_stale(0));
    CHECK(d.control_node.completed(0) == 7);
    // Without its peer it runs on its own clock, one step per period, not as fast as it can.
    CHECK(d.control_node.run_once(0ms) == 0);
    d.now += 99ms;
    CHECK(d.control_node.run_once(0ms) == 0);
    d.now += 1ms;
    CHECK(d.control_node.run_once(0ms) == 1);
    CHECK(d.control_node.completed(0) == 8);
    CHECK(d.control_node.stats().stale_steps == 2);
    CHECK(d.control_node.stats().jumps == 0);
}

TEST_CASE("a node's will makes its actors stale at once; fail_safe links read their safe value") {
    net_test::deployment<net_test::line<bsc::fail_safe<false>>> d;
    d.advance(2);
    REQUIRE(d.belt().is<net_test::Moving>());  // the motor runs
    REQUIRE(d.belt().context().motor.get());
    d.control_link.disconnect();  // the controller's node is lost: its will arrives
    d.belt_node.stop_after(4);
    d.now += 100ms;
    d.belt_node.run_once(0ms);
    CHECK(d.belt_node.is_stale(0));
    CHECK(d.belt_node.completed(1) == 3);  // no deadline to wait for
    d.now += 100ms;
    d.belt_node.run_once(0ms);
    CHECK(d.belt_node.completed(1) == 4);
    CHECK_FALSE(d.belt().context().motor.get());  // the safe value, not the last one
    CHECK(d.belt().is<net_test::Still>());        // and the plant stopped
}

TEST_CASE("a lossless link waits for its publisher however long it is silent") {
    net_test::deployment<net_test::line<bsc::lossless>> d;
    d.advance(2);
    d.control_link.disconnect();
    d.belt_node.stop_after(10);
    d.now += 1h;
    for (int i = 0; i < 10; ++i) d.belt_node.run_once(0ms);
    CHECK(d.belt_node.is_stale(0));
    CHECK(d.belt_node.completed(1) == 2);
    CHECK(d.belt_node.stats().stale_steps == 0);
}

TEST_CASE("messages from another chart, malformed or older than the applied ones are not applied") {
    net_test::deployment<net_test::line<bsc::hold_last>> d;
    d.settle();
    bsc::net::memory_transport intruder{d.bus};
    auto const topic = std::string("bsc/value/belt/arrived");
    // A well-formed message with another chart's fingerprint.
    intruder.publish(topic, bsc::net::wire::encode_value(1000, 12345, true));
    // Not a message of this format at all.
    std::vector<std::byte> garbage(5, std::byte{0x7f});
    intruder.publish(topic, garbage);
    // The right fingerprint, but a bool that is neither 0 nor 1.
    using system = net_test::line<bsc::hold_last>;
    using machine = std::remove_cvref_t<decltype(std::declval<actors&>().belt)>;
    auto bad = bsc::net::wire::encode_value(
        1000, bsc::net::wire::value_fingerprint<machine, &net_test::plant_io::arrived>(), true);
    bad.back() = std::byte{7};
    intruder.publish(topic, bad);
    d.control_node.run_once(0ms);
    CHECK(d.control_node.stats().refused == 3);
    CHECK(d.control_node.completed(1) < 1000);

    // A value for an old step, with the right fingerprint: counted, not applied.
    auto const old_before = d.control_node.stats().old;
    intruder.publish(topic, bsc::net::wire::encode_value(
                                0, bsc::net::wire::value_fingerprint<machine, &net_test::plant_io::arrived>(), true));
    d.control_node.run_once(0ms);
    CHECK(d.control_node.stats().old == old_before + 1);
    CHECK(d.control_node.stats().refused == 3);
    (void)sizeof(system);
}

TEST_CASE("a node started again resumes its actors from their saved state and rejoins the others") {
    auto const dir = std::filesystem::temp_directory_path() /
                     ("bsc_net_node_test_" +
                      std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    using system = net_test::line<bsc::fail_safe<false>>;
    net_test::deployment<system> d{dir};
    d.advance(2);
    REQUIRE(d.control().is<net_test::Running>());
    REQUIRE(std::filesystem::exists(dir / "control.bsc"));

    // The controller's node dies; the belt goes on without it.
    d.control_link.disconnect();
    d.belt_node.stop_after(8);
    for (int i = 0; i < 6; ++i) {
        d.now += 100ms;
        d.belt_node.run_once(0ms);
    }
    REQUIRE(d.belt_node.completed(1) == 8);

    // A new process: a fresh system and transport, the same state directory.
    bsc::net::memory_transport again{d.bus};
    system fresh{};
    auto options = d.options("control", dir);
    options.last_step = 20;
    bsc::net::node<system> restarted{fresh, again, options};
    CHECK(restarted.stats().restored == 1);
    CHECK(restarted.completed(0) == 2);
    CHECK(fresh.actors.control.is<net_test::Running>());  // where it was, not where a new machine starts
    d.belt_node.stop_after(20);
    d.now += 100ms;  // a heartbeat: the belt sends its last messages again
    for (int i = 0; i < 30; ++i) {
        restarted.run_once(0ms);
        d.belt_node.run_once(0ms);
    }
    CHECK(restarted.stats().jumps == 1);   // it rejoined the belt at step 9 instead of replaying 3 to 8
    CHECK(restarted.stats().steps == 12);  // 9 to 20
    CHECK(restarted.completed(0) == 20);
    CHECK(d.belt_node.completed(1) == 20);  // the belt waited for it again, and went on with it
    std::filesystem::remove_all(dir);
}

TEST_CASE("a node does not start from a damaged saved state") {
    auto const dir = std::filesystem::temp_directory_path() /
                     ("bsc_net_node_damaged_" +
                      std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    std::filesystem::create_directories(dir);
    using system = net_test::line<bsc::hold_last>;
    {
        net_test::deployment<system> d{dir};
        d.advance(3);
    }
    auto const file = dir / "control.bsc";
    REQUIRE(std::filesystem::exists(file));
    for (std::size_t at : {std::size_t{6}, std::size_t{40}}) {  // in the step, in the machine's bytes
        std::vector<char> bytes(std::filesystem::file_size(file));
        {
            std::ifstream in(file, std::ios::binary);
            in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        }
        auto damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out.write(damaged.data(), static_cast<std::streamsize>(damaged.size()));
        }
        bsc::net::memory_bus bus;
        bsc::net::memory_transport t{bus};
        system s{};
        bsc::net::node_options o;
        o.actors = {"control"};
        o.state_dir = dir;
        CAPTURE(at);
        CHECK_THROWS_AS(bsc::net::node<system>(s, t, o), std::runtime_error);
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    std::filesystem::remove_all(dir);
}

namespace net_test {
// A transport whose broker never answers: nothing goes out, nothing comes in.
class unreachable_transport final : public bsc::net::transport {
public:
    void set_will(std::string_view, std::span<std::byte const>) override {}
    void subscribe(std::string_view) override {}
    void publish(std::string_view, std::span<std::byte const>) override {}
    std::size_t poll(std::chrono::milliseconds, std::function<void(bsc::net::message const&)> const&) override {
        return 0;
    }
    bool connected() const override { return false; }
    std::string peer() const override { return "the MQTT broker at 192.0.2.1:1883"; }
};
}  // namespace net_test

TEST_CASE("a node that cannot connect says so, and names a peer never heard from without a number") {
    using system = net_test::line<bsc::hold_last>;
    net_test::unreachable_transport t;
    system s{};
    bsc::net::node_options o;
    o.name = "control";
    o.actors = {"control"};
    o.last_step = 3;
    bsc::net::node<system> n(s, t, o);
    CHECK(n.run_once(0ms) == 0);
    auto const why = n.waiting();
    INFO(why);
    CHECK(why ==
          "cannot reach the MQTT broker at 192.0.2.1:1883; control waits for belt to start (not heard from yet)");
    CHECK(why.find("-9223372036854775808") == std::string::npos);
    CHECK(n.completed(1) == std::numeric_limits<std::int64_t>::min());
}

TEST_CASE("a node refuses an actor the system does not have") {
    using system = net_test::line<bsc::hold_last>;
    bsc::net::memory_bus bus;
    bsc::net::memory_transport t{bus};
    system s{};
    bsc::net::node_options o;
    o.actors = {"conveyor"};
    CHECK_THROWS_AS(bsc::net::node<system>(s, t, o), std::invalid_argument);
}

namespace net_test {
struct Even;
struct Odd;

// A meter whose level grows by one every 100 ms (every step), and a reader that gets it doubled.
struct meter_io {
    bsc::output<int> level;
};
inline constexpr auto meter_chart = bsc::make_chart<meter_io>(
    bsc::composite<Root>(bsc::initial<Even>, bsc::state<Odd>),
    bsc::state<Even> + bsc::after(100ms) / [](meter_io& m) { m.level.set(m.level.pending() + 1); } = bsc::state<Odd>,
    bsc::state<Odd> + bsc::after(100ms) / [](meter_io& m) { m.level.set(m.level.pending() + 1); } = bsc::state<Even>);
struct reader_io {
    bsc::input<int> doubled;
};
inline constexpr auto reader_chart = bsc::make_chart<reader_io>(
    bsc::composite<Root>(bsc::initial<Still>, bsc::state<Moving>),
    bsc::state<Still>[([](reader_io const& r) { return r.doubled.get() < 0; })] = bsc::state<Moving>,
    bsc::state<Moving>[([](reader_io const& r) { return r.doubled.get() >= 0; })] = bsc::state<Still>);
constexpr int twice(int n) { return 2 * n; }

struct gauge_actors {
    bsc::machine<decltype(meter_chart)> meter{meter_chart};
    bsc::machine<decltype(reader_chart)> reader{reader_chart};
};
using gauge = bsc::system<gauge_actors, bsc::order<&gauge_actors::meter, &gauge_actors::reader>,
                          bsc::link<&gauge_actors::meter, &meter_io::level, &gauge_actors::reader, &reader_io::doubled,
                                    bsc::convert<&twice>, bsc::fail_safe<-1>>>;
}  // namespace net_test

TEST_CASE("across nodes a link's bsc::convert applies as in one process, and its fail-safe value is read as it is") {
    std::chrono::steady_clock::time_point now{};
    bsc::net::memory_bus bus;
    bsc::net::memory_transport to_meter{bus}, to_reader{bus};
    net_test::gauge meter_side{}, reader_side{};
    auto options = [&](std::string actor) {
        bsc::net::node_options o;
        o.name = actor;
        o.actors = {actor};
        o.last_step = 3;
        o.clock = [&now] { return now; };
        return o;
    };
    bsc::net::node<net_test::gauge> meter_node{meter_side, to_meter, options("meter")};
    bsc::net::node<net_test::gauge> reader_node{reader_side, to_reader, options("reader")};
    for (int i = 0; i < 1000; ++i)
        if (meter_node.run_once(0ms) + reader_node.run_once(0ms) == 0) break;
    REQUIRE(reader_node.completed(1) == 3);
    CHECK(meter_side.actors.meter.context().level.get() == 3);      // one more in each of steps 1 to 3
    CHECK(reader_side.actors.reader.context().doubled.get() == 6);  // step 3's level (the meter steps first), doubled
    to_meter.disconnect();                                          // the meter's will: stale at once
    reader_node.stop_after(4);
    now += 100ms;
    reader_node.run_once(0ms);
    CHECK(reader_node.completed(1) == 4);
    CHECK(reader_side.actors.reader.context().doubled.get() == -1);  // the fail-safe value, not twice it
    CHECK(reader_side.actors.reader.is<net_test::Moving>());
}
