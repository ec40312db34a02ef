// The explorer and its properties (docs/verification.md), on small charts whose state
// spaces are known by hand.

#include <doctest/doctest.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>
#include "inside.hpp"

using namespace std::chrono_literals;

namespace ver {
struct go {};
struct back {};
struct Root;
struct A;
struct B;
struct C;
struct ctx {
    int n = 0;
};
// A -go/n=(n+1)%3-> B -go[n==2]-> C; back returns to A. Reachable: (A,0..2), (B,1..2,0), (C,2).
inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / [](ctx& c) { c.n = (c.n + 1) % 3; } = bsc::state<B>,
    bsc::state<B> + bsc::event<go>[([](ctx const& c) { return c.n == 2; })] = bsc::state<C>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<C> + bsc::event<back> = bsc::state<A>);

inline auto model() {
    return bsc::verify::event_model<bsc::machine<decltype(chart)>, go, back>{bsc::machine{chart, ctx{}}};
}
inline constexpr auto in_b = [](auto const& m) { return m.template is<B>(); };
inline constexpr auto in_c = [](auto const& m) { return m.template is<C>(); };
}  // namespace ver

TEST_CASE("the explorer visits each reachable state once, breadth first") {
    bsc::verify::explorer ex{ver::model()};
    auto const& st = ex.run();
    CHECK(st.complete);
    CHECK(st.states == 7);                                 // (A,0) (B,1) (A,1) (B,2) (A,2) (C,2) (B,0)
    CHECK(st.transitions == 14);                           // two events offered in each state
    CHECK(st.key_bytes == (2 + 8 * sizeof(int) + 7) / 8);  // the root byte in 2 bits (3 children), n
    CHECK(st.depth == 5);
}

TEST_CASE("reachability gives a shortest witness in the chart's names") {
    bsc::verify::explorer ex{ver::model()};
    auto const v = bsc::verify::reachable(ex, "C", ver::in_c);
    REQUIRE(v.holds());
    REQUIRE(v.trace.size() == 5);
    CHECK(v.trace[0].label == "(initial)");
    CHECK(v.trace[1].label == "go");
    CHECK(v.trace[2].label == "back");
    CHECK(v.trace[4].configuration == "Root C");
    CHECK_FALSE(bsc::verify::reachable(ex, "nothing", [](auto const&) { return false; }).holds());
}

TEST_CASE("an invariant that fails comes back with a shortest counterexample") {
    bsc::verify::explorer ex{ver::model()};
    auto const v = bsc::verify::always(ex, "never in C", [](auto const& m) { return !m.template is<ver::C>(); });
    CHECK(v.fails());
    CHECK(v.trace.size() == 5);
    CHECK(v.trace.back().configuration == "Root C");
    CHECK(bsc::verify::always(ex, "n < 3", [](auto const& m) { return m.context().n < 3; }).holds());
}

TEST_CASE("deadlock freedom, reinitiability and leads-to") {
    bsc::verify::explorer ex{ver::model()};
    CHECK(bsc::verify::deadlock_free(ex).holds());
    CHECK(bsc::verify::reinitiable(ex).holds());
    // From B, `go` with n != 2 is ignored: B can stay B forever, so B --> C fails.
    auto const v = bsc::verify::leads_to(ex, "B --> C", ver::in_b, ver::in_c);
    CHECK(v.fails());
    CHECK(v.trace.back().configuration == "Root B");
    CHECK(v.detail.find("loops") != std::string::npos);
    CHECK(bsc::verify::leads_to(ex, "C --> A", ver::in_c, [](auto const& m) {
              return !m.template is<ver::C>();
          }).fails());  // C can ignore `go` forever
}

namespace ver {
struct Stop;
struct halt {};
// A chart that can get stuck: D has only an internal transition... which the static checks
// forbid, so the trap is a guard that never holds again.
struct D;
inline constexpr auto trap = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<D>, bsc::final_state<Stop>),
    bsc::state<A> + bsc::event<go> / [](ctx& c) { c.n = 1; } = bsc::state<D>,
    bsc::state<D> + bsc::event<back>[([](ctx const& c) { return c.n == 0; })] = bsc::state<A>,
    bsc::state<A> + bsc::event<halt> = bsc::state<Stop>);
}  // namespace ver

TEST_CASE("a state with no way out is a deadlock unless it is final; reinitiability fails there") {
    bsc::verify::explorer ex{bsc::verify::event_model<bsc::machine<decltype(ver::trap)>, ver::go, ver::back, ver::halt>{
        bsc::machine{ver::trap, ver::ctx{}}}};
    auto const v = bsc::verify::deadlock_free(ex, [](auto const& m) { return m.halted(); });
    REQUIRE(v.fails());
    CHECK(v.trace.back().configuration == "Root D");
    CHECK(bsc::verify::reinitiable(ex).fails());
}

TEST_CASE("a bound stops exploration with a report, and verdicts become inconclusive") {
    bsc::verify::explorer ex{ver::model(), bsc::verify::limits{3, std::size_t{1} << 30}};
    auto const& st = ex.run();
    CHECK_FALSE(st.complete);
    CHECK(st.stopped_by.find("max_states") != std::string::npos);
    CHECK(bsc::verify::always(ex, "true", [](auto const&) { return true; }).result ==
          bsc::verify::verdict::status::inconclusive);
}

namespace ver {
struct On;
struct Off;
struct blink_data {
    bsc::input<bool> enable;
    bsc::output<bool> lamp;
    bsc::timer t{300ms};
};
// A lamp that blinks with a BSC timer while enabled, and a timeout that switches it off.
inline constexpr auto blink = bsc::make_chart<blink_data>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](blink_data const& d) { return d.enable.get(); })] /
        [](blink_data& d) {
            d.lamp.set(true);
            d.t.start();
        } = bsc::state<On>,
    bsc::state<On>[([](blink_data const& d) { return d.t.tm(); })] /
        [](blink_data& d) {
            d.lamp.set(false);
            d.t.reset();
        } = bsc::state<Off>,
    bsc::state<On> + bsc::after(1s) = bsc::state<Off>);
}  // namespace ver

TEST_CASE("cycle models: absolute time is abstracted, so a periodic behaviour has finitely many states") {
    auto apply = [](ver::blink_data const& d, std::size_t choice) { d.enable.set(choice == 1); };
    bsc::verify::cycle_model model{bsc::machine{ver::blink, ver::blink_data{}}, 100ms, 2, apply};
    bsc::verify::explorer ex{model};
    auto const& st = ex.run();
    CHECK(st.complete);
    CHECK(st.states < 64);
    CHECK(bsc::verify::deadlock_free(ex).holds());
    CHECK(bsc::verify::reinitiable(ex).holds());
    // The lamp is never on for more than the timer allows: On lasts 1 + 3 cycles at most.
    auto const on_long = bsc::verify::reachable(
        ex, "t.tm while On", [](auto const& m) { return m.template is<ver::On>() && m.context().t.tm(); });
    CHECK_FALSE(on_long.holds());  // the guard fires in the very cycle tm turns true
    CHECK(bsc::verify::leads_to(
              ex, "On --> Off", [](auto const& m) { return m.template is<ver::On>(); },
              [](auto const& m) { return m.template is<ver::Off>(); })
              .holds());
}

namespace ver {
struct Ticking;
struct Halted;
struct stop {};
struct two_data {
    bsc::input<bool> enable;
};
inline constexpr auto enabled = [](two_data const& d) { return d.enable.get(); };
// Two guarded internal timeouts of one state: which fires, when both are due, depends on when each
// came due, long after the longest delay.
inline constexpr auto two_timeouts = bsc::make_chart<two_data>(
    bsc::composite<Root>(bsc::initial<Ticking>, bsc::state<Halted>),
    bsc::state<Ticking> + bsc::after(1s)[enabled] / [] {}, bsc::state<Ticking> + bsc::after(2s)[enabled] / [] {},
    bsc::state<Ticking> + bsc::event<stop> = bsc::state<Halted>,
    bsc::state<Halted> + bsc::event<stop> = bsc::state<Ticking>);
struct rows_fired {
    std::vector<int> rows;
    void on_row(int row) { rows.push_back(row); }
};
}  // namespace ver

TEST_CASE("the codec keeps the order in which a state's timeouts came due, long past the longest delay") {
    using machine = bsc::machine<decltype(ver::two_timeouts), bsc::scan_policy, ver::rows_fired>;
    machine never{ver::two_timeouts};  // neither timeout has fired: both count from 0
    machine once{ver::two_timeouts};   // the 1 s one fired at 1 s, and counts from there
    never.step(0s);
    once.step(0s);
    once.context().enable.set(true);
    once.step(1s);
    once.context().enable.set(false);
    for (auto t = 2s; t <= 10s; t += 1s) {
        never.step(t);
        once.step(t);
    }
    REQUIRE(once.observer().rows == std::vector<int>{0});
    inside::codec<machine> const codec{1s};
    std::vector<std::byte> never_key(codec.key_size);
    std::vector<std::byte> once_key(codec.key_size);
    codec.encode(never, never_key.data());
    codec.encode(once, once_key.data());
    CHECK(never_key != once_key);  // each timeout's count is capped at 3 periods, but not their difference
    // Decoded, each behaves as the machine it was encoded from: when enabled, `never` fires the
    // 1 s timeout (due at 1 s), `once` the 2 s one (due at 2 s, as the other, but armed first).
    auto const next_row = [](machine m, bsc::duration at) {
        m.observer().rows.clear();
        m.context().enable.set(true);
        m.step(at);
        return m.observer().rows;
    };
    CHECK(next_row(never, 11s) == std::vector<int>{0});
    CHECK(next_row(once, 11s) == std::vector<int>{1});
    machine const fresh{ver::two_timeouts};
    auto const decoded_never = codec.decode(fresh, never_key.data());
    auto const decoded_once = codec.decode(fresh, once_key.data());
    CHECK(next_row(decoded_never, decoded_never.now() + 1s) == std::vector<int>{0});
    CHECK(next_row(decoded_once, decoded_once.now() + 1s) == std::vector<int>{1});
}

TEST_CASE("leads_to_within: a bounded response, with a counterexample that shows the time of each step") {
    auto apply = [](ver::blink_data const& d, std::size_t choice) { d.enable.set(choice == 1); };
    auto label = [](std::size_t choice) { return choice == 1 ? std::string("enable=1") : std::string("enable=0"); };
    bsc::verify::cycle_model model{bsc::machine{ver::blink, ver::blink_data{}}, 100ms, 2, apply, label};
    bsc::verify::explorer ex{model};
    auto const on = [](auto const& m) { return m.template is<ver::On>(); };
    auto const off = [](auto const& m) { return m.template is<ver::Off>(); };
    // The timer of 300 ms starts timing in the cycle after On and turns the lamp off in the cycle
    // it expires: Off four cycles (400 ms) after On.
    auto const holds = bsc::verify::leads_to_within(ex, "On --> Off", on, off, 400ms);
    CHECK(holds.holds());
    CHECK(holds.property == "On --> Off within 400ms");
    CHECK(bsc::verify::leads_to_within(ex, "On --> Off", on, off, 499ms).holds());  // 4 whole periods
    auto const fails = bsc::verify::leads_to_within(ex, "On --> Off", on, off, 399ms);
    REQUIRE(fails.fails());
    // A shortest path to On (enable at step 1), then the slowest way on, one step past the
    // 3 periods the bound covers: Off only at step 5.
    REQUIRE(fails.trace.size() == 6);
    CHECK(fails.detail == "p holds at step 1; q does not hold 399ms later");
    CHECK(fails.trace[1].time == 100ms);
    CHECK(fails.trace[4].configuration == "Root On");
    CHECK(fails.trace[5].time == 500ms);
    CHECK(fails.trace[5].configuration == "Root Off");
    CHECK(fails.to_string() ==
          "On --> Off within 399ms: FAILS (p holds at step 1; q does not hold 399ms later)\n"
          "  0. [0s] (initial) -> Root Off\n"
          "  1. [100ms] enable=1 -> Root On\n"
          "  2-4. [200ms-400ms] 3 steps, same inputs and configuration\n"
          "  5. [500ms] (inputs unchanged) -> Root Off\n");
    CHECK_THROWS_AS(bsc::verify::leads_to_within(ex, "", on, off, -1ms), std::invalid_argument);
}

TEST_CASE("leads_to_within fails on a cycle or a deadlock that avoids q, and q in the p-state counts") {
    auto apply = [](ver::blink_data const& d, std::size_t choice) { d.enable.set(choice == 1); };
    bsc::verify::cycle_model model{bsc::machine{ver::blink, ver::blink_data{}}, 100ms, 2, apply};
    bsc::verify::explorer ex{model};
    auto const off = [](auto const& m) { return m.template is<ver::Off>(); };
    auto const never = [](auto const&) { return false; };
    CHECK(bsc::verify::leads_to_within(ex, "", off, off, 0ms).holds());
    auto const v = bsc::verify::leads_to_within(ex, "", off, never, 10s);
    REQUIRE(v.fails());
    CHECK(v.detail.find("loops without reaching q") != std::string::npos);
    CHECK(v.trace.front().label == "(initial)");
}

TEST_CASE("a trace report folds runs of repeated steps and shows only the inputs that changed") {
    bsc::verify::verdict v{"A[] p", bsc::verify::verdict::status::fails, {}, {}};
    v.trace = {{"(initial)", "Root Idle", 0ms}, {"a=0 b=1", "Root Idle", 10ms}, {"a=0 b=1", "Root Idle", 20ms},
               {"a=0 b=1", "Root Idle", 30ms},  {"a=1 b=1", "Root Busy", 40ms}, {"a=1 b=1", "Root Busy Sub", 50ms}};
    CHECK(v.to_string() ==
          "A[] p: FAILS\n"
          "  0. [0s] (initial) -> Root Idle\n"
          "  1. [10ms] a=0 b=1 -> Root Idle\n"
          "  2-3. [20ms-30ms] 2 steps, same inputs and configuration\n"
          "  4. [40ms] a=1 -> Root Busy\n"
          "  5. [50ms] (inputs unchanged) -> Root Busy Sub\n");
    v.trace = {{"(initial)", "A", {}}, {"go", "B", {}}, {"go", "B", {}}};  // an event model: no time
    CHECK(v.to_string() == "A[] p: FAILS\n  0. (initial) -> A\n  1. go -> B\n  2. go -> B\n");
    // Only labels made of name=value words alone are shown as what changed.
    v.trace = {{"(initial)", "A", {}}, {"push P1=0", "A", {}}, {"push P1=1", "B", {}}};
    CHECK(v.to_string() == "A[] p: FAILS\n  0. (initial) -> A\n  1. push P1=0 -> A\n  2. push P1=1 -> B\n");
}

TEST_CASE("a progress callback reports a long exploration while it runs, and once at the end") {
    auto apply = [](ver::blink_data const& d, std::size_t choice) { d.enable.set(choice == 1); };
    bsc::verify::cycle_model model{bsc::machine{ver::blink, ver::blink_data{}}, 100ms, 2, apply};
    bsc::verify::explorer ex{model};
    std::vector<bsc::verify::progress> seen;
    ex.on_progress([&](bsc::verify::progress const& p) { seen.push_back(p); }, 2);
    auto const& st = ex.run();
    REQUIRE(seen.size() >= 2);
    CHECK(seen.back().done);
    CHECK(seen.back().states == st.states);
    CHECK(seen.back().expanded == st.states);
    CHECK(seen.back().depth == st.depth);
    CHECK(seen.back().memory_bytes > 0);
    CHECK_FALSE(seen.front().done);
    CHECK(seen.front().expanded == 2);
    for (std::size_t i = 1; i < seen.size(); ++i) CHECK(seen[i].states >= seen[i - 1].states);
}

namespace ver {
struct E;
// A row whose guard can never hold: the static checks accept it, coverage reports it.
inline constexpr auto dead = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<E>), bsc::state<A> + bsc::event<go> = bsc::state<B>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>,
    bsc::state<B> + bsc::event<go>[([](ctx const& c) { return c.n > 100; })] = bsc::state<E>,
    bsc::state<E> + bsc::event<back> = bsc::state<A>);
}  // namespace ver

TEST_CASE("coverage reports the states and transitions that no explored run exercises") {
    std::vector<bool> fired(8, false);
    using M = bsc::machine<decltype(ver::dead), bsc::default_policy, bsc::verify::row_recorder>;
    bsc::verify::explorer ex{
        bsc::verify::event_model<M, ver::go, ver::back>{M{ver::dead, ver::ctx{}, bsc::verify::row_recorder{&fired}}}};
    auto const report = bsc::verify::coverage(ex, fired);
    CHECK(report.dead_states == std::vector<std::string>{"E"});
    CHECK(report.dead_transitions == std::vector<std::string>{"B + go -> E", "E + back -> A"});
}

TEST_CASE("AG EF p: from every reachable state a p-state can be reached") {
    bsc::verify::explorer ex{ver::model()};
    CHECK(bsc::verify::always_reachable(ex, "C", ver::in_c).holds());
    bsc::verify::explorer trapped{
        bsc::verify::event_model<bsc::machine<decltype(ver::trap)>, ver::go, ver::back, ver::halt>{
            bsc::machine{ver::trap, ver::ctx{}}}};
    auto const v = bsc::verify::always_reachable(trapped, "A", [](auto const& m) { return m.template is<ver::A>(); });
    REQUIRE(v.fails());
    CHECK(v.trace.back().configuration == "Root D");  // the first state cut off from A
}

namespace ver {
struct item {
    std::uint8_t id = 0;
    bool checked = false;
};
struct carrier {
    bsc::input<item> incoming;
    bsc::output<item> outgoing;
    bsc::input<bool> flag;
};
}  // namespace ver

TEST_CASE("the codec encodes channels of aggregates member by member, and decodes them back") {
    using codec = inside::codec<ver::carrier>;
    // 2 x (8 + 1) bits per item channel, 2 bits for the flag: 38 bits.
    CHECK(codec::key_size == 5);
    ver::carrier c{};
    auto const& environment = c;  // inputs are set through a const view, outputs by the chart
    environment.incoming.set({7, true});
    inside::latch(c.incoming);
    environment.incoming.set({9, false});
    c.outgoing.set({3, true});
    environment.flag.set(true);
    std::vector<std::byte> key(codec::key_size);
    codec{}.encode(c, key.data());
    ver::carrier const back = codec{}.decode(ver::carrier{}, key.data());
    CHECK(back.incoming.get().id == 7);
    CHECK(back.incoming.get().checked);
    CHECK(back.incoming.pending().id == 9);
    CHECK(back.outgoing.pending().id == 3);
    CHECK(back.outgoing.get().id == 0);
    CHECK(back.flag.pending());
    CHECK_FALSE(back.flag.get());
}
