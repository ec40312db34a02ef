// Each test case pins down one sentence of docs/semantics.md (quoted in the case name), and
// runs against both back ends: the compiled bsc::machine and the table-driven
// bsc::table::machine.

#include <doctest/doctest.h>

#include <cstddef>
#include <string>

#include "backends.hpp"
#include "inside.hpp"
#include "trace.hpp"

using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;
using bsc_test::trace_observer;

namespace sem {
struct go {};
struct back {};
struct tick {};
struct ping {};
struct pong {};
struct A;
struct A1;
struct A2;
struct B;
struct B1;
struct B2;
struct Root;
struct ctx {
    int value = 0;
    bool flag = false;
    std::string log;
    bsc::input<bool> ready;  // the environment's: set between dispatches
};
inline constexpr auto log = bsc_test::log_action<ctx>;

// What a machine's chart logged after the first `mark` characters of its log, without the space
// that separates it from what came before (the log is the chart's: the test reads it, and
// marks where the part it checks begins).
template <class Machine>
std::string logged_since(Machine const& m, std::size_t mark) {
    std::string const& log = m.context().log;
    return log.substr(mark > 0 && mark < log.size() && log[mark] == ' ' ? mark + 1 : mark);
}
}  // namespace sem

using namespace sem;

TEST_CASE_TEMPLATE("a transition exits innermost first, runs its action, then enters outermost first", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::composite<A1>(bsc::initial<A2>)),
                             bsc::composite<B>(bsc::initial<B1>, bsc::composite<B1>(bsc::initial<B2>))),
        bsc::state<A2> + bsc::event<go> / log("action") = bsc::state<B>,
        bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<A> + bsc::on_exit / log("exit A"),
        bsc::state<A1> + bsc::on_exit / log("exit A1"), bsc::state<A2> + bsc::on_exit / log("exit A2"),
        bsc::state<B> + bsc::on_entry / log("enter B"), bsc::state<B1> + bsc::on_entry / log("enter B1"),
        bsc::state<B2> + bsc::on_entry / log("enter B2"));
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.active_states().joined() == "Root A A1 A2");
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "exit A2 exit A1 exit A action enter B enter B1 enter B2");
    CHECK(m.active_states().joined() == "Root B B1 B2");
}

namespace sem {
struct B3;
}  // namespace sem

TEST_CASE_TEMPLATE(
    "states with nothing to do on entry or exit are passed over, and the others on the path run in order", Backend,
    compiled, table) {
    // Quiet and acting states alternate on every path, so that a state passed over in the
    // middle of a path neither stops the path nor loses its byte.
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::composite<A1>(bsc::initial<A2>)),
                             bsc::composite<B>(bsc::initial<B1>, bsc::composite<B1>(bsc::initial<B2>), bsc::state<B3>)),
        bsc::state<A2> + bsc::event<go> / log("action") = bsc::state<B2>,
        bsc::state<B2> + bsc::event<back> = bsc::state<A>, bsc::state<B> + bsc::event<tick> = bsc::state<B3>,
        bsc::state<B3> + bsc::event<ping> = bsc::state<B1>, bsc::state<A> + bsc::on_exit / log("exit A"),
        bsc::state<A2> + bsc::on_exit / log("exit A2"), bsc::state<B1> + bsc::on_entry / log("enter B1"),
        bsc::state<B3> + bsc::on_entry / log("enter B3"));
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.active_states().joined() == "Root A A1 A2");
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "exit A2 exit A action enter B1");
    CHECK(m.active_states().joined() == "Root B B1 B2");
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);  // nothing on the way out or in
    CHECK(m.context().log == "exit A2 exit A action enter B1");
    CHECK(m.active_states().joined() == "Root A A1 A2");
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(tick{}) == bsc::outcome::consumed);  // B2 and B1 exit quietly
    CHECK(m.context().log == "exit A2 exit A action enter B1 exit A2 exit A action enter B1 enter B3");
    CHECK(m.active_states().joined() == "Root B B3");
    CHECK(m.dispatch(ping{}) == bsc::outcome::consumed);  // B1's default child, entered quietly
    CHECK(m.active_states().joined() == "Root B B1 B2");

    // An observer sees every state, quiet or not.
    std::string trace;
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> observed{chart, ctx{},
                                                                                      trace_observer{&trace}};
    CHECK(trace == "+Root +A +A1 +A2");
    trace.clear();
    CHECK(observed.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(trace == "-A2 -A1 -A A2>B2 +B +B1 +B2");
}

TEST_CASE_TEMPLATE(
    "a composite's transition exits its active descendants, innermost first, whichever of them is active", Backend,
    compiled, table) {
    // The two charts differ by one exit action two levels below the source: without it, the
    // compiled back end does not look below the source at all (docs/design.md, "Dispatch").
    static constexpr auto common = bsc::rows(
        bsc::state<A2> + bsc::event<tick> = bsc::state<B3>, bsc::state<B3> + bsc::event<tick> = bsc::state<A2>,
        bsc::state<A> + bsc::event<go> / log("go") = bsc::state<B>, bsc::state<B> + bsc::event<back> = bsc::state<A>,
        bsc::state<A> + bsc::on_exit / log("exit A"));
    static constexpr auto tree = bsc::composite<Root>(
        bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::composite<A1>(bsc::initial<A2>, bsc::state<B3>)),
        bsc::state<B>);
    static constexpr auto quiet = bsc::make_chart<ctx>(tree, common);
    static constexpr auto acting = bsc::make_chart<ctx>(tree, common, bsc::state<B3> + bsc::on_exit / log("exit B3"));

    machine_t<Backend, decltype(quiet)> q{quiet, ctx{}};
    CHECK(q.dispatch(tick{}) == bsc::outcome::consumed);
    CHECK(q.active_states().joined() == "Root A A1 B3");
    CHECK(q.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(q.context().log == "exit A go");
    CHECK(q.active_states().joined() == "Root B");
    CHECK(q.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(q.active_states().joined() == "Root A A1 A2");

    machine_t<Backend, decltype(acting)> a{acting, ctx{}};
    CHECK(a.dispatch(tick{}) == bsc::outcome::consumed);
    CHECK(a.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(a.context().log == "exit B3 exit A go");
    CHECK(a.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(a.dispatch(go{}) == bsc::outcome::consumed);  // from A2, which has nothing to do on exit
    CHECK(a.context().log == "exit B3 exit A go exit A go");
    CHECK(a.active_states().joined() == "Root B");
}

namespace sem {
struct C;
struct C1;
struct C2;
struct D;
}  // namespace sem

TEST_CASE_TEMPLATE("the deepest source wins; among equals, the first enabled in declaration order", Backend, compiled,
                   table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>), bsc::state<B>,
                             bsc::state<C>),
        bsc::state<A> + bsc::event<go> = bsc::state<B>,  // ancestor
        bsc::state<A1> + bsc::event<go>[([](ctx const& c) { return c.value == 1; })] = bsc::state<C>,
        bsc::state<A1> + bsc::event<go>[([](ctx const& c) { return c.value >= 1; })] = bsc::state<A2>,
        bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<C> + bsc::event<back> = bsc::state<A>,
        bsc::state<A2> + bsc::event<back> = bsc::state<A1>);
    SUBCASE("no guard of the leaf holds: the ancestor's transition fires") {
        machine_t<Backend, decltype(chart)> m{chart, ctx{}};
        m.dispatch(go{});
        CHECK(m.template is<B>());
    }
    SUBCASE("both leaf guards hold: the first declared fires") {
        machine_t<Backend, decltype(chart)> m{chart, ctx{1, false, {}, {}}};
        m.dispatch(go{});
        CHECK(m.template is<C>());
    }
    SUBCASE("only the second leaf guard holds: it fires, not the ancestor's") {
        machine_t<Backend, decltype(chart)> m{chart, ctx{2, false, {}, {}}};
        m.dispatch(go{});
        CHECK(m.template is<A2>());
    }
}

TEST_CASE_TEMPLATE("an event that enables no transition is ignored and changes nothing", Backend, compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A> + bsc::event<go>[([](ctx const& c) { return c.ready.get(); })] = bsc::state<B>,
        bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    auto const before = m.active_configuration();
    CHECK(m.dispatch(go{}) == bsc::outcome::ignored);
    CHECK(m.dispatch(back{}) == bsc::outcome::ignored);
    CHECK(m.active_configuration() == before);
    m.context().ready.set(true);
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.template is<B>());
}

TEST_CASE_TEMPLATE("the transition domain: siblings keep their parent, self and ancestor/descendant targets re-enter",
                   Backend, compiled, table) {
    std::string trace;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>), bsc::state<B>),
        bsc::state<A1> + bsc::event<go> = bsc::state<A2>,   // siblings: A stays
        bsc::state<A2> + bsc::event<go> = bsc::state<A2>,   // external self-transition
        bsc::state<A2> + bsc::event<back> = bsc::state<A>,  // to an ancestor: A re-entered
        bsc::state<A> + bsc::event<tick> = bsc::state<A2>,  // to a descendant: A re-entered
        bsc::state<A> + bsc::event<ping> = bsc::state<B>, bsc::state<B> + bsc::event<ping> = bsc::state<A>);
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> m{chart, ctx{}, trace_observer{&trace}};
    trace.clear();
    m.dispatch(go{});
    CHECK(trace == "-A1 A1>A2 +A2");
    trace.clear();
    m.dispatch(go{});
    CHECK(trace == "-A2 A2>A2 +A2");
    trace.clear();
    m.dispatch(back{});
    CHECK(trace == "-A2 -A A2>A +A +A1");
    trace.clear();
    m.dispatch(tick{});
    CHECK(trace == "-A1 -A A>A2 +A +A2");
}

TEST_CASE_TEMPLATE("an internal transition (no target) runs its action and exits and enters nothing", Backend, compiled,
                   table) {
    std::string trace;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>)),
        bsc::state<A> + bsc::event<go> / [](ctx& c) { ++c.value; }, bsc::state<A1> + bsc::event<back> = bsc::state<A2>,
        bsc::state<A2> + bsc::event<back> = bsc::state<A1>);
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> m{chart, ctx{}, trace_observer{&trace}};
    trace.clear();
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(trace == "A>internal");
    CHECK(m.context().value == 1);
    CHECK(m.active_states().joined() == "Root A A1");
}

TEST_CASE_TEMPLATE("shallow history restores the last active child; its own children take their defaults", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>,
                             bsc::composite<A>(bsc::shallow_history, bsc::initial<A1>,
                                               bsc::composite<A1>(bsc::initial<C1>, bsc::state<C2>), bsc::state<A2>),
                             bsc::state<B>),
        bsc::state<C1> + bsc::event<tick> = bsc::state<C2>, bsc::state<C2> + bsc::event<tick> = bsc::state<C1>,
        bsc::state<A1> + bsc::event<ping> = bsc::state<A2>, bsc::state<A2> + bsc::event<ping> = bsc::state<A1>,
        bsc::state<A> + bsc::event<go> = bsc::state<B>, bsc::state<B> + bsc::event<back> = bsc::state<A>,
        bsc::state<B> + bsc::event<pong> = bsc::state<C2>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    m.dispatch(tick{});  // A1/C2
    m.dispatch(go{});
    m.dispatch(back{});
    CHECK(m.active_states().joined() == "Root A A1 C1");  // A1 remembered, C default
    m.dispatch(ping{});                                   // A2
    m.dispatch(go{});
    m.dispatch(back{});
    CHECK(m.active_states().joined() == "Root A A2");
    SUBCASE("an explicit target inside the history state wins over history") {
        m.dispatch(go{});
        m.dispatch(pong{});
        CHECK(m.active_states().joined() == "Root A A1 C2");
    }
}

TEST_CASE_TEMPLATE("deep history restores the whole last active sub-configuration", Backend, compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>,
                             bsc::composite<A>(bsc::deep_history, bsc::initial<A1>,
                                               bsc::composite<A1>(bsc::initial<C1>, bsc::state<C2>), bsc::state<A2>),
                             bsc::state<B>),
        bsc::state<C1> + bsc::event<tick> = bsc::state<C2>, bsc::state<C2> + bsc::event<tick> = bsc::state<C1>,
        bsc::state<A1> + bsc::event<ping> = bsc::state<A2>, bsc::state<A2> + bsc::event<ping> = bsc::state<A1>,
        bsc::state<A> + bsc::event<go> = bsc::state<B>, bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.active_states().joined() == "Root A A1 C1");  // never visited: defaults
    m.dispatch(tick{});
    m.dispatch(go{});
    CHECK(m.active_states().joined() == "Root B");
    m.dispatch(back{});
    CHECK(m.active_states().joined() == "Root A A1 C2");
}

namespace sem {
struct P;
struct R1;
struct R2;
struct X1;
struct X2;
struct Y1;
struct Y2;
struct Out;
struct e1 {};
struct e2 {};
}  // namespace sem

TEST_CASE_TEMPLATE("a parallel state: entered region by region, events broadcast to every region", Backend, compiled,
                   table) {
    std::string trace;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<P>,
                             bsc::parallel<P>(bsc::composite<R1>(bsc::initial<X1>, bsc::state<X2>),
                                              bsc::composite<R2>(bsc::initial<Y1>, bsc::state<Y2>)),
                             bsc::state<Out>),
        bsc::state<X1> + bsc::event<go> = bsc::state<X2>, bsc::state<Y1> + bsc::event<go> = bsc::state<Y2>,
        bsc::state<X2> + bsc::event<back> = bsc::state<X1>, bsc::state<Y2> + bsc::event<back> = bsc::state<Y1>,
        bsc::state<P> + bsc::event<tick> = bsc::state<Out>, bsc::state<Out> + bsc::event<tick> = bsc::state<Y2>,
        bsc::state<X2> + bsc::event<ping> / log("x2") = bsc::state<X1>,
        bsc::state<Y2> + bsc::event<ping> / log("y2") = bsc::state<Out>,
        bsc::state<X2> + bsc::event<pong> / log("x2") = bsc::state<Out>,
        bsc::state<Y2> + bsc::event<pong> / log("y2") = bsc::state<Y1>,
        bsc::state<P> + bsc::event<e1> = bsc::state<Out>, bsc::state<Y2> + bsc::event<e1> = bsc::state<Y1>,
        bsc::state<X1> + bsc::event<e2> = bsc::state<X2>, bsc::state<Y2> + bsc::event<e2> / log("y2"));
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> m{chart, ctx{}, trace_observer{&trace}};
    CHECK(trace == "+Root +P +R1 +X1 +R2 +Y1");
    trace.clear();
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    // SCXML microstep: all exits (reverse document order), then actions, then entries.
    CHECK(trace == "-Y1 -X1 X1>X2 Y1>Y2 +X2 +Y2");
    CHECK(m.active_states().joined() == "Root P R1 X2 R2 Y2");

    SUBCASE("a transition of the parallel state itself fires once, whatever the number of regions") {
        trace.clear();
        m.dispatch(tick{});
        CHECK(trace == "-Y2 -R2 -X2 -R1 -P P>Out +Out");
        SUBCASE("entering a region's state enters the other regions by default, in document order") {
            trace.clear();
            m.dispatch(tick{});
            CHECK(trace == "-Out Out>Y2 +P +R1 +X1 +R2 +Y2");
        }
    }
    SUBCASE("conflicting exit sets: the transition selected in the earlier region wins") {
        m.dispatch(ping{});  // X2 -> X1 stays in R1; Y2 -> Out would leave P: dropped
        CHECK(m.active_states().joined() == "Root P R1 X1 R2 Y2");
        CHECK(m.context().log == "x2");
        m.dispatch(go{});
        std::size_t const mark = m.context().log.size();  // what the chart logs from here
        m.dispatch(pong{});                               // X2 -> Out leaves P; Y2 -> Y1 conflicts with it: dropped
        CHECK(m.active_states().joined() == "Root Out");
        CHECK(logged_since(m, mark) == "x2");
    }
    SUBCASE("conflicting exit sets: a later transition from a descendant preempts an ancestor's") {
        trace.clear();
        m.dispatch(e1{});  // P -> Out is selected by X2, but Y2 -> Y1 from inside P preempts it
        CHECK(trace == "-Y2 Y2>Y1 +Y1");
        CHECK(m.active_states().joined() == "Root P R1 X2 R2 Y1");
    }
    SUBCASE("internal transitions have empty exit sets and never conflict") {
        m.dispatch(ping{});
        std::size_t const mark = m.context().log.size();  // what the chart logs from here
        m.dispatch(e2{});                                 // X1 -> X2 and Y2's internal transition both fire
        CHECK(logged_since(m, mark) == "y2");
        CHECK(m.active_states().joined() == "Root P R1 X2 R2 Y2");
    }
}

TEST_CASE_TEMPLATE("guards compose with !, && and ||; actions run in sequence; event data reaches both", Backend,
                   compiled, table) {
    struct number {
        int n;
    };
    struct big;
    static constexpr auto positive = bsc::guard([](ctx const&, number const& e) { return e.n > 0; });
    static constexpr auto even = bsc::guard([](ctx const&, number const& e) { return e.n % 2 == 0; });
    static constexpr auto flagged = bsc::guard([](ctx const& c) { return c.ready.get(); });
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<big>),
        bsc::state<A> + bsc::event<number>[positive && even && !flagged] /
                            (bsc::action([](ctx& c, number const& e) { c.value += e.n; }), log("first"),
                             [](ctx& c) { c.log += " second"; }),
        bsc::state<A> + bsc::event<number>[flagged || !positive] / log("other"),
        bsc::state<A> + bsc::event<go> = bsc::state<big>, bsc::state<big> + bsc::event<go> = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.dispatch(number{3}) == bsc::outcome::ignored);
    CHECK(m.dispatch(number{4}) == bsc::outcome::consumed);
    CHECK(m.context().value == 4);
    CHECK(m.context().log == "first second");
    std::size_t const mark = m.context().log.size();  // what the chart logs from here
    m.context().ready.set(true);
    CHECK(m.dispatch(number{4}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "other");
    CHECK(m.context().value == 4);
}

TEST_CASE_TEMPLATE("guards and actions take the arguments they need", Backend, compiled, table) {
    struct number {
        int n;
    };
    struct S;
    struct T;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<S>, bsc::state<T>),
        bsc::state<S> + bsc::event<number>[([] { return true; })] / [] {},
        bsc::state<S> + bsc::event<number>[([](ctx const& c) { return c.value < 100; })] / [](ctx& c) { c.value += 1; },
        bsc::state<S> + bsc::event<number>[([](ctx const&, number const& e) { return e.n == 5; })] /
                            [](ctx& c, number const& e) { c.value += e.n; },
        bsc::state<S> + bsc::event<go> = bsc::state<T>, bsc::state<T> + bsc::event<go> = bsc::state<S>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.dispatch(number{5}) == bsc::outcome::consumed);  // the first, unguarded-in-effect, wins
    CHECK(m.context().value == 0);
}

namespace sem {
// Rules defined once and reused: two charts share a group of rows.
inline constexpr auto common_rules = bsc::rows(bsc::state<A> + bsc::event<go> = bsc::state<B>,
                                               bsc::rows(bsc::state<B> + bsc::event<back> = bsc::state<A>));
inline constexpr auto base = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<A>, bsc::state<B>), common_rules);
inline constexpr auto extended = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>), common_rules,
    bsc::state<B> + bsc::event<go> / [](ctx& c) { ++c.value; });
}  // namespace sem

TEST_CASE_TEMPLATE("groups of rows (bsc::rows) are flattened into the chart, so rules can be shared", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(sem::base)> b{sem::base, ctx{}};
    machine_t<Backend, decltype(sem::extended)> e{sem::extended, ctx{}};
    b.dispatch(go{});
    e.dispatch(go{});
    CHECK(b.dispatch(go{}) == bsc::outcome::ignored);
    CHECK(e.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(e.context().value == 1);
    CHECK(b.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(b.template is<A>());
}

TEST_CASE_TEMPLATE("rows keep their declaration order through groups and nested groups: the first enabled wins",
                   Backend, compiled, table) {
    struct number {
        int n;
    };
    // Three rows of A on number, each in a group of a different depth; for n = 3 all three hold,
    // for n = 2 the last two, for n = 1 the last one.
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::rows(bsc::state<A> + bsc::event<number>[([](ctx const&, number const& e) { return e.n >= 3; })] /
                                      [](ctx& c) { c.value = c.value * 10 + 3; }),
        bsc::state<A> + bsc::event<number>[([](ctx const&, number const& e) { return e.n >= 2; })] /
                            [](ctx& c) { c.value = c.value * 10 + 2; },
        bsc::rows(bsc::rows(bsc::state<A> + bsc::event<number>[([](ctx const&, number const& e) { return e.n >= 1; })] /
                                                [](ctx& c) { c.value = c.value * 10 + 1; }),
                  bsc::state<A> + bsc::event<back> = bsc::state<B>),
        bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    for (int n : {3, 1, 2, 3, 2, 1}) CHECK(m.dispatch(number{n}) == bsc::outcome::consumed);
    CHECK(m.context().value == 312321);
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(m.template is<B>());
}

TEST_CASE_TEMPLATE("eventless transitions run after each microstep until none is enabled, and at construction", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>, bsc::state<D>),
        bsc::state<A>[([](ctx const& c) { return c.value > 0 || c.ready.get(); })] / log("A>B") = bsc::state<B>,
        bsc::state<B> / log("B>C") = bsc::state<C>,
        bsc::state<C> + bsc::event<go> / [](ctx& c) { c.value = 10; } = bsc::state<D>,
        bsc::state<D>[([](ctx const& c) { return c.value == 10; })] / log("D>A") = bsc::state<A>);
    SUBCASE("at construction") {
        machine_t<Backend, decltype(chart)> m{chart, ctx{1, false, {}, {}}};
        CHECK(m.template is<C>());
        CHECK(m.context().log == "A>B B>C");
    }
    SUBCASE("after an event, the chain runs before dispatch returns") {
        machine_t<Backend, decltype(chart)> m{chart, ctx{0, false, {}, {}}};
        CHECK(m.template is<A>());
        CHECK(m.dispatch(go{}) == bsc::outcome::ignored);
        m.context().ready.set(true);
        CHECK(m.dispatch(go{}) == bsc::outcome::ignored);  // the event fires nothing; A>B>C follow it
        CHECK(m.template is<C>());
        std::size_t const mark = m.context().log.size();  // what the chart logs from here
        CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
        CHECK(logged_since(m, mark) == "D>A A>B B>C");
        CHECK(m.template is<C>());
    }
}

TEST_CASE_TEMPLATE("an eventless transition is also evaluated when the dispatched event fired nothing", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A>[([](ctx const& c) { return c.ready.get(); })] = bsc::state<B>,
        bsc::state<B> + bsc::event<go> = bsc::state<A>, bsc::state<A> + bsc::event<back> / log("back"));
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    m.context().ready.set(true);  // written by the environment between dispatches
    CHECK(m.dispatch(go{}) == bsc::outcome::ignored);
    CHECK(m.template is<B>());
}

TEST_CASE_TEMPLATE("a guarded eventless cycle that stays enabled is stopped and reported as a livelock", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A>[([](ctx const& c) { return c.flag; })] / [](ctx& c) { ++c.value; } = bsc::state<B>,
        bsc::state<B>[([](ctx const& c) { return c.flag; })] / [](ctx& c) { ++c.value; } = bsc::state<A>,
        bsc::state<A> + bsc::event<go> / [](ctx& c) { c.flag = true; });
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::livelock);
    // max_eventless_steps transitions settle normally; the one after them is reported.
    CHECK(m.context().value == static_cast<int>(bsc::default_policy::max_eventless_steps) + 1);
    CHECK(m.last_outcome() == bsc::outcome::livelock);
}

TEST_CASE_TEMPLATE("raised events are queued and processed in order after the current step, before dispatch returns",
                   Backend, compiled, table) {
    std::string trace;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
        bsc::state<A> + bsc::event<go> / (bsc::raise(ping{}), bsc::raise(pong{}), log("go")) = bsc::state<B>,
        bsc::state<B> + bsc::on_entry / log("enter B"), bsc::state<B> + bsc::event<ping> / log("ping") = bsc::state<C>,
        bsc::state<C> + bsc::event<pong> /
                            [](ctx& c, pong const&, auto& raise) {
                                c.log += " pong";
                                raise(back{});
                            },
        bsc::state<C> + bsc::event<back> / log("back") = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "go enter B ping pong back");
    CHECK(m.template is<A>());
    CHECK(inside::queue(m).empty());
}

namespace sem {
struct tiny_queue : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 2;
};
}  // namespace sem

TEST_CASE_TEMPLATE("queue overflow is reported, the extra event is dropped and the rest is processed", Backend,
                   compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A> + bsc::event<go> / (bsc::raise(ping{}), bsc::raise(ping{}), bsc::raise(ping{})),
        bsc::state<A> + bsc::event<ping> / [](ctx& c) { ++c.value; }, bsc::state<A> + bsc::event<back> = bsc::state<B>,
        bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart), tiny_queue> m{chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::queue_overflow);
    CHECK(m.context().value == 2);
    CHECK(m.dispatch(go{}) == bsc::outcome::queue_overflow);
    CHECK(m.context().value == 4);
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);  // the overflow is reported once, not forever
}

TEST_CASE_TEMPLATE("events that keep raising each other are stopped and reported as a livelock", Backend, compiled,
                   table) {
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
        bsc::state<A> + bsc::event<ping> / (bsc::raise(pong{}), bsc::action([](ctx& c) { ++c.value; })),
        bsc::state<A> + bsc::event<pong> / bsc::raise(ping{}), bsc::state<A> + bsc::event<back> = bsc::state<B>,
        bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK(m.dispatch(ping{}) == bsc::outcome::livelock);
    CHECK(inside::queue(m).empty());
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
}

TEST_CASE_TEMPLATE("a final child of the root halts the machine", Backend, compiled, table) {
    static constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<A>, bsc::final_state<B>),
                                                       bsc::state<A> + bsc::event<go> = bsc::state<B>,
                                                       bsc::state<A> + bsc::event<back> / log("back"));
    machine_t<Backend, decltype(chart)> m{chart, ctx{}};
    CHECK_FALSE(m.halted());
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.halted());
    CHECK(m.dispatch(back{}) == bsc::outcome::halted);
    CHECK(m.context().log.empty());
}

TEST_CASE_TEMPLATE("a transition from the root to a descendant exits and re-enters the root", Backend, compiled,
                   table) {
    std::string trace;
    static constexpr auto chart = bsc::make_chart<ctx>(bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
                                                       bsc::state<Root> + bsc::event<go> = bsc::state<B>,
                                                       bsc::state<B> + bsc::event<back> = bsc::state<A>);
    machine_t<Backend, decltype(chart), bsc::default_policy, trace_observer> m{chart, ctx{}, trace_observer{&trace}};
    trace.clear();
    m.dispatch(go{});
    CHECK(trace == "-A -Root Root>B +Root +B");
}
