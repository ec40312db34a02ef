// Priority among nested transitions (bsc/priority.hpp): which of a state's candidates is tried
// first, its own or its ancestors', on both back ends: on events, on eventless transitions
// while settling, in the components of the BSC cycle, across parallel regions; what the exports
// and the logger show of it.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/export.hpp>
#include <bsc/logger.hpp>

#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>

#include "../compile_fail/region_cycle.hpp"
#include "backends.hpp"
#include "generated_charts.hpp"

using namespace std::chrono_literals;
using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;

namespace prio {
struct bottle {};
struct estop {
    bool pressed = true;
};
struct reset {};
struct arm {};
struct Station;
struct Normal;
struct Idle;
struct Filling;
struct Capping;
struct EStop;

struct io {
    int valve_openings = 0;
    bool full = false;
    bool pressed = false;
};

inline constexpr auto estop_pressed = bsc::named("pressed",
                                                 bsc::guard([](io const&, estop const& e) { return e.pressed; }));
inline constexpr auto pressed_now = bsc::named("pressed", bsc::guard([](io const& c) { return c.pressed; }));
inline constexpr auto full_now = bsc::named("full", bsc::guard([](io const& c) { return c.full; }));

// The e-stop of the report: Normal's row and Filling's row take the same event.
template <bsc::priority P>
constexpr auto station() {
    return bsc::make_chart<io, P>(
        bsc::composite<Station>(
            bsc::initial<Normal>,
            bsc::composite<Normal>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Filling>, bsc::state<Capping>),
            bsc::state<EStop>),
        bsc::state<Filling> + bsc::on_entry / [](io& c) { ++c.valve_openings; },
        bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
        bsc::state<Filling> + bsc::event<estop> = bsc::state<Capping>,  // an inner row on the same event
        bsc::state<Normal> + bsc::event<estop>[estop_pressed] = bsc::state<EStop>,
        bsc::state<Capping> + bsc::event<bottle> = bsc::state<Filling>,
        bsc::state<EStop> + bsc::event<reset> = bsc::state<Normal>);
}
inline constexpr auto parent_first_station = station<bsc::parent_first>();
inline constexpr auto child_first_station = station<bsc::child_first>();

// Eventless rows: `arm` makes both conditions true at once.
template <bsc::priority P>
constexpr auto conditions() {
    return bsc::make_chart<io, P>(
        bsc::composite<Station>(bsc::initial<Normal>,
                                bsc::composite<Normal>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Filling>),
                                bsc::state<Capping>, bsc::state<EStop>),
        bsc::state<Idle> + bsc::event<arm> /
                               [](io& c) {
                                   c.full = true;
                                   c.pressed = true;
                               } = bsc::state<Filling>,
        bsc::state<Filling>[full_now] = bsc::state<Capping>, bsc::state<Normal>[pressed_now] = bsc::state<EStop>,
        bsc::state<Capping> + bsc::event<reset> = bsc::state<Normal>,
        bsc::state<EStop> + bsc::event<reset> / [](io& c) { c.pressed = false; } = bsc::state<Normal>);
}
inline constexpr auto parent_first_conditions = conditions<bsc::parent_first>();
inline constexpr auto child_first_conditions = conditions<bsc::child_first>();

// Three levels and a parallel state: Outer's row sits above both regions.
struct go {};
struct Top;
struct Outer;
struct Par;
struct RegionA;
struct RegionB;
struct A1;
struct A2;
struct B1;
struct B2;
struct Away;
struct Mid;
struct M1;
struct M2;

struct trace {
    std::string fired;
    bool leave = true;
};
template <char C>
inline constexpr auto note = [](trace& t) { t.fired += C; };

template <bsc::priority P>
constexpr auto nested() {
    return bsc::make_chart<trace, P>(
        bsc::composite<Top>(
            bsc::initial<Outer>,
            bsc::composite<Outer>(
                bsc::initial<Par>,
                bsc::parallel<Par>(bsc::composite<RegionA>(bsc::initial<A1>, bsc::state<A1>, bsc::state<A2>),
                                   bsc::composite<RegionB>(bsc::initial<B1>, bsc::state<B1>, bsc::state<B2>)),
                bsc::composite<Mid>(bsc::initial<M1>, bsc::state<M1>, bsc::state<M2>)),
            bsc::state<Away>),
        bsc::state<A1> + bsc::event<go> / note<'a'> = bsc::state<A2>,
        bsc::state<B1> + bsc::event<go> / note<'b'> = bsc::state<B2>,
        bsc::state<Outer> + bsc::event<go>[([](trace const& t) { return t.leave; })] / note<'o'> = bsc::state<Away>,
        bsc::state<A2> + bsc::event<reset> = bsc::state<Mid>,
        bsc::state<M1> + bsc::event<go> / note<'1'> = bsc::state<M2>,
        bsc::state<Mid> + bsc::event<go>[([](trace const& t) { return !t.leave; })] / note<'m'> = bsc::state<M1>,
        bsc::state<M2> + bsc::event<reset> = bsc::state<M1>,
        bsc::state<Away> + bsc::event<reset> / [](trace& t) { t.leave = false; } = bsc::state<Outer>);
}
inline constexpr auto parent_first_nested = nested<bsc::parent_first>();
inline constexpr auto child_first_nested = nested<bsc::child_first>();
}  // namespace prio

TEST_CASE_TEMPLATE("parent first, the outer e-stop wins over the inner row on the same event", Backend, compiled,
                   table) {
    using namespace prio;
    machine_t<Backend, decltype(parent_first_station)> m{parent_first_station, io{}};
    m.dispatch(bottle{});
    REQUIRE(m.template is<Filling>());
    CHECK(m.dispatch(estop{}) == bsc::outcome::consumed);
    CHECK(m.template is<EStop>());
    m.dispatch(reset{});
    m.dispatch(bottle{});
    // The outer row's guard is false: the inner row, tried next, fires.
    m.dispatch(estop{false});
    CHECK(m.template is<Capping>());
    CHECK(m.context().valve_openings == 2);
}

TEST_CASE_TEMPLATE("child first, the same chart lets the inner row win", Backend, compiled, table) {
    using namespace prio;
    machine_t<Backend, decltype(child_first_station)> m{child_first_station, io{}};
    m.dispatch(bottle{});
    m.dispatch(estop{});
    CHECK(m.template is<Capping>());  // the e-stop was lost to Filling's row
    m.dispatch(estop{});
    CHECK(m.template is<EStop>());  // Capping has no row on estop: Normal's row fires
}

TEST_CASE_TEMPLATE("eventless transitions settle in the chart's priority order", Backend, compiled, table) {
    using namespace prio;
    machine_t<Backend, decltype(parent_first_conditions)> parent{parent_first_conditions, io{}};
    machine_t<Backend, decltype(child_first_conditions)> child{child_first_conditions, io{}};
    parent.dispatch(arm{});
    child.dispatch(arm{});
    CHECK(parent.template is<EStop>());
    CHECK(child.template is<Capping>());
}

TEST_CASE_TEMPLATE("a component's turn in the BSC cycle tries the outer condition first, parent first", Backend,
                   compiled, table) {
    using namespace prio;
    machine_t<Backend, decltype(parent_first_conditions), bsc::scan_policy> parent{parent_first_conditions, io{}};
    machine_t<Backend, decltype(child_first_conditions), bsc::scan_policy> child{child_first_conditions, io{}};
    parent.step(0ms);
    child.step(0ms);
    parent.dispatch(arm{});  // under the scan policy, the eventless rows wait for the next cycle
    child.dispatch(arm{});
    REQUIRE(parent.template is<Filling>());
    REQUIRE(child.template is<Filling>());
    CHECK(parent.step(1ms).transitions == 1);
    CHECK(child.step(1ms).transitions == 1);
    CHECK(parent.template is<EStop>());
    CHECK(child.template is<Capping>());
}

TEST_CASE_TEMPLATE("parent first, a row above a parallel state wins over every region's row", Backend, compiled,
                   table) {
    using namespace prio;
    machine_t<Backend, decltype(parent_first_nested)> parent{parent_first_nested, trace{}};
    machine_t<Backend, decltype(child_first_nested)> child{child_first_nested, trace{}};
    parent.dispatch(go{});
    child.dispatch(go{});
    CHECK(parent.context().fired == "o");
    CHECK(parent.template is<Away>());
    CHECK(child.context().fired == "ab");  // both regions' rows; Outer's row conflicts with them and loses
    CHECK(child.template is<A2>());
    CHECK(child.template is<B2>());

    // Outer's guard now false: parent first, the regions' rows fire as child first would.
    parent.dispatch(reset{});
    parent.dispatch(go{});
    CHECK(parent.context().fired == "oab");
    // Three levels: Outer (guard false), Mid (guard true), then M1. Parent first, Mid's row wins;
    // child first, M1's.
    parent.dispatch(reset{});
    REQUIRE(parent.template is<M1>());
    parent.dispatch(go{});
    CHECK(parent.context().fired == "oabm");
    CHECK(parent.template is<M1>());
    child.dispatch(reset{});
    REQUIRE(child.template is<M1>());
    child.dispatch(go{});  // Outer's guard is still true in this machine: child first, M1's own row
    CHECK(child.context().fired == "ab1");
    CHECK(child.template is<M2>());
}

TEST_CASE_TEMPLATE("parent first, the livelock check's twin runs: the outer eventless row leaves first", Backend,
                   compiled, table) {
    static constexpr auto chart = cf::region_cycle<bsc::parent_first>();  // rejected child first
    machine_t<Backend, decltype(chart)> m{chart, cf::region_ctx{}};
    CHECK(m.halted());
    CHECK(m.template is<cf::Done>());
}

namespace prio {
// A longer outer timeout beside a shorter inner one that leaves it, with a guarded row of the root
// tried first, parent first, in the same component: while the root's row fires, one transition
// per cycle, the inner timeout waits, and the outer one comes due. make_chart accepts the chart
// (the outer timeout is not dead), and it fires.
struct monitor {
    int scans = 0;
};
struct Busy;
struct Step;
struct Retry;
inline constexpr auto held_back = bsc::make_chart<monitor, bsc::parent_first>(
    bsc::composite<Station>(bsc::initial<Idle>, bsc::state<Idle>,
                            bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>), bsc::state<Retry>),
    bsc::state<Station>[([](monitor const& m) { return m.scans < 15; })] / [](monitor& m) { ++m.scans; },
    bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>,
    bsc::state<Busy> + bsc::after(std::chrono::milliseconds(1200)) = bsc::state<Idle>,
    bsc::state<Step> + bsc::after(std::chrono::seconds(1)) = bsc::state<Retry>,
    bsc::state<Retry> + bsc::event<go> = bsc::state<Idle>);
}  // namespace prio

TEST_CASE_TEMPLATE("parent first, an outer timeout longer than an inner one fires while the inner one is held back",
                   Backend, compiled, table) {
    using namespace prio;
    machine_t<Backend, decltype(held_back), bsc::scan_policy> m{held_back, monitor{}};
    m.step(0ms);
    m.dispatch(go{});
    REQUIRE(m.template is<Step>());
    int scan = 1;
    for (; scan <= 20 && m.template is<Step>(); ++scan) m.step(std::chrono::milliseconds(100 * scan));
    CHECK(m.template is<Idle>());  // Busy's 1.2 s timeout, not Step's 1 s one
    CHECK(scan - 1 == 15);         // the first scan after the root's row stops firing
}

TEST_CASE("the priority is the chart's, known at compile time, and the default is child first") {
    using namespace prio;
    static_assert(decltype(parent_first_station)::order == bsc::priority::parent_first);
    static_assert(decltype(child_first_station)::order == bsc::priority::child_first);
    static constexpr auto plain = bsc::make_chart<io>(
        bsc::composite<Station>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Filling>),
        bsc::state<Idle> + bsc::event<bottle> = bsc::state<Filling>,
        bsc::state<Filling> + bsc::event<reset> = bsc::state<Idle>);
    static_assert(decltype(plain)::order == bsc::priority::child_first);
    // Each priority is a chart type of its own; a chart_ref keeps it.
    static_assert(!std::is_same_v<decltype(parent_first_station), decltype(child_first_station)>);
    static_assert(bsc::chart_ref<parent_first_station>::order == bsc::priority::parent_first);
    static_assert(bsc::table::tables<decltype(parent_first_station)>::order == bsc::priority::parent_first);
    static_assert(bsc::table::tables<decltype(child_first_station)>::order == bsc::priority::child_first);
}

TEST_CASE("the exports say parent first, and the SCXML conditions encode it") {
    using namespace prio;
    std::string const note = "priority: parent first (outer transitions before inner ones)";
    CHECK(bsc::to_dot(parent_first_station).find("label=\"" + note + "\"; labelloc=t;") != std::string::npos);
    CHECK(bsc::to_mermaid(parent_first_station).rfind("---\ntitle: \"" + note + "\"\n---\nstateDiagram-v2\n", 0) == 0);
    CHECK(bsc::to_plantuml(parent_first_station).find("\ntitle " + note + "\n") != std::string::npos);
    for (auto const& text : {bsc::to_dot(child_first_station), bsc::to_mermaid(child_first_station),
                             bsc::to_plantuml(child_first_station), bsc::to_scxml(child_first_station)})
        CHECK(text.find("parent first") == std::string::npos);

    auto const parent = bsc::to_scxml(parent_first_station);
    // Filling's row on estop fires only when Normal's, tried first, does not.
    CHECK(parent.find("<transition event=\"estop\" cond=\"!(pressed)\" target=\"Capping\"/>") != std::string::npos);
    CHECK(parent.find("<transition event=\"estop\" cond=\"pressed\" target=\"EStop\"/>") != std::string::npos);
    CHECK(parent.find("Parent-first priority") != std::string::npos);
    // Rows no outer row competes with are written as they are.
    CHECK(parent.find("<transition event=\"bottle\" target=\"Filling\"/>") != std::string::npos);
    auto const child = bsc::to_scxml(child_first_station);
    CHECK(child.find("<transition event=\"estop\" target=\"Capping\"/>") != std::string::npos);

    // Eventless rows: Filling's condition negates Normal's, and keeps its own.
    auto const conditions = bsc::to_scxml(parent_first_conditions);
    CHECK(conditions.find("<transition cond=\"!(pressed) &amp;&amp; (full)\" target=\"Capping\"/>") !=
          std::string::npos);
}

TEST_CASE_TEMPLATE("the logger reports the outer transition that won", Backend, compiled, table) {
    using namespace prio;
    std::ostringstream out;
    machine_t<Backend, decltype(parent_first_station), bsc::default_policy, bsc::logger> m{parent_first_station, io{},
                                                                                           bsc::logger{out}};
    m.dispatch(bottle{});
    m.dispatch(estop{});
    auto const log = out.str();
    CHECK(log.find("transition Normal -> EStop on estop [pressed]") != std::string::npos);
    CHECK(log.find("Filling -> Capping") == std::string::npos);
}

TEST_CASE("the generated parent-first charts have outer rows that compete with inner ones") {
    // So that the differential test and the fuzz target (gen::parent_first) exercise the order.
    auto const competing = [](auto const& chart) {
        using model = bsc::detail::chart_model<std::remove_cvref_t<decltype(chart)>>;
        int n = 0;
        for (int o = 0; o < model::R; ++o)
            for (int i = 0; i < model::R; ++i) n += bsc::detail::outer_tried_first(model::tree, model::rows, o, i);
        return n;
    };
    int total = 0;
    for (int n : {competing(gen::parent_first<2>::chart), competing(gen::parent_first<4>::chart),
                  competing(gen::parent_first<7>::chart), competing(gen::parent_first_scan<5>::chart),
                  competing(gen::parent_first_scan<11>::chart)})
        total += n > 0;
    CHECK(total >= 3);
    static_assert(std::remove_cvref_t<decltype(gen::parent_first<2>::chart)>::order == bsc::priority::parent_first);
    static_assert(std::remove_cvref_t<decltype(gen::generated<2>::chart)>::order == bsc::priority::child_first);
}
