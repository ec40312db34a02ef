// The manufacturing cell example (examples/manufacturing_cell): the controller of the Basic
// Statechart paper in closed loop with the plant model, under several arrival patterns and scan
// periods, checked on every cycle against the paper's requirements; the timing of the timed
// devices to the cycle; the empty cell; and the structure of the chart.

#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../../examples/manufacturing_cell/controller.hpp"
#include "../../examples/manufacturing_cell/monitor.hpp"
#include "../../examples/manufacturing_cell/plant.hpp"

using namespace std::chrono_literals;

namespace {

/// An arrival pattern, the scan period to run it at and the plant's times.
struct scenario {
    std::string name;
    std::vector<bsc::duration> arrivals;
    bsc::duration period = 100ms;
    cell::plant_timing timing{};
};

/// A plant whose belt takes longer than the drill (4 s against T1 = 3 s), so that the belt,
/// not the drill, is the last device to finish a phase.
cell::plant_timing slow_belt() {
    cell::plant_timing t;
    t.belt_travel = 4s;
    return t;
}

std::vector<scenario> scenarios() {
    namespace a = cell::arrivals;
    return {
        {"one piece", a::steady(1, 0s, 0s)},
        {"one piece, late", a::steady(1, 7300ms, 0s)},
        {"steady stream", a::steady(12, 0s, 4s)},
        {"steady stream, faster than the cell", a::steady(10, 500ms, 1s)},
        {"bursts", a::bursts(3, 4, 1s, 30s)},
        {"everything at once", a::bursts(1, 8, 0s, 0s)},
        {"random, seed 1", a::random(25, 1, 500ms, 8s)},
        {"random, seed 2", a::random(25, 2, 500ms, 8s)},
        {"random, seed 3", a::random(25, 3, 500ms, 8s)},
        {"random, seed 4, period 70 ms", a::random(25, 4, 200ms, 10s), 70ms},
        {"steady stream, period 250 ms", a::steady(8, 0s, 5s), 250ms},
        {"bursts, period 30 ms", a::bursts(2, 3, 0s, 25s), 30ms},
        {"steady stream, slow belt", a::steady(8, 0s, 3s), 100ms, slow_belt()},
        {"random, seed 5, slow belt", a::random(15, 5, 500ms, 8s), 100ms, slow_belt()},
    };
}

/// An upper bound on the cycles a run may take: every piece through the cell one by one.
long cycle_budget(scenario const& s) {
    bsc::duration const last = s.arrivals.empty() ? bsc::duration{} : s.arrivals.back();
    return static_cast<long>((last + static_cast<long>(s.arrivals.size() + 5) * 30s) / s.period);
}

/// The name of the one state of S... that is active, or "" if none or several are.
template <class... S, class M>
std::string_view one_of(M const& m) {
    std::string_view found;
    int active = 0;
    auto const visit = [&]<class T>() {
        if (m.template is<T>()) {
            found = bsc::name_of<T>;
            ++active;
        }
    };
    (visit.template operator()<S>(), ...);
    return active == 1 ? found : std::string_view{};
}

/// The active state of each component, in the paper's order (belt, drill, test, robot, table).
template <class M>
std::array<std::string_view, 5> component_states(M const& m) {
    return {one_of<cell::BeltOff, cell::BeltOn, cell::BeltDone>(m), one_of<cell::DrillOff, cell::DrillOn>(m),
            one_of<cell::TestOff, cell::TestOn>(m), one_of<cell::RobotOff, cell::RobotOn>(m),
            one_of<cell::CylinderReturned, cell::CylinderAdvancing, cell::CylinderReturning>(m)};
}

/// An observer that records the transitions taken, as "Source>Target" ("internal" as target
/// of an internal transition).
struct recorder {
    std::vector<std::string> fired;
    template <class S, class T, class E>
    void on_transition(S, T, E const&) {
        fired.push_back(std::string(S::name) + ">" + std::string(T::name));
    }
};

/// The results of one closed-loop run that the tests look at.
struct run_result {
    bool done = false;
    std::vector<std::string> violations;
    std::vector<cell::piece> pieces;
    int turns = 0;
    long cycles = 0;
    std::array<std::vector<int>, 3> on_runs;  // drill, test, robot: cycles on, counted here
    std::vector<char> starts;                 // the order devices started in: b, d, t, r, v
    std::set<std::string> configurations;     // the active configurations seen between cycles
};

/// Runs a scenario in closed loop and checks, on every cycle, what can be read directly from
/// the cycle's record (the monitor checks the rest).
run_result run(scenario const& s) {
    INFO("scenario: " << s.name);
    cell::machine m{cell::chart};
    cell::closed_loop loop{m, s.arrivals, s.period, s.timing};
    run_result r;
    std::array<int, 3> on{};
    cell::actuators last{};
    long const budget = cycle_budget(s);
    while (!loop.done() && loop.cycles() < budget) {
        cell::cycle_record const c = loop.cycle();
        auto const& o = c.out;
        // Every cycle: the structure holds (one state per component) ...
        auto const states = component_states(m);
        for (std::string_view st : states) REQUIRE_FALSE(st.empty());
        r.configurations.insert(m.active_states().joined());
        // ... no device runs while the valve is on ...
        if (o.valve) CHECK_FALSE((o.belt || o.drill || o.test || o.robot));
        // ... and a device that starts had its piece when the cycle latched the sensors.
        if (o.belt && !last.belt) CHECK((c.latched.IN && !c.latched.P1));
        if (o.drill && !last.drill) CHECK(c.latched.P2);
        if (o.test && !last.test) CHECK(c.latched.P3);
        if (o.robot && !last.robot) CHECK(c.latched.P4);
        if (o.valve && !last.valve) CHECK((c.latched.P1 || c.latched.P2 || c.latched.P3));
        std::array<bool, 5> const now{o.belt, o.drill, o.test, o.robot, o.valve};
        std::array<bool, 5> const before{last.belt, last.drill, last.test, last.robot, last.valve};
        for (std::size_t i = 0; i < 5; ++i)
            if (now[i] && !before[i]) r.starts.push_back("bdtrv"[i]);
        for (std::size_t i = 0; i < 3; ++i) {
            if (now[i + 1]) {
                ++on[i];
            } else if (before[i + 1]) {
                r.on_runs[i].push_back(on[i]);
                on[i] = 0;
            }
        }
        last = o;
    }
    r.done = loop.run(budget);
    r.violations = loop.monitor().violations();
    r.pieces = loop.plant().pieces();
    r.turns = loop.plant().turns();
    r.cycles = loop.cycles();
    return r;
}

void check_outcome(scenario const& s, run_result const& r) {
    INFO("scenario: " << s.name);
    CHECK(r.done);
    for (std::string const& v : r.violations) FAIL_CHECK(v);
    REQUIRE(r.pieces.size() == s.arrivals.size());
    for (cell::piece const& p : r.pieces) {
        INFO("piece " << p.id);
        CHECK(p.stored);
        CHECK(p.drilled == 1);
        CHECK(p.tested == 1);
        if (p.id > 0) CHECK(p.stored_at > r.pieces[static_cast<std::size_t>(p.id - 1)].stored_at);  // FIFO
    }
}

}  // namespace

namespace {
// A scan machine with BSC timers in its context, in a global: constant-initialised (constinit).
constinit cell::machine global_cell{cell::chart};
}  // namespace

TEST_CASE("manufacturing cell: a controller in a global is constant-initialised (constinit) and runs") {
    CHECK(global_cell.active_states().joined() ==
          "Cell Belt BeltOff Drill DrillOff Test TestOff Robot RobotOff Table CylinderReturned");
    global_cell.context().IN.set(true);
    global_cell.step(std::chrono::milliseconds{0});
    global_cell.step(std::chrono::milliseconds{10});
    CHECK(global_cell.context().belt.get());
}

TEST_CASE("manufacturing cell: the expected on-time follows the BSC timer semantics") {
    // Started in cycle k, timing from cycle k+1, expired at the first cycle at least the limit
    // after that: on for 1 + ceil(limit / period) cycles.
    CHECK(cell::expected_on_cycles(3s, 100ms) == 31);
    CHECK(cell::expected_on_cycles(2500ms, 100ms) == 26);
    CHECK(cell::expected_on_cycles(3s, 70ms) == 1 + 43);  // 3000 / 70 = 42.9
    CHECK(cell::expected_on_cycles(2500ms, 250ms) == 11);
    CHECK(cell::expected_on_cycles(300ms, 100ms) == 4);  // the case of cycle_test.cpp
}

TEST_CASE("manufacturing cell: every arrival pattern runs through the cell and meets the requirements") {
    for (scenario const& s : scenarios()) {
        SUBCASE(s.name.c_str()) {
            run_result const r = run(s);
            check_outcome(s, r);
            // Timing to the cycle: drill, test and robot follow T1, T2 and T3.
            std::array<bsc::duration, 3> const limits{cell::drill_time, cell::test_time, cell::robot_time};
            for (std::size_t i = 0; i < 3; ++i) {
                INFO("device " << cell::device_names[i + 1]);
                CHECK(r.on_runs[i].size() == s.arrivals.size());  // once per piece
                for (int cycles : r.on_runs[i]) CHECK(cycles == cell::expected_on_cycles(limits[i], s.period));
            }
        }
    }
}

TEST_CASE("manufacturing cell: one piece goes belt, turn, drill, turn, test, turn, robot") {
    scenario const s{"one piece", cell::arrivals::steady(1, 0s, 0s)};
    run_result const r = run(s);
    check_outcome(s, r);
    CHECK(std::string(r.starts.begin(), r.starts.end()) == "bvdvtvr");
    CHECK(r.turns == 3);  // after the third turn P1..P3 are empty: g15, no fourth turn
}

TEST_CASE("manufacturing cell: without pieces nothing moves and E1..E4 alternate") {
    using machine = bsc::machine<decltype(cell::chart), bsc::scan_policy, recorder>;
    machine m{cell::chart, cell::data{}, recorder{}};
    cell::closed_loop loop{m, cell::arrivals::none(), 100ms};
    std::vector<std::vector<std::string>> fired;
    std::vector<std::array<bool, 4>> e;
    for (int i = 0; i < 40; ++i) {
        m.observer().fired.clear();
        cell::cycle_record const c = loop.cycle();
        CHECK(c.out == cell::actuators{});
        CHECK(m.is<cell::CylinderReturned>());
        fired.push_back(m.observer().fired);
        auto const& d = m.context();
        e.push_back({d.E1, d.E2, d.E3, d.E4});
    }
    CHECK(loop.plant().turns() == 0);
    CHECK(loop.monitor().ok());
    // Each phase takes two cycles: every device ends it without acting (g3, g6, g9, g12), the
    // table resets E1..E4 without turning (g15), and the belt comes back from BeltDone.
    auto const count = [&](std::size_t i, std::string_view t) {
        int n = 0;
        for (auto const& f : fired[i]) n += f == t ? 1 : 0;
        return n;
    };
    for (std::size_t i = 2; i + 1 < fired.size(); i += 2) {
        INFO("cycles " << i << " and " << i + 1);
        for (char const* t : {"BeltOff>BeltDone", "DrillOff>internal", "TestOff>internal", "RobotOff>internal",
                              "CylinderReturned>internal", "BeltDone>BeltOff"})
            CHECK(count(i, t) + count(i + 1, t) == 1);
        CHECK(fired[i].size() + fired[i + 1].size() == 6);
    }
    // Seen between cycles, E2..E4 alternate between true and false; E1 is set and reset
    // within the cycle of g15, since the belt runs before the table.
    for (std::size_t i = 3; i < e.size(); ++i) {
        INFO("cycle " << i);
        CHECK(e[i][1] != e[i - 1][1]);
        CHECK(e[i][1] == e[i][2]);
        CHECK(e[i][2] == e[i][3]);
        CHECK_FALSE(e[i][0]);
    }
}

TEST_CASE("manufacturing cell: the chart has the paper's components and states") {
    cell::machine m{cell::chart};
    // A parallel root whose regions are the five components, in the paper's order, each in
    // exactly one state.
    std::string const active = m.active_states().joined();
    CHECK(active.rfind("Cell Belt ", 0) == 0);
    std::vector<std::string> words;
    for (std::size_t b = 0, e = 0; b < active.size(); b = e + 1) {
        e = active.find(' ', b);
        if (e == std::string::npos) e = active.size();
        words.push_back(active.substr(b, e - b));
    }
    REQUIRE(words.size() == 11);
    CHECK(words[1] == "Belt");
    CHECK(words[3] == "Drill");
    CHECK(words[5] == "Test");
    CHECK(words[7] == "Robot");
    CHECK(words[9] == "Table");
    CHECK(m.is<cell::Cell>());
    CHECK(m.is<cell::DrillOff>());
    CHECK(m.is<cell::TestOff>());
    CHECK(m.is<cell::RobotOff>());
    CHECK(m.is<cell::CylinderReturned>());

    // Over the runs, each component is always in exactly one of its states (checked in run())
    // and visits all of them: belt 3, drill 2, test 2, robot 2, table 3 states; the
    // uncontrolled product is the paper's 72 configurations.
    std::set<std::string> configurations;
    std::array<std::set<std::string>, 5> visited;
    for (scenario const& s : scenarios()) {
        run_result const r = run(s);
        configurations.insert(r.configurations.begin(), r.configurations.end());
    }
    for (std::string const& c : configurations) {
        std::vector<std::string> w;
        for (std::size_t b = 0, e = 0; b < c.size(); b = e + 1) {
            e = c.find(' ', b);
            if (e == std::string::npos) e = c.size();
            w.push_back(c.substr(b, e - b));
        }
        REQUIRE(w.size() == 11);
        for (std::size_t i = 0; i < 5; ++i) visited[i].insert(w[2 * i + 2]);
    }
    std::array<std::size_t, 5> const paper{3, 2, 2, 2, 3};
    std::size_t product = 1;
    for (std::size_t i = 0; i < 5; ++i) {
        CHECK(visited[i].size() == paper[i]);
        product *= visited[i].size();
    }
    CHECK(product == 72);

    // The paper's 26 configurations acted on: 3 x 2 x 2 x 2 = 24 with the table standing still
    // (CylinderReturned), and 2 while it turns, with every device off (the belt has ended its
    // phase).
    std::size_t still = 0;
    std::set<std::string> turning;
    for (std::string const& c : configurations) {
        if (c.ends_with("CylinderReturned"))
            ++still;
        else
            turning.insert(c);
    }
    CHECK(still == 24);
    CHECK(turning == std::set<std::string>{
                         "Cell Belt BeltDone Drill DrillOff Test TestOff Robot RobotOff Table CylinderAdvancing",
                         "Cell Belt BeltDone Drill DrillOff Test TestOff Robot RobotOff Table CylinderReturning"});
    CHECK(configurations.size() == 26);
}

TEST_CASE("manufacturing cell: the monitor catches violations of each requirement") {
    cell::plant const p{cell::arrivals::none()};
    cell::sensors const nothing{};
    cell::sensors at_p2{};
    at_p2.P2 = true;
    cell::actuators drill_on{};
    drill_on.drill = true;
    cell::actuators valve_on{};
    valve_on.valve = true;
    cell::actuators off{};

    SUBCASE("constraint 2: a device starts without a piece") {
        cell::monitor m{100ms};
        m.check(0ms, nothing, drill_on, p);
        REQUIRE(m.violations().size() == 1);
        CHECK(m.violations()[0].find("constraint 2") != std::string::npos);
    }
    SUBCASE("constraint 1: a device starts twice between two turns") {
        cell::monitor m{100ms};
        m.check(0ms, at_p2, drill_on, p);
        m.check(100ms, at_p2, off, p);
        m.check(200ms, at_p2, drill_on, p);
        bool found = false;
        for (auto const& v : m.violations()) found = found || v.find("constraint 1") != std::string::npos;
        CHECK(found);
    }
    SUBCASE("constraint 3: the table turns without a piece at P1, P2 or P3") {
        cell::monitor m{100ms};
        m.check(0ms, nothing, valve_on, p);
        REQUIRE(m.violations().size() == 1);
        CHECK(m.violations()[0].find("constraint 3") != std::string::npos);
    }
    SUBCASE("synchronisation: a device runs while the valve is on") {
        cell::monitor m{100ms};
        cell::actuators both = valve_on;
        both.drill = true;
        m.check(0ms, at_p2, both, p);
        bool found = false;
        for (auto const& v : m.violations()) found = found || v.find("synchronisation") != std::string::npos;
        CHECK(found);
    }
    SUBCASE("timing: the drill stops a cycle early") {
        cell::monitor m{100ms};
        int const expected = cell::expected_on_cycles(cell::drill_time, 100ms);
        for (int i = 0; i < expected - 1; ++i) m.check(i * 100ms, at_p2, drill_on, p);
        CHECK(m.ok());
        m.check((expected - 1) * 100ms, at_p2, off, p);
        REQUIRE(m.violations().size() == 1);
        CHECK(m.violations()[0].find("timing") != std::string::npos);
    }
    SUBCASE("a piece that is never stored") {
        cell::plant q{cell::arrivals::steady(1, 0s, 0s)};
        q.arrive(0s);
        cell::monitor m{100ms};
        m.check_end(q);
        CHECK(m.violations().size() == 3);  // not stored, not drilled, not tested
    }
}
