// The bottle-filling station (examples/filling_station/station.hpp) under both priorities among
// nested transitions, on both back ends: the e-stop pressed in the scan that an inner row reads
// too (a bottle arriving, the bottle full, the cap's time up) stops the station with every
// output off under parent first, and lets the inner row fire under child first; without the
// e-stop the two priorities run alike; and the explorer proves the parent-first chart safe and
// refutes the child-first one with the reported case.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include <cstddef>
#include <string>

#include "backends.hpp"
#include "../../examples/filling_station/station.hpp"

namespace filling_test {

template <class Backend, bsc::priority P>
using machine = bsc_test::machine_t<Backend, bsc::chart_ref<filling::chart<P>>, bsc::scan_policy>;

struct inputs {
    bool estop = false;
    bool bottle = false;
    bool full = false;
    bool reset = false;
};

// A station under priority P and its clock: each scan sets the inputs, then steps one period
// later.
template <class Backend, bsc::priority P>
struct plc {
    machine<Backend, P> m{filling::chart<P>};
    bsc::duration now{};

    void scan(inputs in) {
        m.context().estop.set(in.estop);
        m.context().bottle.set(in.bottle);
        m.context().full.set(in.full);
        m.context().reset.set(in.reset);
        m.step(now);
        now += filling::scan_period;
    }
    bool valve() const { return m.context().valve.get(); }
    bool capper() const { return m.context().capper.get(); }
    std::string states() const { return m.active_states().joined(); }
};

// A station run to Filling: the nozzle clear, then a bottle.
template <class Backend, bsc::priority P>
plc<Backend, P> run_to_filling() {
    plc<Backend, P> s;
    s.scan({});
    s.scan({.bottle = true});
    REQUIRE(s.m.template is<filling::Filling>());
    REQUIRE(s.valve());
    return s;
}

// Feeds the same scans to both stations, every sequence of the 8 combinations of bottle, full
// and reset up to `depth` long (plausible or not), and checks that they answer alike, with the
// valve open exactly in Filling and the capper on exactly in Capping.
template <class Backend>
void compare(plc<Backend, bsc::parent_first> const& parent, plc<Backend, bsc::child_first> const& child, int depth,
             long& scans) {
    if (depth == 0) return;
    for (int bits = 0; bits < 8; ++bits) {
        inputs const in{.bottle = (bits & 1) != 0, .full = (bits & 2) != 0, .reset = (bits & 4) != 0};
        auto p = parent;
        auto c = child;
        p.scan(in);
        c.scan(in);
        ++scans;
        bool const same = p.states() == c.states() && p.valve() == c.valve() && p.capper() == c.capper() &&
                          p.valve() == p.m.template is<filling::Filling>() &&
                          p.capper() == p.m.template is<filling::Capping>();
        if (!same) {
            FAIL_CHECK("the priorities differ: " << p.states() << " against " << c.states());
            return;
        }
        compare(p, c, depth - 1, scans);
    }
}

}  // namespace filling_test

TEST_CASE_TEMPLATE("filling_station: e-stop as a bottle arrives: parent first stops, child first opens the valve",
                   Backend, bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    plc<Backend, bsc::parent_first> parent;
    plc<Backend, bsc::child_first> child;
    parent.scan({});
    child.scan({});
    REQUIRE(parent.m.template is<filling::Idle>());
    REQUIRE(child.m.template is<filling::Idle>());

    parent.scan({.estop = true, .bottle = true});
    child.scan({.estop = true, .bottle = true});
    CHECK(parent.states() == "Station EStop");
    CHECK_FALSE(parent.valve());
    CHECK(child.states() == "Station Normal Operating Filling");
    CHECK(child.valve());  // open, with the e-stop pressed

    // Child first stops one scan late, the valve having been open for that scan.
    child.scan({.estop = true, .bottle = true});
    CHECK(child.m.template is<filling::EStop>());
    CHECK_FALSE(child.valve());
}

TEST_CASE_TEMPLATE("filling_station: e-stop as the bottle is full: parent first stops, child first caps", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    auto parent = run_to_filling<Backend, bsc::parent_first>();
    auto child = run_to_filling<Backend, bsc::child_first>();
    parent.scan({.estop = true, .bottle = true, .full = true});
    child.scan({.estop = true, .bottle = true, .full = true});
    CHECK(parent.m.template is<filling::EStop>());
    CHECK_FALSE(parent.valve());
    CHECK_FALSE(parent.capper());
    CHECK(child.m.template is<filling::Capping>());
    CHECK_FALSE(child.valve());
    CHECK(child.capper());
}

TEST_CASE_TEMPLATE("filling_station: e-stop as the cap's time is up: parent first stops, child first takes the timeout",
                   Backend, bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    auto parent = run_to_filling<Backend, bsc::parent_first>();
    auto child = run_to_filling<Backend, bsc::child_first>();
    for (int k = 0; k < 3; ++k) {  // Capping entered, then 200 ms of the 300
        parent.scan({.bottle = true, .full = true});
        child.scan({.bottle = true, .full = true});
    }
    REQUIRE(parent.m.template is<filling::Capping>());
    REQUIRE(child.m.template is<filling::Capping>());
    parent.scan({.estop = true, .bottle = true, .full = true});  // 300 ms: Capping's timeout is due
    child.scan({.estop = true, .bottle = true, .full = true});
    CHECK(parent.m.template is<filling::EStop>());
    CHECK_FALSE(parent.capper());
    CHECK(child.m.template is<filling::Capped>());
}

TEST_CASE_TEMPLATE("filling_station: after an e-stop, reset only with the button released, then the nozzle cleared",
                   Backend, bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    auto s = run_to_filling<Backend, bsc::parent_first>();
    s.scan({.estop = true, .bottle = true});
    REQUIRE(s.m.template is<filling::EStop>());
    s.scan({.estop = true, .bottle = true, .reset = true});  // still pressed: the reset is refused
    CHECK(s.m.template is<filling::EStop>());
    s.scan({.bottle = true});  // released: nothing restarts by itself
    CHECK(s.m.template is<filling::EStop>());
    s.scan({.bottle = true, .reset = true});
    CHECK(s.states() == "Station Normal Clearing");
    s.scan({.bottle = true});  // the half-filled bottle is still under the nozzle
    CHECK(s.m.template is<filling::Clearing>());
    CHECK_FALSE(s.valve());
    s.scan({});
    CHECK(s.m.template is<filling::Idle>());
}

TEST_CASE_TEMPLATE("filling_station: without the e-stop the priorities run alike, the valve open exactly in Filling",
                   Backend, bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    long scans = 0;
    compare(plc<Backend, bsc::parent_first>{}, plc<Backend, bsc::child_first>{}, 5, scans);
    CHECK(scans == 8 + 64 + 512 + 4096 + 32768);
}

TEST_CASE_TEMPLATE(
    "filling_station: explored with the e-stop and the bottle free: parent first safe, child first refuted", Backend,
    bsc_test::compiled, bsc_test::table) {
    using namespace filling_test;
    auto const label = [](std::size_t c) {
        return "estop=" + std::to_string(c & 1u) + " bottle=" + std::to_string((c >> 1) & 1u);
    };
    // The e-stop and the bottle are enough to tell the priorities apart.
    auto const apply = [](filling::io const& d, std::size_t c) {
        d.estop.set((c & 1u) != 0);
        d.bottle.set((c & 2u) != 0);
        d.full.set(false);
        d.reset.set(false);
    };
    auto const valve_closed = [](auto const& m) { return !m.context().estop.get() || !m.context().valve.get(); };

    using parent_machine = machine<Backend, bsc::parent_first>;
    bsc::verify::explorer parent{bsc::verify::cycle_model{parent_machine{filling::chart<bsc::parent_first>},
                                                          filling::scan_period, 4, apply, label}};
    REQUIRE(parent.run().complete);
    CHECK(bsc::verify::always(parent, "valve closed while the e-stop is pressed", valve_closed).holds());
    CHECK(bsc::verify::reachable(parent, "Filling", [](auto const& m) {
              return m.template is<filling::Filling>();
          }).holds());

    using child_machine = machine<Backend, bsc::child_first>;
    bsc::verify::explorer child{bsc::verify::cycle_model{child_machine{filling::chart<bsc::child_first>},
                                                         filling::scan_period, 4, apply, label}};
    REQUIRE(child.run().complete);
    auto const v = bsc::verify::always(child, "valve closed while the e-stop is pressed", valve_closed);
    REQUIRE(v.fails());
    REQUIRE(v.trace.size() == 3);
    CHECK(v.trace[1].label == "estop=0 bottle=0");
    CHECK(v.trace[1].configuration == "Station Normal Operating Idle");
    CHECK(v.trace[2].label == "estop=1 bottle=1");
    CHECK(v.trace[2].configuration == "Station Normal Operating Filling");
}
