// The diagram exports (<bsc/export.hpp>) and the names of guards and actions (bsc::named):
// named guards and actions behave and compose as before; each format shows every state and
// transition of the four examples, with their structure (initial states, history, parallel
// regions); and a chart built for the purpose checks labels, identifiers and the rarer parts
// (final states, timeouts, internal transitions, template and clashing state names).
// SCXML well-formedness and Graphviz rendering are checked by ctests on the exported files
// (tests/export/check_exports.py).

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/export.hpp>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../../examples/eca_cell/pause.hpp"
#include "../../examples/manufacturing_cell/controller.hpp"
#include "../../examples/mcs/mcs.hpp"
#include "../../examples/production_cell/controllers.hpp"
#include "inside.hpp"

namespace export_test {

using namespace std::chrono_literals;

struct go {};
struct stop {};
struct tick {};

struct Root;
namespace a {
struct Idle;
}
namespace b {
struct Idle;
}
struct Work;
template <int N>
struct Slot;
struct Both;
struct Left;
struct L1;
struct L2;
struct Right;
struct Done;

struct ctx {
    bsc::inout<bool> ready;  // set by the environment, cleared by Slot<1>'s exit action
    int count = 0;
    int resets = 0;
};

inline constexpr auto ready = bsc::named<"ready">(bsc::guard([](ctx const& c) { return c.ready.get(); }));
inline constexpr auto positive = bsc::named("positive", bsc::guard([](ctx const& c) { return c.count > 0; }));
inline constexpr auto below_ten = bsc::guard([](ctx const& c) { return c.count < 10; });
inline constexpr auto count_up = bsc::named<"count_up">(bsc::action([](ctx& c) { ++c.count; }));
inline constexpr auto reset = bsc::named<"reset">([](ctx& c) {  // a plain callable, named
    c.count = 0;
    ++c.resets;
});

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<a::Idle>, bsc::state<b::Idle>,
        bsc::composite<Work>(
            bsc::shallow_history, bsc::initial<Slot<1>>, bsc::state<Slot<2>>,
            bsc::parallel<Both>(bsc::composite<Left>(bsc::initial<L1>, bsc::state<L2>), bsc::state<Right>)),
        bsc::final_state<Done>),
    bsc::state<a::Idle> + bsc::event<go>[ready && !positive] / (count_up, reset) = bsc::state<Work>,
    bsc::state<a::Idle> + bsc::event<stop> = bsc::state<Done>,
    bsc::state<b::Idle>[below_ten || ready] = bsc::state<a::Idle>,
    bsc::state<Slot<1>> + bsc::after(1500ms) = bsc::state<Slot<2>>, bsc::state<Slot<2>> + bsc::event<tick> / count_up,
    bsc::state<Slot<2>> + bsc::event<go> = bsc::state<Both>,
    bsc::state<L1> + bsc::event<tick>[positive] = bsc::state<L2>,
    bsc::state<Work> + bsc::event<stop> / reset = bsc::state<b::Idle>, bsc::state<Work> + bsc::on_entry / count_up,
    bsc::state<Slot<1>> + bsc::on_exit / [](ctx& c) { c.ready.set(false); });

}  // namespace export_test

namespace {

bool has(std::string const& text, std::string_view part) { return text.find(part) != std::string::npos; }

std::size_t count(std::string const& text, std::string_view part) {
    std::size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
    return n;
}

/// A chart's states and transitions, read from bsc's own tables rather than from the model
/// the exports use: names by bsc::name_of, transitions "Source --> Target" by position.
template <class Chart>
struct expected {
    using model = inside::model<Chart>;
    std::vector<std::string> states;
    std::vector<std::pair<std::string, std::string>> transitions;  // with a target
    int internal = 0;
    int composites = 0;  // composite states: one initial marker each
    int parallels = 0;
    int history = 0;

    expected() {
        // clang-format off
        states = []<class... Tags>(inside::type_list<Tags...>) {
            return std::vector<std::string>{std::string(bsc::name_of<Tags>)...};
        }(typename model::tags{});
        // clang-format on
        states.erase(states.begin());  // the implicit top
        for (int s = 1; s < model::N; ++s) {
            auto const i = static_cast<std::size_t>(s);
            composites += model::tree.kinds[i] == inside::kind::composite ? 1 : 0;
            parallels += model::tree.kinds[i] == inside::kind::parallel ? 1 : 0;
            history += model::tree.hist[i] != inside::history::none ? 1 : 0;
        }
        for (int r = 0; r < model::R; ++r) {
            auto const i = static_cast<std::size_t>(r);
            if (model::rows.kinds[i] != inside::row_kind::transition) continue;
            if (model::rows.target[i] < 0) {
                ++internal;
                continue;
            }
            transitions.emplace_back(states[static_cast<std::size_t>(model::rows.source[i] - 1)],
                                     states[static_cast<std::size_t>(model::rows.target[i] - 1)]);
        }
    }
};

/// Every state and every transition of an example (whose state names are identifiers) is in
/// each format, and the structure is there: one initial marker per composite, history, regions.
template <class Chart>
void check_example(Chart const& chart) {
    expected<Chart> const e;
    auto const mermaid = bsc::to_mermaid(chart);
    auto const dot = bsc::to_dot(chart);
    auto const plantuml = bsc::to_plantuml(chart);
    auto const scxml = bsc::to_scxml(chart);
    CAPTURE(mermaid);

    CHECK(mermaid.starts_with("stateDiagram-v2\n"));
    CHECK(has(mermaid, "    [*] --> " + e.states[0] + "\n"));
    CHECK(dot.starts_with("digraph \"" + e.states[0] + "\" {\n"));
    CHECK(dot.ends_with("}\n"));
    CHECK(plantuml.starts_with("@startuml\n"));
    CHECK(plantuml.ends_with("@enduml\n"));
    CHECK(has(scxml, "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" name=\"" + e.states[0] +
                         "\" initial=\"" + e.states[0] + "\">"));

    for (auto const& s : e.states) {
        CAPTURE(s);
        CHECK((has(mermaid, "    " + s + "\n") || has(mermaid, "as " + s + "\n") || has(mermaid, "as " + s + " {\n")));
        CHECK((has(dot, "\"" + s + "\" [label=\"" + s) || has(dot, "subgraph \"cluster_" + s + "\" {")));
        CHECK(has(plantuml, "state \"" + s));
        CHECK(has(scxml, " id=\"" + s + "\""));
    }
    for (auto const& transition : e.transitions) {
        auto const& source = transition.first;  // not a structured binding: CAPTURE is a lambda
        auto const& target = transition.second;
        CAPTURE(source);
        CAPTURE(target);
        CHECK(has(mermaid, "    " + source + " --> " + target));
        CHECK(has(plantuml, "\n" + source + " --> " + target));
        CHECK(has(scxml, "target=\"" + target + "\""));
    }
    // Mermaid: the root's marker, one per composite, one line per transition with a target.
    CHECK(count(mermaid, " --> ") == 1 + static_cast<std::size_t>(e.composites) + e.transitions.size());
    // DOT: the start edge, one initial edge per composite, one edge per transition with a target.
    CHECK(count(dot, " -> ") == 1 + static_cast<std::size_t>(e.composites) + e.transitions.size());
    CHECK(count(dot, "subgraph ") >= static_cast<std::size_t>(e.composites + e.parallels));
    CHECK(count(dot, "shape=circle, label=\"H") == static_cast<std::size_t>(e.history));
    // SCXML: every row a transition; a history composite adds two (<initial>, <history>).
    CHECK(count(scxml, "<transition") == e.transitions.size() + static_cast<std::size_t>(e.internal + 2 * e.history));
    CHECK(count(scxml, "type=\"internal\"") == static_cast<std::size_t>(e.internal));
    CHECK(count(scxml, "<parallel ") == static_cast<std::size_t>(e.parallels));
    CHECK(count(scxml, "<history ") == static_cast<std::size_t>(e.history));
}

}  // namespace

TEST_CASE("a named guard or action behaves as the unnamed one and composes the same way") {
    using namespace export_test;
    // Naming keeps the wrapped kind: guards compose with !, && and ||, actions with `,`.
    static_assert(inside::is_bsc_guard<std::remove_cvref_t<decltype(ready)>>);
    static_assert(inside::is_bsc_action<std::remove_cvref_t<decltype(count_up)>>);
    static_assert(!inside::is_bsc_guard<std::remove_cvref_t<decltype(reset)>>);
    // The name given as a template argument takes no room.
    constexpr auto lambda = [](ctx const& c) { return c.ready.get(); };
    static_assert(sizeof(bsc::named<"x">(bsc::guard(lambda))) == sizeof(bsc::guard(lambda)));
    static_assert(sizeof(bsc::named<"x">(lambda)) == sizeof(lambda));
    static_assert(bsc::named<"x">(bsc::guard(lambda)).name == "x");
    static_assert(bsc::named<"y">(bsc::named<"x">(bsc::guard(lambda))).name == "y");  // renamed
    static_assert(positive.name == "positive");

    // The composed guards and the sequence run as they would unnamed.
    ctx c{};
    static_assert((ready && !positive)(ctx{bsc::inout<bool>{true}, 0, 0}, go{}));
    static_assert(!(ready && !positive)(ctx{bsc::inout<bool>{true}, 1, 0}, go{}));
    static_assert((below_ten || ready)(ctx{bsc::inout<bool>{false}, 3, 0}, go{}));
    static_assert(!(!ready || positive)(ctx{bsc::inout<bool>{true}, 0, 0}, go{}));
    int raised = 0;
    auto raise = [&](auto const&) {
        ++raised;
        return true;
    };
    c.count = 5;
    (count_up, reset, count_up)(c, go{}, raise);
    CHECK(c.count == 1);
    CHECK(c.resets == 1);
    bsc::seq(reset, count_up, count_up)(c, go{}, raise);
    CHECK(c.count == 2);
    CHECK(c.resets == 2);
    CHECK(raised == 0);

    // And in a machine.
    bsc::machine m{chart, ctx{}};
    CHECK(m.is<a::Idle>());
    CHECK(m.dispatch(go{}) == bsc::outcome::ignored);  // not ready
    m.context().ready.set(true);
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.is<Slot<1>>());
    CHECK(m.context().count == 1);  // count_up, reset, then Work's entry count_up
    CHECK(m.context().resets == 1);
    CHECK(m.dispatch(stop{}) == bsc::outcome::consumed);  // Work + stop / reset, then b::Idle [below_ten]
    CHECK(m.is<a::Idle>());
    CHECK(!m.context().ready.get());  // Slot<1>'s exit action, published at the end of the dispatch
    CHECK(m.context().count == 0);
    CHECK(m.context().resets == 2);
}

TEST_CASE("named guards and actions appear by name; unnamed ones as guard and action") {
    using namespace export_test;
    auto const mermaid = bsc::to_mermaid(chart);
    CAPTURE(mermaid);
    CHECK(has(mermaid, "    a_Idle --> Work : go [ready && !positive] / count_up, reset\n"));
    CHECK(has(mermaid, "    a_Idle --> Done : stop\n"));
    CHECK(has(mermaid, "    b_Idle --> a_Idle : [guard || ready]\n"));
    CHECK(has(mermaid, "    Slot_1 --> Slot_2 : after(1500ms)\n"));
    CHECK(has(mermaid, "    L1 --> L2 : tick [positive]\n"));
    CHECK(has(mermaid, "    Work --> b_Idle : stop / reset\n"));
    // Activities: entry and exit actions and internal transitions under the state's name; a
    // composite's in its title. History in the title too.
    CHECK(has(mermaid, "state \"Work [H]<br/>entry / count_up\" as Work {\n"));
    CHECK(has(mermaid, "state \"Slot&lt;1&gt;\" as Slot_1\n"));
    CHECK(has(mermaid, "Slot_1 : exit / action\n"));
    CHECK(has(mermaid, "Slot_2 : tick / count_up\n"));
    CHECK(has(mermaid, "Done --> [*]\n"));
    // A parallel state's regions are separated by --; a composite starts with its initial state.
    CHECK(has(mermaid, "state \"Both\" as Both {\n"));
    CHECK(has(mermaid, "[*] --> L1\n"));
    CHECK(count(mermaid, "        --\n") == 1);
    // Unguarded, actionless eventless transitions have no label; a guard with no named part is [guard].
    CHECK(inside::guard_label(bsc::guard([] { return true; })) == "guard");
    CHECK(inside::guard_label(!below_ten && below_ten) == "guard");
    CHECK(inside::guard_label((ready || positive) && !(ready && positive)) ==
          "(ready || positive) && !(ready && positive)");
    CHECK(inside::action_label(bsc::seq([] {}, [] {})) == "action");
    CHECK(inside::action_label(bsc::named<"boot">(bsc::seq([] {}, [] {}))) == "boot");
}

TEST_CASE("state identifiers are valid in every format and unique") {
    using inside::identifier;
    CHECK(identifier("Slot<1>") == "Slot_1");
    CHECK(identifier("Pair<ns::A, 2>") == "Pair_ns_A_2");
    CHECK(identifier("3rd") == "s_3rd");
    CHECK(identifier("end") == "end_");
    CHECK(identifier("state") == "state_");
    CHECK(identifier("<>") == "unnamed");
    // Two states with one unqualified name are told apart by their enclosing scopes.
    auto const names = inside::unique_names({"Idle", "Idle", "Busy", "A_B", "A<B>"},
                                            {"x::a::Idle", "x::b::Idle", "x::Busy", "A_B", "A<B>"});
    CHECK(names == std::vector<std::string>{"a::Idle", "b::Idle", "Busy", "A_B", "A<B>"});
    CHECK(inside::unique_identifiers(names) == std::vector<std::string>{"a_Idle", "b_Idle", "Busy", "A_B", "A_B_4"});
    // A name that looks like a suffixed id does not make two states share one.
    CHECK(inside::unique_identifiers({"A_B_2", "A_B", "A<B>"}) == std::vector<std::string>{"A_B_2", "A_B", "A_B_2_2"});
    CHECK(inside::last_scopes("n::Pair<n::A, n::B>", 1) == "Pair<n::A, n::B>");
    CHECK(inside::last_scopes("m::n::Pair<n::A>", 2) == "n::Pair<n::A>");
}

TEST_CASE("Graphviz: clusters, regions as dashed clusters, edges to and from clusters") {
    using namespace export_test;
    auto const dot = bsc::to_dot(chart);
    CAPTURE(dot);
    CHECK(has(dot, "compound=true; nodesep=0.6; ranksep=0.8; forcelabels=true;"));
    CHECK(has(dot, "subgraph \"cluster_Work\" {\n"));
    CHECK(has(dot, "label=\"Work\\nentry / count_up\"; style=\"rounded\";"));
    CHECK(has(dot, "subgraph \"cluster_Left\" {\n"));
    CHECK(has(dot, "label=\"Left\"; style=\"rounded,dashed\";"));  // a region
    CHECK(has(dot, "subgraph \"cluster_region_Right\" {\n"));      // a basic region
    CHECK(has(dot, "\"Work:history\" [shape=circle, label=\"H\""));
    CHECK(has(dot, "\"Done\" [label=\"Done\", peripheries=2];"));
    CHECK(has(dot, "\"Slot_1\" [label=\"Slot<1>\\nexit / action\"];"));
    CHECK(has(dot, "\"Root:initial\" -> \"a_Idle\";"));
    CHECK(has(dot, "\"Work:initial\" -> \"Slot_1\";"));
    // Labels padded so that neighbouring ones never run together; an edge clipped at a
    // cluster's border is tied to its label.
    CHECK(has(dot,
              "\"a_Idle\" -> \"Work:anchor\" [label=\"  go [ready && !positive] / count_up, reset  \", "
              "lhead=\"cluster_Work\", decorate=true];"));
    CHECK(
        has(dot, "\"Work:anchor\" -> \"b_Idle\" [label=\"  stop / reset  \", ltail=\"cluster_Work\", decorate=true];"));
    CHECK(has(dot, "\"b_Idle\" -> \"a_Idle\" [label=\"  [guard || ready]  \"];"));
}

TEST_CASE("PlantUML: nested states, regions, history, final states") {
    using namespace export_test;
    auto const puml = bsc::to_plantuml(chart);
    CAPTURE(puml);
    CHECK(has(puml, "hide empty description\n[*] --> Root\nstate \"Root\" as Root {\n    [*] --> a_Idle\n"));
    CHECK(has(puml, "    state \"Work [H]\" as Work {\n        [*] --> Slot_1\n"));
    CHECK(has(puml, "    Work : entry / count_up\n"));
    CHECK(has(puml, "            --\n"));
    CHECK(has(puml, "    Done --> [*]\n"));
    CHECK(has(puml, "\nSlot_1 --> Slot_2 : after(1500ms)\n"));
}

TEST_CASE("SCXML: states, history with its default, eventless, timeout and internal transitions") {
    using namespace export_test;
    auto const scxml = bsc::to_scxml(chart);
    CAPTURE(scxml);
    CHECK(scxml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"));
    CHECK(has(scxml, "<state id=\"Root\" initial=\"a_Idle\">"));
    CHECK(has(scxml,
              "<transition event=\"go\" cond=\"ready &amp;&amp; !positive\" target=\"Work\">\n"
              "                <script>/* count_up, reset */</script>\n"
              "            </transition>"));
    CHECK(has(scxml, "<transition cond=\"guard || ready\" target=\"a_Idle\"/>"));  // eventless
    CHECK(has(scxml,
              "<state id=\"Work\">\n"
              "            <initial>\n"
              "                <transition target=\"Work_history\"/>\n"
              "            </initial>\n"
              "            <history id=\"Work_history\" type=\"shallow\">\n"
              "                <transition target=\"Slot_1\"/>\n"
              "            </history>\n"
              "            <onentry><script>/* count_up */</script></onentry>\n"));
    CHECK(has(scxml,
              "<!-- after(1500ms): a timeout, enabled once Slot&lt;1&gt; has been active for 1500ms -->\n"
              "                <transition event=\"after(1500ms)\" target=\"Slot_2\"/>"));
    CHECK(has(scxml, "<onexit><script>/* action */</script></onexit>"));
    CHECK(has(scxml, "<transition event=\"tick\" type=\"internal\">"));
    CHECK(has(scxml, "<parallel id=\"Both\">"));
    CHECK(has(scxml, "<final id=\"Done\"/>"));
}

TEST_CASE("exports of the examples: every state and transition, and the structure") {
    SUBCASE("MCS") {
        check_example(mcs::chart);
        auto const mermaid = bsc::to_mermaid(mcs::chart);
        CHECK(has(mermaid, "    Off --> On : ON_P\n"));
        CHECK(has(mermaid, "    Estop --> Off : OFF_P [cond]\n"));
        CHECK(has(mermaid, "    On --> Estop : ESTOP_P / Set_Error1\n"));
        CHECK(has(mermaid, "state \"On [H*]<br/>entry / Show<br/>exit / Show\" as On {\n"));
        CHECK(has(mermaid, "[*] --> Auto\n"));
        auto const scxml = bsc::to_scxml(mcs::chart);
        CHECK(has(scxml, "<history id=\"On_history\" type=\"deep\">\n"));
        CHECK(has(scxml, "<transition event=\"RESET_P\" target=\"Estop\">"));
        CHECK(has(scxml, "<transition event=\"OFF_P\" cond=\"cond\" target=\"Off\"/>"));
        CHECK(has(scxml, "<script>/* Set_Error0 */</script>"));
        CHECK(has(scxml, "<onentry><script>/* Show */</script></onentry>"));
    }
    SUBCASE("manufacturing cell") {
        check_example(cell::chart);
        auto const mermaid = bsc::to_mermaid(cell::chart);
        CHECK(count(mermaid, "        --\n") == 4);  // five regions
        CHECK(has(mermaid, "    BeltOff --> BeltOn : [g1] / BeltOn\n"));
        CHECK(has(mermaid, "    DrillOff --> DrillOn : [g4] / DrillOn & tm1On\n"));
        CHECK(has(mermaid, "    CylinderReturned --> CylinderAdvancing : [g13] / ValveOn\n"));
        CHECK(has(mermaid, "    BeltDone --> BeltOff : [!E1]\n"));
        CHECK(has(mermaid, "DrillOff : [g6] / E2\n"));  // an internal transition
        auto const dot = bsc::to_dot(cell::chart);
        CHECK(count(dot, "style=\"rounded,dashed\"") == 5);
        CHECK(has(dot, "\"CylinderReturned\" -> \"CylinderAdvancing\" [label=\"  [g13] / ValveOn  \"]"));
        auto const scxml = bsc::to_scxml(cell::chart);
        CHECK(has(scxml, "<parallel id=\"Cell\">"));
        CHECK(has(scxml, "<transition cond=\"g13\" target=\"CylinderAdvancing\">"));
        CHECK(has(scxml, "<script>/* DrillOn &amp; tm1On */</script>"));
        CHECK(has(bsc::to_plantuml(cell::chart), "CylinderReturned --> CylinderAdvancing : [g13] / ValveOn\n"));
    }
    SUBCASE("production cell actors") {
        check_example(pcell::feed_belt_chart);
        check_example(pcell::table_chart);
        check_example(pcell::robot_chart);
        check_example(pcell::press_chart);
        check_example(pcell::deposit_belt_chart);
        auto const robot = bsc::to_mermaid(pcell::robot_chart);
        CHECK(has(robot, "    A1Grip --> A1Lift : after(300ms)\n"));
        CHECK(has(robot, "state \"On [H*]<br/>exit / turn=stop, arm1=stop, arm2=stop\" as On {\n"));
        CHECK(has(robot, "    TuIdle --> TuTurn : [arm2_full && belt_ready] / task=deposit, target=arm2_to_belt\n"));
        CHECK(has(bsc::to_mermaid(pcell::feed_belt_chart), "FbFed : entry / motor=0, fed=1\n"));
        CHECK(has(bsc::to_mermaid(pcell::press_chart),
                  "    PsWaitLoad --> PsForge : [loaded && load_ready && arm1_ext == 0] / load_ready=0\n"));
        CHECK(has(bsc::to_mermaid(pcell::press_chart_variant<false>),
                  "    PsWaitLoad --> PsForge : [loaded && load_ready] / load_ready=0\n"));
        auto const deposit = bsc::to_scxml(pcell::deposit_belt_chart);
        CHECK(has(deposit, "event=\"after("));
        CHECK(has(deposit, "cond=\"!dropped\""));
    }
    SUBCASE("ECA cell main") {
        check_example(eca::main_chart);
        check_example(eca::extended_main_chart);
        auto const mermaid = bsc::to_mermaid(eca::main_chart);
        CHECK(has(mermaid, "    Idle --> QueryRobotOnPress : press\n"));
        CHECK(has(mermaid, "    QueryRobotOnPress --> Idle : [Robot?Idle] / set_pressed, set_busy, start, light_on\n"));
        CHECK(has(mermaid, "    QueryRobotOnPress --> Idle : [Robot?Busy] / set_pressed\n"));
        auto const extended = bsc::to_scxml(eca::extended_main_chart);
        CHECK(has(extended, "<transition event=\"continue\""));
        CHECK(has(extended, "<transition cond=\"Pause?Paused\" target=\"Idle\">"));
    }
    SUBCASE("every guard and action of the examples has a name") {
        // An unnamed guard or action is drawn as "guard" or "action" (alone or in a composition).
        auto const placeholders = [](std::string const& text) {
            return count(text, "[guard]") + count(text, "guard &&") + count(text, "&& guard") +
                   count(text, "guard ||") + count(text, "|| guard") + count(text, "/ action") +
                   count(text, "action,") + count(text, ", action");
        };
        auto const check_named = [&](auto const& chart) {
            CHECK(placeholders(bsc::to_mermaid(chart)) == 0);
            CHECK(placeholders(bsc::to_plantuml(chart)) == 0);
        };
        check_named(mcs::chart);
        check_named(cell::chart);
        check_named(eca::main_chart);
        check_named(eca::extended_main_chart);
        check_named(pcell::feed_belt_chart);
        check_named(pcell::table_chart);
        check_named(pcell::robot_chart);
        check_named(pcell::press_chart);
        check_named(pcell::deposit_belt_chart);
    }
}

// The text of a row that make_chart's errors carry (bsc::error::as_written): the same names as
// the exports, computed at compile time from the row's type.
namespace row_text_test {
struct go {};
struct Idle;
struct Busy;
struct ctx {
    int x = 0;
};
inline constexpr auto ready = bsc::named<"ready">(bsc::guard([](ctx const& c) { return c.x > 0; }));
inline constexpr auto hot = bsc::named<"hot">([](ctx const& c) { return c.x > 5; });
inline constexpr auto cold = bsc::guard([](ctx const& c) { return c.x < 0; });
inline constexpr auto start = bsc::named<"start">(bsc::action([](ctx& c) { c.x = 1; }));
inline constexpr auto stop = bsc::named<"stop">([](ctx& c) { c.x = 0; });

// row_text<Row>() is a prvalue: keep it in a variable template so that its view stays valid.
template <class Row>
inline constexpr auto kept = inside::row_text<Row>();
template <class Row>
constexpr std::string_view kept_text(Row const&) {
    return kept<Row>.view();
}
}  // namespace row_text_test

TEST_CASE("a row's text as errors show it: names, composed guards, sequences, timeouts, entry and exit") {
    using namespace row_text_test;
    CHECK(kept_text(bsc::state<Idle> + bsc::event<go> = bsc::state<Busy>) == "Idle + go = Busy");
    CHECK(kept_text(bsc::state<Idle> + bsc::event<go>[ready] / start = bsc::state<Busy>) ==
          "Idle + go [ready] / start = Busy");
    CHECK(kept_text(bsc::state<Idle> + bsc::event<go>[!(ready || hot) && cold] / (start, bsc::action(stop))) ==
          "Idle + go [!(ready || hot) && guard] / (start, stop)");
    CHECK(kept_text(bsc::state<Idle> + bsc::event<go>[ready && (hot || !cold)] = bsc::state<Busy>) ==
          "Idle + go [ready && (hot || !guard)] = Busy");
    CHECK(kept_text(bsc::state<Busy> + bsc::after(std::chrono::seconds(3)) / [](ctx&) {}) ==
          "Busy + after(...) / action");
    CHECK(kept_text(bsc::state<Busy>[hot] = bsc::state<Idle>) == "Busy [hot] = Idle");
    CHECK(kept_text(bsc::state<Idle> + bsc::on_entry / start) == "Idle + on_entry / start");
    CHECK(kept_text(bsc::state<Idle> + bsc::on_exit / stop) == "Idle + on_exit / stop");
    CHECK(kept_text(bsc::state<Idle> + bsc::on_exit / [](ctx&) {}) == "Idle + on_exit / action");
}
