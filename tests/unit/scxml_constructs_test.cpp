// The constructs of SCXML and UML beyond the core formalism (docs/semantics.md, "Beyond the
// core"): local transitions, event families and bsc::any_event, done events and halting.
// Each case runs against both back ends; the names quote docs/semantics.md.

#include <doctest/doctest.h>

#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <bsc/export.hpp>
#include <bsc/verify.hpp>

#include "backends.hpp"
#include "trace.hpp"

using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;

namespace beyond {
struct go {};
struct back {};
struct restart {};
struct Root;
struct Work;
struct Step1;
struct Step2;
struct Idle;
struct ctx {
    std::string log;
};
inline constexpr auto log = bsc_test::log_action<ctx>;
}  // namespace beyond

using namespace beyond;

// What a machine's chart logged after the first `mark` characters of its log, without the space
// that separates it from what came before (the log is the chart's: the test reads it, and
// marks where the part it checks begins).
template <class Machine>
std::string logged_since(Machine const& m, std::size_t mark) {
    std::string const& log = m.context().log;
    return log.substr(mark > 0 && mark < log.size() && log[mark] == ' ' ? mark + 1 : mark);
}

// ---- local transitions ---------------------------------------------------------------------

namespace beyond {
inline constexpr auto local_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step1>, bsc::state<Step2>)),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Step1> + bsc::event<go> = bsc::state<Step2>,
    bsc::state<Work> + bsc::event<restart> / log("restart") = bsc::local(bsc::state<Step1>),
    bsc::state<Work> + bsc::event<back> / log("back") = bsc::state<Step1>,
    bsc::state<Work> + bsc::on_entry / log("enter Work"), bsc::state<Work> + bsc::on_exit / log("exit Work"),
    bsc::state<Step1> + bsc::on_entry / log("enter Step1"), bsc::state<Step1> + bsc::on_exit / log("exit Step1"),
    bsc::state<Step2> + bsc::on_entry / log("enter Step2"), bsc::state<Step2> + bsc::on_exit / log("exit Step2"),
    bsc::state<Step2> + bsc::event<go> = bsc::state<Idle>);
}  // namespace beyond

TEST_CASE_TEMPLATE("a local transition exits and enters only below its source", Backend, compiled, table) {
    machine_t<Backend, decltype(local_chart)> m{local_chart, ctx{}};
    m.dispatch(go{});
    m.dispatch(go{});
    REQUIRE(m.active_states().joined() == "Root Work Step2");
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    CHECK(m.dispatch(restart{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "exit Step2 restart enter Step1");
    CHECK(m.active_states().joined() == "Root Work Step1");
    m.dispatch(go{});
    mark = m.context().log.size();
    // The same target without bsc::local leaves and re-enters the source (SCXML's external).
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "exit Step2 exit Work back enter Work enter Step1");
}

TEST_CASE("a local transition is drawn as such, and exported as SCXML's type=\"internal\"") {
    auto const scxml = bsc::to_scxml(local_chart);
    CHECK(scxml.find("<transition event=\"restart\" target=\"Step1\" type=\"internal\">") != std::string::npos);
    CHECK(scxml.find("<transition event=\"back\" target=\"Step1\">") != std::string::npos);
    CHECK(bsc::to_mermaid(local_chart).find("Work --> Step1 : restart / action (local)") != std::string::npos);
}

// ---- event families and bsc::any_event -------------------------------------------------------

namespace beyond {
// SCXML's "error", "error.send" and "error.send.failed", as classes.
struct error {};
struct error_send : error {
    int code = 0;
};
struct error_send_failed : error_send {};
struct other {};
struct Fault;
struct Sent;
struct Caught;
inline constexpr auto family_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Sent>, bsc::state<Fault>, bsc::state<Caught>),
    bsc::state<Idle> + bsc::event<error_send>[([](ctx const&, error_send const& e) { return e.code > 0; })] /
                           bsc::action([](ctx& c, error_send const& e) {
                               c.log += "send " + std::to_string(e.code);
                           }) = bsc::state<Sent>,
    bsc::state<Idle> + bsc::event<error> / log("error") = bsc::state<Fault>,
    bsc::state<Idle> + bsc::event<bsc::any_event> / log("any") = bsc::state<Caught>,
    bsc::state<Sent> + bsc::event<go> = bsc::state<Idle>, bsc::state<Fault> + bsc::event<go> = bsc::state<Idle>,
    bsc::state<Caught> + bsc::event<go> = bsc::state<Idle>);
}  // namespace beyond

TEST_CASE_TEMPLATE("a row on an event takes the events derived from it; the first matching row in document order wins",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(family_chart)> m{family_chart, ctx{}};
    error_send_failed failed;  // not named by any row: its families' rows take it
    failed.code = 7;
    CHECK(m.dispatch(failed) == bsc::outcome::consumed);
    CHECK(m.context().log == "send 7");
    CHECK(m.template is<Sent>());
    m.dispatch(go{});
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    failed.code = 0;                            // the first row's guard fails: the row on the family `error` is next
    CHECK(m.dispatch(failed) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "error");
    CHECK(m.template is<Fault>());
    m.dispatch(go{});
    mark = m.context().log.size();
    CHECK(m.dispatch(error{}) == bsc::outcome::consumed);  // not an error_send: the first row is not a candidate
    CHECK(m.template is<Fault>());
    m.dispatch(go{});
    mark = m.context().log.size();
    CHECK(m.dispatch(other{}) == bsc::outcome::consumed);  // only bsc::any_event takes it
    CHECK(logged_since(m, mark) == "any");
    CHECK(m.template is<Caught>());
    // bsc::any_event takes every event, so nothing is unhandled: an event of no row at all too.
    struct stranger {};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(stranger{}) == bsc::outcome::consumed);
    CHECK(m.template is<Caught>());
}

namespace beyond {
struct Outer;
struct Inner;
struct Elsewhere;
inline constexpr auto deepest_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Outer>,
                         bsc::composite<Outer>(bsc::initial<Inner>, bsc::state<Inner>, bsc::state<Elsewhere>),
                         bsc::state<Caught>),
    bsc::state<Outer> + bsc::event<bsc::any_event> / log("outer any") = bsc::state<Caught>,
    bsc::state<Inner> + bsc::event<go> / log("inner go") = bsc::state<Elsewhere>,
    bsc::state<Elsewhere> + bsc::event<back> = bsc::state<Inner>,
    bsc::state<Caught> + bsc::event<back> = bsc::state<Outer>,
    // Raised as error_send_failed, which the chart does not name: queued as error_send.
    bsc::state<Elsewhere> + bsc::event<restart> / bsc::action([](ctx&, restart const&, auto& raise) {
                                error_send_failed e;
                                e.code = 3;
                                raise(e);
                            }),
    bsc::state<Elsewhere> + bsc::event<error_send> / bsc::action([](ctx& c, error_send const& e) {
                                c.log += " raised " + std::to_string(e.code);
                            }) = bsc::state<Inner>);
}  // namespace beyond

TEST_CASE_TEMPLATE("bsc::any_event has the priority of its row: a deeper state's row on the event wins", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(deepest_chart)> m{deepest_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "inner go");
    CHECK(m.template is<Elsewhere>());
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    CHECK(m.dispatch(restart{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "raised 3");
    CHECK(m.template is<Inner>());
    mark = m.context().log.size();
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);  // Inner has no row on back: Outer's any_event row
    CHECK(logged_since(m, mark) == "outer any");
    CHECK(m.template is<Caught>());
}

// ---- done events and halting -----------------------------------------------------------------

namespace beyond {
struct Finished;
struct Next;
inline constexpr auto done_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Work>,
                         bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step1>, bsc::final_state<Finished>),
                         bsc::state<Next>),
    bsc::state<Step1> + bsc::event<go> / log("go") = bsc::state<Finished>,
    bsc::state<Work> + bsc::event<bsc::done<Work>> / log("done Work") = bsc::state<Next>,
    bsc::state<Next> + bsc::event<back> = bsc::state<Work>, bsc::state<Step1> + bsc::on_exit / log("exit Step1"),
    bsc::state<Finished> + bsc::on_entry / log("enter Finished"),
    bsc::state<Finished> + bsc::on_exit / log("exit Finished"), bsc::state<Work> + bsc::on_exit / log("exit Work"),
    bsc::state<Next> + bsc::on_entry / log("enter Next"));
}  // namespace beyond

TEST_CASE_TEMPLATE("entering a final child of a composite raises done for the composite, after the final state's entry",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(done_chart)> m{done_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "exit Step1 go enter Finished exit Finished exit Work done Work enter Next");
    CHECK(m.template is<Next>());
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(m.template is<Step1>());
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.template is<Next>());
}

namespace beyond {
struct a {};
struct b {};
struct P;
struct R1;
struct R2;
struct A1;
struct B1;
struct F1;
struct F2;
inline constexpr auto parallel_done_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<P>,
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A1>, bsc::state<A1>, bsc::final_state<F1>),
                                          bsc::composite<R2>(bsc::initial<B1>, bsc::state<B1>, bsc::final_state<F2>)),
                         bsc::state<Next>),
    bsc::state<A1> + bsc::event<a> = bsc::state<F1>, bsc::state<B1> + bsc::event<b> = bsc::state<F2>,
    bsc::state<R1> + bsc::event<bsc::done<R1>> / log("done R1"),
    bsc::state<R2> + bsc::event<bsc::done<R2>> / log("done R2"),
    bsc::state<P> + bsc::event<bsc::done<P>> / log("done P") = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<P>);
}  // namespace beyond

TEST_CASE_TEMPLATE(
    "when every region of a parallel state is in a final state, done for the parallel state follows the region's",
    Backend, compiled, table) {
    machine_t<Backend, decltype(parallel_done_chart)> m{parallel_done_chart, ctx{}};
    CHECK(m.dispatch(a{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "done R1");
    CHECK(m.template is<F1>());
    CHECK(m.dispatch(b{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "done R1 done R2 done P");
    CHECK(m.template is<Next>());
    // Back in P, the regions start over from their initial states: nothing is complete, and
    // the bytes of the regions (F1, F2 from the last visit) do not count while P is entered.
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark).empty());
    CHECK(m.template is<A1>());
    CHECK(m.template is<B1>());
}

namespace beyond {
struct Q;
struct Q1;
struct Q2;
inline constexpr auto entered_complete_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::parallel<Q>(bsc::composite<Q1>(bsc::initial<F1>, bsc::final_state<F1>),
                                          bsc::composite<Q2>(bsc::initial<F2>, bsc::final_state<F2>)),
                         bsc::state<Next>),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Q>, bsc::state<Q1> + bsc::event<bsc::done<Q1>> / log("done Q1"),
    bsc::state<Q2> + bsc::event<bsc::done<Q2>> / log("done Q2"),
    bsc::state<Q> + bsc::event<bsc::done<Q>> / log("done Q") = bsc::state<Next>,
    bsc::state<Next> + bsc::event<go> = bsc::state<Idle>);
}  // namespace beyond

TEST_CASE_TEMPLATE("a parallel state entered with every region final raises its done once, after its regions'", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(entered_complete_chart)> m{entered_complete_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "done Q1 done Q2 done Q");
    CHECK(m.template is<Next>());
    m.dispatch(go{});
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "done Q1 done Q2 done Q");
}

namespace beyond {
struct End;
inline constexpr auto halting_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Work>, bsc::composite<Work>(bsc::initial<Step1>, bsc::state<Step1>),
                         bsc::final_state<End>),
    bsc::state<Step1> + bsc::event<go> / (bsc::raise(back{}), log("go")) = bsc::state<End>,
    bsc::state<End> + bsc::on_entry / log("enter End"), bsc::state<End> + bsc::on_exit / log("exit End"),
    bsc::state<Work> + bsc::on_exit / log("exit Work"), bsc::state<Step1> + bsc::on_exit / log("exit Step1"),
    bsc::state<Root> + bsc::on_exit / log("exit Root"),
    bsc::state<Work> + bsc::event<back> / log("back") = bsc::state<Work>);
}  // namespace beyond

TEST_CASE_TEMPLATE(
    "reaching a final child of the root runs every active state's exit actions, innermost first, and halts", Backend,
    compiled, table) {
    machine_t<Backend, decltype(halting_chart)> m{halting_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    // The raised `back` is dropped: the machine halted before it was processed (SCXML).
    CHECK(m.context().log == "exit Step1 exit Work go enter End exit End exit Root");
    CHECK(m.halted());
    CHECK(m.dispatch(go{}) == bsc::outcome::halted);
    CHECK(m.context().log == "exit Step1 exit Work go enter End exit End exit Root");
}

// ---- the exports -------------------------------------------------------------------------------

TEST_CASE("done events, any_event and halting are exported as SCXML has them") {
    auto const scxml = bsc::to_scxml(done_chart);
    CHECK(scxml.find("<transition event=\"done.state.Work\" target=\"Next\">") != std::string::npos);
    auto const any = bsc::to_scxml(deepest_chart);
    CHECK(any.find("<transition event=\"*\" target=\"Caught\">") != std::string::npos);
    // SCXML halts only in a final child of <scxml>: the root leaves for one on its done event.
    auto const halting = bsc::to_scxml(halting_chart);
    CHECK(halting.find("<transition event=\"done.state.Root\" target=\"Root_halted\"/>") != std::string::npos);
    CHECK(halting.find("<final id=\"Root_halted\"/>") != std::string::npos);
    CHECK(bsc::to_scxml(local_chart).find("_halted") == std::string::npos);
    CHECK(bsc::to_mermaid(done_chart).find("Work --> Next : done.state.Work") != std::string::npos);
}

// ---- initial transitions: actions and deep targets ---------------------------------------------

namespace beyond {
struct Deep;
struct Mid;
struct Other;
inline constexpr auto initial_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Work>(bsc::initial<Deep>, bsc::state<Step1>,
                             bsc::composite<Mid>(bsc::initial<Other>, bsc::state<Other>, bsc::state<Deep>))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Work>, bsc::state<Work> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<Idle> + bsc::event<restart> = bsc::state<Step1>, bsc::state<Step1> + bsc::event<go> = bsc::state<Other>,
    bsc::state<Other> + bsc::event<go> = bsc::state<Deep>, bsc::state<Deep> + bsc::event<go> = bsc::state<Step1>,
    bsc::state<Step1> + bsc::event<back> = bsc::state<Mid>, bsc::state<Work> + bsc::on_entry / log("enter Work"),
    bsc::state<Work> + bsc::on_initial / log("initial Work"), bsc::state<Mid> + bsc::on_entry / log("enter Mid"),
    bsc::state<Mid> + bsc::on_initial / log("initial Mid"), bsc::state<Deep> + bsc::on_entry / log("enter Deep"),
    bsc::state<Step1> + bsc::on_entry / log("enter Step1"));
}  // namespace beyond

TEST_CASE_TEMPLATE("an initial transition runs its actions after its state's entry, and may target a deeper state",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(initial_chart)> m{initial_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    // Work's initial goes to Deep, inside Mid: Mid is entered on the way, and its own initial
    // transition (to Other) is not taken.
    CHECK(m.context().log == "enter Work initial Work enter Mid enter Deep");
    CHECK(m.active_states().joined() == "Root Work Mid Deep");
    m.dispatch(back{});
    std::size_t mark = m.context().log.size();  // what the chart logs from here
    // A transition to a state inside Work does not take Work's initial transition.
    CHECK(m.dispatch(restart{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "enter Work enter Step1");
    mark = m.context().log.size();
    // Entering Mid as a transition's target takes Mid's initial transition.
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(logged_since(m, mark) == "enter Mid initial Mid");
    CHECK(m.template is<Other>());
}

// ---- history states -----------------------------------------------------------------------------

namespace beyond {
struct resume {};
struct Hs;
struct Hd;
struct Sub;
struct SubA;
struct SubB;
inline constexpr auto history_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Work>(bsc::initial<Step1>, bsc::shallow_history_state<Hs, Sub>,
                             bsc::deep_history_state<Hd, SubB>, bsc::state<Step1>,
                             bsc::composite<Sub>(bsc::initial<SubA>, bsc::state<SubA>, bsc::state<SubB>))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Hs>, bsc::state<Idle> + bsc::event<resume> = bsc::state<Hd>,
    bsc::state<Idle> + bsc::event<restart> = bsc::state<Work>, bsc::state<SubA> + bsc::event<go> = bsc::state<SubB>,
    bsc::state<SubB> + bsc::event<go> = bsc::state<Step1>, bsc::state<Step1> + bsc::event<go> = bsc::state<Sub>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Idle>, bsc::state<Hs> + bsc::on_initial / log("Hs default"),
    bsc::state<Work> + bsc::on_entry / log("enter Work"), bsc::state<Sub> + bsc::on_entry / log("enter Sub"),
    bsc::state<SubA> + bsc::on_entry / log("enter SubA"), bsc::state<SubB> + bsc::on_entry / log("enter SubB"),
    bsc::state<Step1> + bsc::on_entry / log("enter Step1"));
}  // namespace beyond

TEST_CASE_TEMPLATE(
    "a history state restores its composite, or takes its default transition if the composite was never active",
    Backend, compiled, table) {
    SUBCASE("shallow, never active: the default, with its action; then the remembered child, entered by default") {
        machine_t<Backend, decltype(history_chart)> m{history_chart, ctx{}};
        CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
        CHECK(m.context().log == "enter Work Hs default enter Sub enter SubA");
        m.dispatch(go{});  // SubA -> SubB
        m.dispatch(back{});
        std::size_t mark = m.context().log.size();  // what the chart logs from here
        CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
        CHECK(logged_since(m, mark) == "enter Work enter Sub enter SubA");  // shallow: Sub, then Sub's initial
    }
    SUBCASE("deep, never active: the default (deep inside); then the whole remembered configuration") {
        machine_t<Backend, decltype(history_chart)> m{history_chart, ctx{}};
        CHECK(m.dispatch(resume{}) == bsc::outcome::consumed);
        CHECK(m.context().log == "enter Work enter Sub enter SubB");
        m.dispatch(go{});  // SubB -> Step1
        m.dispatch(go{});  // Step1 -> Sub (SubA)
        m.dispatch(go{});  // SubA -> SubB
        m.dispatch(back{});
        std::size_t mark = m.context().log.size();  // what the chart logs from here
        CHECK(m.dispatch(resume{}) == bsc::outcome::consumed);
        CHECK(logged_since(m, mark) == "enter Work enter Sub enter SubB");
        CHECK(m.active_states().joined() == "Root Work Sub SubB");
    }
    SUBCASE("a transition to the composite itself takes its initial state, not its history") {
        machine_t<Backend, decltype(history_chart)> m{history_chart, ctx{}};
        m.dispatch(resume{});
        m.dispatch(back{});
        std::size_t mark = m.context().log.size();  // what the chart logs from here
        CHECK(m.dispatch(restart{}) == bsc::outcome::consumed);
        CHECK(logged_since(m, mark) == "enter Work enter Step1");
        // ... and is remembered: the shallow history now restores Step1.
        m.dispatch(back{});
        mark = m.context().log.size();
        m.dispatch(go{});
        CHECK(logged_since(m, mark) == "enter Work enter Step1");
    }
}

// ---- exploring a chart that uses them ------------------------------------------------------------

// The log shows what ran; it does not change behaviour, so the explorer leaves it out.
template <>
inline constexpr bool bsc::transient<std::string> = true;

TEST_CASE("the explorer covers history states and done events") {
    std::vector<bool> fired(64, false);
    using M = bsc::machine<decltype(history_chart), bsc::default_policy, bsc::verify::row_recorder>;
    bsc::verify::explorer ex{bsc::verify::event_model<M, go, back, resume, restart>{
        M{history_chart, ctx{}, bsc::verify::row_recorder{&fired}}}};
    auto const report = bsc::verify::coverage(ex, fired);
    // Every state but the history states (never active) is reached and every row fires; the
    // explored configurations tell "Work never active" (its byte at Hs) from "Work left in
    // Step1", so the history defaults are taken once per path, not on every entry.
    CHECK(report.dead_states.empty());
    CHECK(report.dead_transitions.empty());
    // Idle with Work never active; SubA, SubB, Step1 (with Sub last in SubA or in SubB); and Idle
    // with Work left in Sub or in Step1, each with Sub's byte, which a deep history state keeps:
    // 1 + 2 + 2 + 4.
    CHECK(ex.count() == 9);

    std::vector<bool> fired_done(64, false);
    using D = bsc::machine<decltype(parallel_done_chart), bsc::default_policy, bsc::verify::row_recorder>;
    bsc::verify::explorer done_ex{
        bsc::verify::event_model<D, a, b, go>{D{parallel_done_chart, ctx{}, bsc::verify::row_recorder{&fired_done}}}};
    auto const done_report = bsc::verify::coverage(done_ex, fired_done);
    CHECK(done_report.dead_states.empty());
    CHECK(done_report.dead_transitions.empty());
}

// ---- deferred events --------------------------------------------------------------------------

namespace beyond {
struct job {
    int n = 0;
};
struct start {};
struct finish {};
struct Busy;
struct Busy2;
inline constexpr auto record_job = bsc::action([](ctx& c, job const& j) {
    if (!c.log.empty()) c.log += ' ';
    c.log += "job " + std::to_string(j.n);
});
inline constexpr auto defer_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Busy>, bsc::state<Busy2>),
    bsc::state<Idle> + bsc::event<start> = bsc::state<Busy>, bsc::state<Idle> + bsc::event<job> / record_job,
    bsc::state<Busy> + bsc::event<job> / bsc::defer, bsc::state<Busy> + bsc::event<go> = bsc::state<Busy2>,
    bsc::state<Busy2> + bsc::event<job>[([](ctx const&, job const& j) { return j.n > 1; })] / bsc::defer,
    bsc::state<Busy2> + bsc::event<job> / record_job, bsc::state<Busy> + bsc::event<finish> = bsc::state<Idle>,
    bsc::state<Busy2> + bsc::event<finish> = bsc::state<Idle>);
}  // namespace beyond

TEST_CASE_TEMPLATE("a deferred event waits, and is dispatched again after the next change of configuration, in order",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(defer_chart)> m{defer_chart, ctx{}};
    m.dispatch(start{});
    CHECK(m.dispatch(job{1}) == bsc::outcome::consumed);
    CHECK(m.dispatch(job{2}) == bsc::outcome::consumed);
    CHECK(m.dispatch(job{3}) == bsc::outcome::consumed);
    CHECK(m.context().log.empty());
    // Busy2 defers only the jobs above 1: job 1 is taken there, 2 and 3 wait on.
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "job 1");
    CHECK(m.dispatch(finish{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "job 1 job 2 job 3");
    CHECK(m.template is<Idle>());
    // Nothing is kept any more.
    m.dispatch(start{});
    m.dispatch(finish{});
    CHECK(m.context().log == "job 1 job 2 job 3");
}

TEST_CASE_TEMPLATE("deferring more events than the policy keeps reports an overflow and drops the newest", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(defer_chart)> m{defer_chart, ctx{}};
    m.dispatch(start{});
    for (int i = 1; i <= static_cast<int>(bsc::default_policy::deferred_capacity); ++i)
        CHECK(m.dispatch(job{i}) == bsc::outcome::consumed);
    CHECK(m.dispatch(job{99}) == bsc::outcome::queue_overflow);
    m.dispatch(finish{});
    CHECK(m.context().log == "job 1 job 2 job 3 job 4 job 5 job 6 job 7 job 8");
}

namespace beyond {
struct Left;
struct Right;
struct L1;
struct L2;
struct R1b;
struct R2b;
struct Par;
inline constexpr auto defer_parallel_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Par>,
        bsc::parallel<Par>(bsc::composite<Left>(bsc::initial<L1>, bsc::state<L1>, bsc::state<L2>),
                           bsc::composite<Right>(bsc::initial<R1b>, bsc::state<R1b>, bsc::state<R2b>))),
    bsc::state<L1> + bsc::event<job> / bsc::defer, bsc::state<L1> + bsc::event<go> = bsc::state<L2>,
    bsc::state<L2> + bsc::event<job> / record_job, bsc::state<L2> + bsc::event<back> = bsc::state<L1>,
    bsc::state<R1b> + bsc::event<job>[([](ctx const&, job const& j) { return j.n == 7; })] = bsc::state<R2b>,
    bsc::state<R2b> + bsc::event<back> = bsc::state<R1b>);
}  // namespace beyond

TEST_CASE_TEMPLATE("an event another region takes with a transition is not deferred", Backend, compiled, table) {
    machine_t<Backend, decltype(defer_parallel_chart)> m{defer_parallel_chart, ctx{}};
    CHECK(m.dispatch(job{7}) == bsc::outcome::consumed);  // Right takes it: L1's deferral does not keep it
    CHECK(m.template is<R2b>());
    CHECK(m.dispatch(job{5}) == bsc::outcome::consumed);  // only L1 takes it: kept
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);    // L1 -> L2 releases it
    CHECK(m.context().log == "job 5");
}

TEST_CASE("a deferring row is drawn with / defer, and is a comment in SCXML, which has no deferral") {
    CHECK(bsc::to_mermaid(defer_chart).find("Busy : job / defer") != std::string::npos);
    CHECK(
        bsc::to_scxml(defer_chart).find("<!-- job / defer: the event is deferred (UML), which SCXML cannot say -->") !=
        std::string::npos);
}

// ---- delayed events to self ------------------------------------------------------------------

namespace beyond {
struct tick {};
struct start_again {};
struct Wait;
struct Rang;
inline constexpr auto delayed_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Wait>, bsc::state<Rang>),
    bsc::state<Idle> + bsc::event<start> / bsc::raise_after(std::chrono::seconds{2}, tick{}, 1) = bsc::state<Wait>,
    bsc::state<Idle> + bsc::event<start_again> / bsc::raise_after(std::chrono::seconds{1}, tick{}) = bsc::state<Wait>,
    bsc::state<Wait> + bsc::event<tick> / log("tick") = bsc::state<Rang>,
    bsc::state<Wait> + bsc::event<finish> / bsc::cancel_delayed(1) = bsc::state<Idle>,
    bsc::state<Wait> + bsc::event<back> = bsc::state<Idle>, bsc::state<Rang> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<Idle> + bsc::event<tick> / log("late tick"));
}  // namespace beyond

TEST_CASE_TEMPLATE("a delayed event comes due in the first cycle at or after its delay, and can be cancelled by its id",
                   Backend, compiled, table) {
    using namespace std::chrono_literals;
    SUBCASE("delivered by step(now), after the delay from the clock of the run that sent it") {
        machine_t<Backend, decltype(delayed_chart)> m{delayed_chart, ctx{}};
        m.step(10s);
        CHECK(m.dispatch(start{}) == bsc::outcome::consumed);
        m.step(11s);
        CHECK(m.template is<Wait>());
        CHECK(m.step(12s).status == bsc::outcome::ignored);  // the tick's microstep is a raised event's
        CHECK(m.context().log == "tick");
        CHECK(m.template is<Rang>());
    }
    SUBCASE("cancelled while pending: never delivered") {
        machine_t<Backend, decltype(delayed_chart)> m{delayed_chart, ctx{}};
        m.step(0s);
        m.dispatch(start{});
        m.dispatch(finish{});
        m.step(5s);
        CHECK(m.context().log.empty());
        CHECK(m.template is<Idle>());
    }
    SUBCASE("not tied to the state that sent it: leaving it does not cancel it") {
        machine_t<Backend, decltype(delayed_chart)> m{delayed_chart, ctx{}};
        m.step(0s);
        m.dispatch(start_again{});
        m.dispatch(back{});
        m.step(1s);
        CHECK(m.context().log == "late tick");
    }
    SUBCASE("sent before the first cycle: counted from the first cycle, as timeouts are") {
        machine_t<Backend, decltype(delayed_chart)> m{delayed_chart, ctx{}};
        m.dispatch(start{});
        m.step(100s);
        m.step(101s);
        CHECK(m.template is<Wait>());
        m.step(102s);
        CHECK(m.template is<Rang>());
    }
    SUBCASE("more pending events than the policy keeps: an overflow, and the newest dropped") {
        machine_t<Backend, decltype(delayed_chart)> m{delayed_chart, ctx{}};
        m.step(0s);
        for (std::size_t i = 0; i < bsc::default_policy::delayed_capacity; ++i) {
            CHECK(m.dispatch(start_again{}) == bsc::outcome::consumed);
            m.dispatch(back{});
        }
        CHECK(m.dispatch(start_again{}) == bsc::outcome::queue_overflow);
        m.dispatch(back{});
        m.step(1s);  // eight ticks come due in Idle
        CHECK(m.context().log == "late tick late tick late tick late tick late tick late tick late tick late tick");
    }
}

namespace beyond {
// A delay near bsc::duration::max(): from a clock far from zero, due past the end of time.
inline constexpr auto far_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>, bsc::state<Wait>, bsc::state<Rang>),
    bsc::state<Idle> + bsc::event<start> / bsc::raise_after(bsc::duration::max() - std::chrono::seconds{5}, tick{},
                                                            1) = bsc::state<Wait>,
    bsc::state<Idle> + bsc::event<start_again> / bsc::raise_after(std::chrono::seconds{1}, tick{}) = bsc::state<Wait>,
    bsc::state<Wait> + bsc::event<tick> / log("tick") = bsc::state<Rang>,
    bsc::state<Wait> + bsc::event<back> = bsc::state<Idle>, bsc::state<Rang> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<Idle> + bsc::event<tick> / log("late tick"));
struct one_delayed_slot : bsc::default_policy {
    static constexpr std::size_t delayed_capacity = 1;
};
}  // namespace beyond

TEST_CASE_TEMPLATE("a delayed event whose due time lies past bsc::duration::max() never comes due, and takes no slot",
                   Backend, compiled, table) {
    using namespace std::chrono_literals;
    auto constexpr end_of_time = bsc::duration::max();
    SUBCASE("sent from a clock far from zero: not delivered, even by step(duration::max())") {
        machine_t<Backend, decltype(far_chart)> m{far_chart, ctx{}};
        m.step(end_of_time - 10s);
        CHECK(m.dispatch(start{}) == bsc::outcome::consumed);
        m.step(end_of_time);
        CHECK(m.context().log.empty());
        CHECK(m.template is<Wait>());
    }
    SUBCASE("not kept: another delayed event still finds the only slot") {
        machine_t<Backend, decltype(far_chart), one_delayed_slot> m{far_chart, ctx{}};
        m.step(end_of_time - 10s);
        CHECK(m.dispatch(start{}) == bsc::outcome::consumed);
        CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
        CHECK(m.dispatch(start_again{}) == bsc::outcome::consumed);  // no overflow
        m.step(end_of_time - 9s);
        CHECK(m.context().log == "tick");
        m.dispatch(back{});
        m.step(end_of_time);
        CHECK(m.context().log == "tick");
    }
    SUBCASE("due at duration::max() exactly: delivered by step(duration::max())") {
        machine_t<Backend, decltype(far_chart)> m{far_chart, ctx{}};
        m.step(5s);
        m.dispatch(start{});
        m.step(end_of_time - 1ns);
        CHECK(m.template is<Wait>());
        m.step(end_of_time);
        CHECK(m.context().log == "tick");
        CHECK(m.template is<Rang>());
    }
    SUBCASE("sent before the first cycle, which starts the clock far from zero: dropped then") {
        machine_t<Backend, decltype(far_chart), one_delayed_slot> m{far_chart, ctx{}};
        m.dispatch(start{});  // counts from the first cycle
        m.step(10s);          // which puts it 5 s past the end of time
        m.step(end_of_time);
        CHECK(m.context().log.empty());
        m.dispatch(back{});
        CHECK(m.dispatch(start_again{}) == bsc::outcome::consumed);  // its slot is free
    }
}

TEST_CASE("bsc::cancel_delayed(0) and a delay beyond bsc::duration, in a chart built at run time, throw") {
    CHECK_THROWS_AS((void)bsc::cancel_delayed(0), std::invalid_argument);
    CHECK_NOTHROW((void)bsc::cancel_delayed(1));
    CHECK_THROWS_AS((void)bsc::raise_after(std::chrono::hours{24 * 365 * 1000}, tick{}), std::out_of_range);
    CHECK_THROWS_AS((void)bsc::raise_after(std::chrono::seconds{-1}, tick{}), std::invalid_argument);
}

TEST_CASE("a delayed event and its cancellation are labelled in the exports") {
    auto const mermaid = bsc::to_mermaid(delayed_chart);
    CHECK(mermaid.find("Idle --> Wait : start / raise_after(2s, tick, 1)") != std::string::npos);
    CHECK(mermaid.find("Wait --> Idle : finish / cancel_delayed(1)") != std::string::npos);
}

// ---- transitions with several targets -----------------------------------------------------------

namespace beyond {
struct Q3;
struct QL;
struct QR;
struct QM;
struct QL1;
struct QL2;
struct QR1;
struct QR2;
struct QM1;
struct QM2;
inline constexpr auto targets_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::parallel<Q3>(bsc::composite<QL>(bsc::initial<QL1>, bsc::state<QL1>, bsc::state<QL2>),
                                           bsc::composite<QM>(bsc::initial<QM1>, bsc::state<QM1>, bsc::state<QM2>),
                                           bsc::composite<QR>(bsc::initial<QR1>, bsc::state<QR1>, bsc::state<QR2>))),
    bsc::state<Idle> + bsc::event<go> = bsc::targets(bsc::state<QL2>, bsc::state<QR2>),
    bsc::state<QL1> + bsc::event<go> = bsc::state<QL2>, bsc::state<QM1> + bsc::event<go> = bsc::state<QM2>,
    bsc::state<QR1> + bsc::event<go> = bsc::state<QR2>, bsc::state<Q3> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<Q3> + bsc::on_entry / log("enter Q3"), bsc::state<QL2> + bsc::on_entry / log("enter QL2"),
    bsc::state<QM1> + bsc::on_entry / log("enter QM1"), bsc::state<QR2> + bsc::on_entry / log("enter QR2"),
    bsc::state<QL> + bsc::on_entry / log("enter QL"), bsc::state<QM> + bsc::on_entry / log("enter QM"),
    bsc::state<QR> + bsc::on_entry / log("enter QR"));
}  // namespace beyond

TEST_CASE_TEMPLATE("a transition with several targets enters each, and the regions that hold none by default", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(targets_chart)> m{targets_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "enter Q3 enter QL enter QL2 enter QM enter QM1 enter QR enter QR2");
    CHECK(m.active_states().joined() == "Root Q3 QL QL2 QM QM1 QR QR2");
    CHECK(bsc::to_scxml(targets_chart).find("<transition event=\"go\" target=\"QL2 QR2\"/>") != std::string::npos);
}

namespace beyond {
struct Outer3;
inline constexpr auto initial_set_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>, bsc::state<Idle>,
        bsc::composite<Outer3>(
            bsc::initial<QL2, QR2>,
            bsc::parallel<Q3>(bsc::composite<QL>(bsc::initial<QL1>, bsc::state<QL1>, bsc::state<QL2>),
                              bsc::composite<QM>(bsc::initial<QM1>, bsc::state<QM1>, bsc::state<QM2>),
                              bsc::composite<QR>(bsc::initial<QR1>, bsc::state<QR1>, bsc::state<QR2>)))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Outer3>, bsc::state<Outer3> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<QL2> + bsc::event<go> = bsc::state<QL1>, bsc::state<QM1> + bsc::event<go> = bsc::state<QM2>,
    bsc::state<QR2> + bsc::event<go> = bsc::state<QR1>, bsc::state<Outer3> + bsc::on_initial / log("initial Outer3"),
    bsc::state<QL2> + bsc::on_entry / log("enter QL2"), bsc::state<QM1> + bsc::on_entry / log("enter QM1"),
    bsc::state<QR2> + bsc::on_entry / log("enter QR2"));
}  // namespace beyond

TEST_CASE_TEMPLATE("an initial transition may name one state in each region (initial<A, B>)", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(initial_set_chart)> m{initial_set_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "initial Outer3 enter QL2 enter QM1 enter QR2");
    CHECK(m.active_states().joined() == "Root Outer3 Q3 QL QL2 QM QM1 QR QR2");
    CHECK(bsc::to_scxml(initial_set_chart).find("<transition target=\"QL2 QR2\">") != std::string::npos);
    CHECK(bsc::to_mermaid(initial_set_chart).find("[*] --> QR2") != std::string::npos);
}

// ---- reachability follows every target and what a shallow history enters -------------------

namespace beyond {
struct Par;
struct RegionA;
struct RegionX;
struct A1;
struct B;
struct X1;
struct Y;

// Y is entered only by the second target of Idle's row: reachability follows every target.
inline constexpr auto second_target_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::parallel<Par>(bsc::composite<RegionA>(bsc::initial<A1>, bsc::state<A1>, bsc::state<B>),
                                            bsc::composite<RegionX>(bsc::initial<X1>, bsc::state<X1>, bsc::state<Y>))),
    bsc::state<Idle> + bsc::event<go> = bsc::targets(bsc::state<B>, bsc::state<Y>),
    bsc::state<Idle> + bsc::event<other> = bsc::state<Par>, bsc::state<Par> + bsc::event<back> = bsc::state<Idle>);

struct Hist;
struct P1;
struct P2;
struct X;
struct next {};
// X is never entered by a row: only the shallow history of Work restores P2, which it enters by
// default, X (as W3C SCXML IRP test 388).
inline constexpr auto restored_default_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Idle>,
                         bsc::composite<Work>(bsc::initial<P1>, bsc::shallow_history_state<Hist, P1>, bsc::state<P1>,
                                              bsc::composite<P2>(bsc::initial<X>, bsc::state<X>, bsc::state<Y>))),
    bsc::state<Idle> + bsc::event<go> = bsc::state<Hist>, bsc::state<P1> + bsc::event<next> = bsc::state<Y>,
    bsc::state<X> + bsc::event<next> = bsc::state<P1>, bsc::state<Work> + bsc::event<back> = bsc::state<Idle>,
    bsc::state<X> + bsc::on_entry / log("enter X"));
}  // namespace beyond

TEST_CASE_TEMPLATE("a state entered only by the second target of bsc::targets is reachable", Backend, compiled, table) {
    machine_t<Backend, decltype(second_target_chart)> m{second_target_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.active_states().joined() == "Root Par RegionA B RegionX Y");
}

TEST_CASE_TEMPLATE("a shallow history enters the restored child by default: a state never active before is reachable",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(restored_default_chart)> m{restored_default_chart, ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);  // no history yet: the default, P1
    CHECK(m.active_states().joined() == "Root Work P1");
    CHECK(m.dispatch(next{}) == bsc::outcome::consumed);
    CHECK(m.active_states().joined() == "Root Work P2 Y");
    CHECK(m.dispatch(back{}) == bsc::outcome::consumed);
    CHECK(m.context().log.empty());
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);  // restores P2, entered by default
    CHECK(m.active_states().joined() == "Root Work P2 X");
    CHECK(m.context().log == "enter X");
}

// ---- done events of parallel states: the regions are active when it completes ----------------

namespace beyond {
struct Both;
struct Left;
struct Right;
struct LeftWork;
struct LeftDone;
struct RightWork;
struct RightDone;
struct After;
inline constexpr auto region_takes_done_chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Both>, bsc::state<After>,
        bsc::parallel<Both>(
            bsc::composite<Left>(bsc::initial<LeftWork>, bsc::state<LeftWork>, bsc::final_state<LeftDone>),
            bsc::composite<Right>(bsc::initial<RightWork>, bsc::state<RightWork>, bsc::final_state<RightDone>))),
    bsc::state<LeftWork> + bsc::event<go> = bsc::state<LeftDone>,
    bsc::state<RightWork> + bsc::event<next> = bsc::state<RightDone>,
    bsc::state<Left> + bsc::event<bsc::done<Both>> / log("Left takes done.state.Both") = bsc::state<After>,
    bsc::state<After> + bsc::event<back> = bsc::state<Both>);
}  // namespace beyond

TEST_CASE_TEMPLATE("a region of a parallel state takes the parallel state's done event", Backend, compiled, table) {
    machine_t<Backend, decltype(region_takes_done_chart)> m{region_takes_done_chart, ctx{}};
    m.dispatch(go{});
    CHECK(m.context().log.empty());
    m.dispatch(next{});
    CHECK(m.context().log == "Left takes done.state.Both");
    CHECK(m.active_states().joined() == "Root After");
}

// ---- In: guards on the configuration (bsc::in<S>) ---------------------------------------------

namespace within {
struct flip {};
struct go {
    bool ready = true;
};
struct probe {};
struct same {};
struct leave {};
struct P;
struct A;
struct A1;
struct A2;
struct A3;
struct A31;
struct A32;
struct A321;
struct A322;
struct B;
struct B1;
struct B2;
struct B3;
struct B4;
struct B5;
struct ctx {
    std::string log;
};
inline constexpr auto log = bsc_test::log_action<ctx>;
inline constexpr auto ready = bsc::guard([](ctx const&, go const& e) { return e.ready; });
inline constexpr auto a2 = bsc::named<"a2">(bsc::in<A2>);
// Region A goes A1, A2, A3 (A31), A32 (A321), A322 and back to A1 on flip; region B's guards read
// where it is: a state of the other region, one several levels down, a composite, and states of
// B's own region.
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::parallel<P>(
        bsc::composite<A>(
            bsc::initial<A1>, bsc::state<A2>,
            bsc::composite<A3>(bsc::initial<A31>, bsc::composite<A32>(bsc::initial<A321>, bsc::state<A322>))),
        bsc::composite<B>(bsc::initial<B1>, bsc::state<B2>, bsc::state<B3>, bsc::state<B4>, bsc::state<B5>)),
    bsc::state<A1> + bsc::event<flip> = bsc::state<A2>, bsc::state<A2> + bsc::event<flip> = bsc::state<A3>,
    bsc::state<A31> + bsc::event<flip> = bsc::state<A32>, bsc::state<A321> + bsc::event<flip> = bsc::state<A322>,
    bsc::state<A322> + bsc::event<flip> = bsc::state<A1>, bsc::state<A2> + bsc::event<leave> = bsc::state<A1>,
    bsc::state<B1> + bsc::event<go>[bsc::in<A2>] / log("B1>B2") = bsc::state<B2>,
    bsc::state<B2> + bsc::event<go>[!bsc::in<A2> && ready] / log("B2>B1") = bsc::state<B1>,
    bsc::state<B1> + bsc::event<probe>[bsc::in<A322>] / log("deep") = bsc::state<B3>,
    bsc::state<B1> + bsc::event<probe>[bsc::in<A3> || a2] / log("composite") = bsc::state<B4>,
    bsc::state<B1> + bsc::event<same>[bsc::in<B2>] / log("never") = bsc::state<B5>,
    bsc::state<B1> + bsc::event<same>[bsc::in<B1> && bsc::in<B> && bsc::in<P>] / log("self"),
    bsc::state<B2> + bsc::event<leave>[bsc::in<A2>] / log("B2>B5") = bsc::state<B5>,
    bsc::state<B3> + bsc::event<go> = bsc::state<B1>, bsc::state<B4> + bsc::event<go> = bsc::state<B1>,
    bsc::state<B5> + bsc::event<go> = bsc::state<B1>);

// Eventless: B follows A, one step behind, and a plain guard composed with In.
struct Follow;
struct Lead;
struct L1;
struct L2;
struct F1;
struct F2;
struct count_ctx {
    int moves = 0;
};
inline constexpr auto counted = bsc::action([](count_ctx& c) { ++c.moves; });
inline constexpr auto few = [](count_ctx const& c) { return c.moves < 100; };
inline constexpr auto follow_chart = bsc::make_chart<count_ctx>(
    bsc::parallel<P>(bsc::composite<Lead>(bsc::initial<L1>, bsc::state<L2>),
                     bsc::composite<Follow>(bsc::initial<F1>, bsc::state<F2>)),
    bsc::state<L1> + bsc::event<flip> = bsc::state<L2>, bsc::state<L2> + bsc::event<flip> = bsc::state<L1>,
    bsc::state<F1>[bsc::guard(few) && bsc::in<L2>] / counted = bsc::state<F2>,
    bsc::state<F2>[few && bsc::in<L1>] / counted = bsc::state<F1>);


// A cycle: the regions are components that fire in document order, Before, Lead, After.
struct Before;
struct After;
struct G1;
struct G2;
inline constexpr auto cycle_chart = bsc::make_chart<count_ctx>(
    bsc::parallel<P>(bsc::composite<Before>(bsc::initial<G1>, bsc::state<G2>),
                     bsc::composite<Lead>(bsc::initial<L1>, bsc::state<L2>),
                     bsc::composite<Follow>(bsc::initial<F1>, bsc::state<F2>)),
    bsc::state<G1>[bsc::in<L2>] = bsc::state<G2>, bsc::state<G2> + bsc::event<flip> = bsc::state<G1>,
    bsc::state<L1> = bsc::state<L2>, bsc::state<L2> + bsc::event<flip> = bsc::state<L1>,
    bsc::state<F1>[bsc::in<L2>] = bsc::state<F2>, bsc::state<F2> + bsc::event<flip> = bsc::state<F1>);
}  // namespace within

TEST_CASE_TEMPLATE("In(S) holds while S is active: a region's guard reads another region's configuration", Backend,
                   compiled, table) {
    using within::flip;
    using within::go;
    machine_t<Backend, decltype(within::chart)> m{within::chart, within::ctx{}};
    CHECK(m.dispatch(go{}) == bsc::outcome::ignored);  // A1: In(A2) is false
    m.dispatch(flip{});
    REQUIRE(m.active_states().joined() == "P A A2 B B1");
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);  // In(A2)
    CHECK(m.context().log == "B1>B2");
    CHECK(m.dispatch(go{}) == bsc::outcome::ignored);       // !In(A2) && ready: In(A2)
    m.dispatch(flip{});                                     // A3
    CHECK(m.dispatch(go{false}) == bsc::outcome::ignored);  // !In(A2), but not ready
    CHECK(m.dispatch(go{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "B1>B2 B2>B1");
    CHECK(m.active_states().joined() == "P A A3 A31 B B1");
}

TEST_CASE_TEMPLATE("In(S) of a state several levels down, of a composite, and of states of the guard's own region",
                   Backend, compiled, table) {
    using within::flip;
    using within::go;
    using within::probe;
    using within::same;
    machine_t<Backend, decltype(within::chart)> m{within::chart, within::ctx{}};
    CHECK(m.dispatch(probe{}) == bsc::outcome::ignored);  // A1: none of A322, A3, A2
    m.dispatch(flip{});                                   // A2: the named In(A2)
    CHECK(m.dispatch(probe{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "composite");
    m.dispatch(go{});
    m.dispatch(flip{});  // A3, A31: the composite A3
    CHECK(m.dispatch(probe{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "composite composite");
    m.dispatch(go{});
    m.dispatch(flip{});
    m.dispatch(flip{});  // A322, three levels below A: In(A322), the first row, holds
    REQUIRE(m.active_states().joined() == "P A A3 A32 A322 B B1");
    CHECK(m.dispatch(probe{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "composite composite deep");
    m.dispatch(go{});
    // The guard's own region: In(B2) never holds where B1 is active, In(B1), In(B), In(P) always.
    CHECK(m.dispatch(same{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "composite composite deep self");
    CHECK(m.active_states().joined() == "P A A3 A32 A322 B B1");
}

TEST_CASE_TEMPLATE("In(S) sees the configuration before the microstep's exits: the regions select first", Backend,
                   compiled, table) {
    using within::flip;
    using within::go;
    using within::leave;
    machine_t<Backend, decltype(within::chart)> m{within::chart, within::ctx{}};
    m.dispatch(flip{});
    m.dispatch(go{});
    REQUIRE(m.active_states().joined() == "P A A2 B B2");
    // leave: A2 -> A1 in region A, and B2's In(A2) in region B, both selected before either fires.
    CHECK(m.dispatch(leave{}) == bsc::outcome::consumed);
    CHECK(m.active_states().joined() == "P A A1 B B5");
}

TEST_CASE_TEMPLATE("eventless rows guarded by In(S) follow another region, composed with a plain guard", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(within::follow_chart)> m{within::follow_chart, within::count_ctx{}};
    CHECK(m.active_states().joined() == "P Lead L1 Follow F1");
    m.dispatch(within::flip{});
    CHECK(m.active_states().joined() == "P Lead L2 Follow F2");
    m.dispatch(within::flip{});
    CHECK(m.active_states().joined() == "P Lead L1 Follow F1");
    CHECK(m.context().moves == 2);
}

TEST_CASE_TEMPLATE("in step(), a component's In(S) sees the transitions of the components before it in the cycle",
                   Backend, compiled, table) {
    using namespace std::chrono_literals;
    machine_t<Backend, decltype(within::cycle_chart), bsc::scan_policy> m{within::cycle_chart, within::count_ctx{}};
    REQUIRE(m.active_states().joined() == "P Before G1 Lead L1 Follow F1");
    m.step(0ms);  // Lead takes L2; Follow, after it, sees it; Before, first, saw L1
    CHECK(m.active_states().joined() == "P Before G1 Lead L2 Follow F2");
    m.step(1ms);
    CHECK(m.active_states().joined() == "P Before G2 Lead L2 Follow F2");
}

TEST_CASE("In(S) runs in constant expressions, and only charts with it pass the configuration to their guards") {
    static_assert([] {
        bsc::machine m{within::follow_chart, within::count_ctx{}};
        m.dispatch(within::flip{});
        m.dispatch(within::flip{});
        return m.context().moves;
    }() == 2);
    // The table's guards take the configuration bytes in a chart with bsc::in only.
    using with_in = bsc::table::tables<decltype(within::chart)>::transition_row_type;
    using without = bsc::table::tables<decltype(beyond::family_chart)>::transition_row_type;
    static_assert(with_in::guards_read_configuration && !without::guards_read_configuration);
    static_assert(std::is_same_v<without::guard_fn,
                                 bool (*)(decltype(beyond::family_chart) const&, beyond::ctx const&, void const*)>);
    static_assert(bsc::detail::tests_configuration<std::remove_cvref_t<decltype(!bsc::in<within::A2>)>>);
    static_assert(bsc::detail::tests_configuration<std::remove_cvref_t<decltype(within::a2)>>);
    static_assert(!bsc::detail::tests_configuration<std::remove_cvref_t<decltype(within::ready)>>);
    CHECK(true);
}

TEST_CASE("In(S) is labelled In(S) in the diagrams and the row text, and written In('id') in SCXML's cond") {
    auto const scxml = bsc::to_scxml(within::chart);
    CHECK(scxml.find("<transition event=\"go\" cond=\"In('A2')\" target=\"B2\">") != std::string::npos);
    CHECK(scxml.find("cond=\"!In('A2') &amp;&amp; guard\"") != std::string::npos);
    CHECK(scxml.find("cond=\"In('A3') || a2\"") != std::string::npos);
    CHECK(scxml.find("cond=\"In('B1') &amp;&amp; In('B') &amp;&amp; In('P')\"") != std::string::npos);
    CHECK(scxml.find("<state id=\"A322\"") != std::string::npos);  // the id In names
    auto const mermaid = bsc::to_mermaid(within::chart);
    CHECK(mermaid.find("B1 --> B3 : probe [In(A322)] / action") != std::string::npos);
    CHECK(mermaid.find("B2 --> B1 : go [!In(A2) && guard] / action") != std::string::npos);
    CHECK(bsc::to_dot(within::chart).find("[In(A3) || a2]") != std::string::npos);
    CHECK(bsc::to_plantuml(within::chart).find("[!In(A2) && guard]") != std::string::npos);
    using row = bsc::detail::chart_model<decltype(within::chart)>::row_at<7>;
    CHECK(std::string_view{bsc::detail::row_text<row>().view()} == "B2 + go [!In(A2) && guard] / action = B1");
}
