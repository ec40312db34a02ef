// The BSC execution cycle (docs/semantics.md, "The execution cycle"): channels, variables,
// components, BSC timers and state-scoped timeouts. The cases that run a machine run against
// both back ends: the compiled bsc::machine and the table-driven bsc::table::machine.

#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>
#include <utility>

#include <bsc/bsc.hpp>

#include "backends.hpp"
#include "inside.hpp"

using namespace std::chrono_literals;

using bsc_test::compiled;
using bsc_test::machine_t;
using bsc_test::table;

namespace cyc {
struct Root;
struct P;
struct C1;
struct C2;
struct C3;
struct Idle1;
struct Busy1;
struct Idle2;
struct Busy2;
struct Idle3;
struct Busy3;
struct kick {};

struct plant {
    bsc::input<bool> start;
    bsc::output<int> lamp;
    bsc::inout<int> shared;
    int var = 0;
    int seen_lamp = -1;
    int seen_var = -1;
};

// Three components; the first writes a variable and an output, the later ones read them.
inline constexpr auto chart = bsc::make_chart<plant>(
    bsc::composite<Root>(bsc::initial<P>, bsc::parallel<P>(bsc::composite<C1>(bsc::initial<Idle1>, bsc::state<Busy1>),
                                                           bsc::composite<C2>(bsc::initial<Idle2>, bsc::state<Busy2>),
                                                           bsc::composite<C3>(bsc::initial<Idle3>, bsc::state<Busy3>))),
    bsc::state<Idle1>[([](plant const& p) { return p.start.get(); })] /
        [](plant& p) {
            p.var = 1;
            p.lamp.set(7);
        } = bsc::state<Busy1>,
    bsc::state<Busy1>[([](plant const& p) { return !p.start.get(); })] = bsc::state<Idle1>,
    bsc::state<Idle2>[([](plant const& p) { return p.var == 1; })] /
        [](plant& p) {
            p.seen_lamp = p.lamp.get();  // published value: still the old one during the cycle
            p.seen_var = p.var;
        } = bsc::state<Busy2>,
    bsc::state<Busy2>[([](plant const& p) { return p.var == 0; })] = bsc::state<Idle2>,
    bsc::state<Idle3>[([](plant const& p) { return p.var == 2; })] = bsc::state<Busy3>,
    bsc::state<Busy3>[([](plant const& p) { return p.var == 0; })] = bsc::state<Idle3>,
    bsc::state<Busy2> + bsc::event<kick> / [](plant& p) { p.var = 2; });
}  // namespace cyc

TEST_CASE_TEMPLATE("inputs written between cycles are latched at the start of the next cycle", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::chart)> m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    CHECK_FALSE(m.context().start.get());  // not yet latched
    CHECK(m.context().start.pending());
    auto const r = m.step(0ms);
    CHECK(m.context().start.get());
    CHECK(m.template is<cyc::Busy1>());
    CHECK(r.transitions == 2);  // C1, then C2 which sees C1's variable at once
}

TEST_CASE_TEMPLATE("a variable written by a component is visible at once to the components after it", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::chart)> m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    CHECK(m.template is<cyc::Busy2>());
    CHECK(m.context().seen_var == 1);
}

TEST_CASE_TEMPLATE("outputs are double-buffered: published at the end of the cycle", Backend, compiled, table) {
    machine_t<Backend, decltype(cyc::chart)> m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    CHECK(m.context().seen_lamp == 0);   // C2 read the published value during the cycle
    CHECK(m.context().lamp.get() == 7);  // published after it
}

TEST_CASE_TEMPLATE("each component fires at most one transition per cycle, in declaration order", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::chart)> m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    m.context().start.set(false);
    auto const r = m.step(1ms);  // C1 goes back to Idle1; C2 and C3 see no change of var
    CHECK(r.transitions == 1);
    CHECK(m.template is<cyc::Idle1>());
    CHECK(m.template is<cyc::Busy2>());
}

TEST_CASE_TEMPLATE("dispatch settles eventless transitions at once, whatever the cycle rules", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::chart)> m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    m.dispatch(cyc::kick{});  // var = 2: C3's eventless transition follows within the dispatch
    CHECK(m.template is<cyc::Busy3>());
}

namespace cyc {
struct A;
struct B;
struct C;
struct D;
struct chain_data {
    bool go = false;
};
// A chain whose guards all hold: one step takes one link.
inline constexpr auto chain = bsc::make_chart<chain_data>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>, bsc::state<D>),
    bsc::state<A> + bsc::event<kick> = bsc::state<B>, bsc::state<B> + bsc::after(100ms) = bsc::state<C>,
    bsc::state<C> + bsc::after(100ms) = bsc::state<D>, bsc::state<D> + bsc::event<kick> = bsc::state<A>);
}  // namespace cyc

TEST_CASE_TEMPLATE("a state-scoped timeout fires at the first cycle at or after its delay, armed on entry", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(cyc::chain)> m{cyc::chain, cyc::chain_data{}};
    m.step(0ms);
    m.step(50ms);
    m.dispatch(cyc::kick{});  // enters B at the machine's time, 50 ms
    CHECK(m.template is<cyc::B>());
    m.step(100ms);
    CHECK(m.template is<cyc::B>());  // 50 ms in B
    m.step(149ms);
    CHECK(m.template is<cyc::B>());
    m.step(150ms);                   // 100 ms in B
    CHECK(m.template is<cyc::C>());  // entered at 150 ms
    m.step(200ms);
    CHECK(m.template is<cyc::C>());
    m.step(250ms);
    CHECK(m.template is<cyc::D>());
}

TEST_CASE_TEMPLATE("a jump of many periods takes one transition per component, not the missed cycles", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(cyc::chain)> m{cyc::chain, cyc::chain_data{}};
    m.step(0ms);  // the clock starts at 0
    m.dispatch(cyc::kick{});
    auto const r = m.step(10s);
    CHECK(r.transitions == 1);
    CHECK(m.template is<cyc::C>());  // C's timeout is armed at 10 s
    m.step(10s);
    CHECK(m.template is<cyc::C>());
    m.step(10s + 100ms);
    CHECK(m.template is<cyc::D>());
}

TEST_CASE_TEMPLATE("time never runs backwards for the machine: an earlier time is reported and ignored", Backend,
                   compiled, table) {
    machine_t<Backend, decltype(cyc::chain)> m{cyc::chain, cyc::chain_data{}};
    m.step(1s);
    m.dispatch(cyc::kick{});  // B armed at 1 s
    auto const r = m.step(500ms);
    CHECK(r.clock_went_backwards);
    CHECK(m.now() == 1s);
    CHECK(m.template is<cyc::B>());
    CHECK_FALSE(m.step(1050ms).clock_went_backwards);
    CHECK(m.template is<cyc::B>());
    m.step(1100ms);
    CHECK(m.template is<cyc::C>());
}

namespace cyc {
struct On;
struct Off;
struct drill_data {
    bsc::input<bool> piece;
    bsc::output<bool> motor;
    bsc::timer t1{300ms};
};
inline constexpr auto drill = bsc::make_chart<drill_data>(
    bsc::composite<Root>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](drill_data const& d) { return d.piece.get(); })] /
        [](drill_data& d) {
            d.motor.set(true);
            d.t1.start();
        } = bsc::state<On>,
    bsc::state<On>[([](drill_data const& d) { return d.t1.tm(); })] /
        [](drill_data& d) {
            d.motor.set(false);
            d.t1.reset();
        } = bsc::state<Off>);
}  // namespace cyc

TEST_CASE_TEMPLATE("a BSC timer starts timing at the cycle after start() and expires at the first cycle at its limit",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(cyc::drill)> m{cyc::drill, cyc::drill_data{}};
    m.context().piece.set(true);
    m.step(0ms);  // cycle 0: start() requested
    CHECK(m.template is<cyc::On>());
    CHECK(m.context().motor.get());
    CHECK_FALSE(m.context().t1.running());
    m.context().piece.set(false);
    m.step(100ms);  // cycle 1: timing begins (t = 100 ms)
    CHECK(m.context().t1.running());
    m.step(200ms);
    m.step(300ms);
    CHECK_FALSE(m.context().t1.tm());
    CHECK(m.template is<cyc::On>());
    m.step(399ms);
    CHECK(m.template is<cyc::On>());
    m.step(400ms);  // 300 ms after timing began: tm, and the guard sees it in this cycle
    CHECK(m.template is<cyc::Off>());
    CHECK_FALSE(m.context().motor.get());
    CHECK_FALSE(m.context().t1.tm());  // reset by the action
}

TEST_CASE_TEMPLATE("dispatch latches inputs at its start and commits outputs at its end", Backend, compiled, table) {
    struct go {};
    struct io {
        bsc::input<int> in;
        bsc::output<int> out;
        int seen = -1;
    };
    struct S;
    struct T;
    static constexpr auto chart = bsc::make_chart<io>(
        bsc::composite<cyc::Root>(bsc::initial<S>, bsc::state<T>),
        bsc::state<S> + bsc::event<go> /
                            [](io& x) {
                                x.seen = x.in.get();
                                x.out.set(x.in.get() * 2);
                            },
        bsc::state<S> + bsc::event<cyc::kick> = bsc::state<T>, bsc::state<T> + bsc::event<cyc::kick> = bsc::state<S>);
    machine_t<Backend, decltype(chart)> m{chart, io{}};
    m.context().in.set(21);
    m.dispatch(go{});
    CHECK(m.context().seen == 21);
    CHECK(m.context().out.get() == 42);
}

TEST_CASE("an inout channel is read as latched and written for the next cycle") {
    bsc::inout<int> ch{1};
    ch.set(5);
    CHECK(ch.get() == 1);
    inside::commit(ch);
    CHECK(ch.get() == 5);
    ch.set(6);
    inside::latch(ch);
    CHECK(ch.get() == 6);
}

namespace cyc::turns {
// The states of the charts that test which components take their turn in a cycle.
struct Q;
struct R1;
struct R2;
struct X;
struct Y;
struct Z;
struct W;
}  // namespace cyc::turns

TEST_CASE_TEMPLATE("components entered during a cycle first run in the next cycle", Backend, compiled, table) {
    struct data {
        bsc::input<bool> in;
    };
    using namespace cyc::turns;
    static constexpr auto chart = bsc::make_chart<data>(
        bsc::composite<cyc::Root>(bsc::initial<X>, bsc::parallel<Q>(bsc::composite<R1>(bsc::initial<Y>, bsc::state<W>),
                                                                    bsc::composite<R2>(bsc::initial<Z>))),
        bsc::state<X>[([](data const& d) { return d.in.get(); })] = bsc::state<Q>,
        bsc::state<Y>[([](data const& d) { return d.in.get(); })] = bsc::state<W>,
        bsc::state<Q> + bsc::event<cyc::kick> = bsc::state<X>, bsc::state<W> + bsc::event<cyc::kick> = bsc::state<Y>);
    machine_t<Backend, decltype(chart)> m{chart, data{}};
    m.context().in.set(true);
    auto const r = m.step(0ms);
    CHECK(r.transitions == 1);
    CHECK(m.template is<Y>());
    m.step(1ms);
    CHECK(m.template is<W>());
}

TEST_CASE_TEMPLATE("a component that an earlier component leaves during a cycle loses its turn", Backend, compiled,
                   table) {
    struct data {
        bsc::input<bool> leave;
        bsc::input<bool> go;
        int region_fired = 0;
    };
    using namespace cyc::turns;
    // The root's component takes its turn first; R1's comes after.
    static constexpr auto chart = bsc::make_chart<data>(
        bsc::composite<cyc::Root>(
            bsc::initial<Q>,
            bsc::parallel<Q>(bsc::composite<R1>(bsc::initial<Y>, bsc::state<W>), bsc::composite<R2>(bsc::initial<Z>)),
            bsc::state<X>),
        bsc::state<Q>[([](data const& d) { return d.leave.get(); })] = bsc::state<X>,
        bsc::state<Y>[([](data const& d) { return d.go.get(); })] / [](data& d) { ++d.region_fired; } = bsc::state<W>,
        bsc::state<X> + bsc::event<cyc::kick> = bsc::state<Q>);
    machine_t<Backend, decltype(chart)> m{chart, data{}};
    REQUIRE(m.template is<Y>());

    // R1 was active when the cycle began and its transition is enabled, but the root's
    // component has left Q when R1's turn comes.
    m.context().leave.set(true);
    m.context().go.set(true);
    auto const left = m.step(0ms);
    CHECK(left.transitions == 1);
    CHECK(m.template is<X>());
    CHECK(m.context().region_fired == 0);

    // The twin: Q stays, and R1 takes its turn.
    m.context().leave.set(false);
    m.context().go.set(false);
    m.dispatch(cyc::kick{});
    REQUIRE(m.template is<Y>());
    m.context().go.set(true);
    auto const stayed = m.step(1ms);
    CHECK(stayed.transitions == 1);
    CHECK(m.template is<W>());
    CHECK(m.context().region_fired == 1);
}

TEST_CASE_TEMPLATE("events raised in a cycle are processed at its end, before the outputs are committed", Backend,
                   compiled, table) {
    struct ping {};
    struct io {
        bsc::output<int> out;
        int got = 0;
    };
    struct S;
    struct T;
    static constexpr auto chart = bsc::make_chart<io>(
        bsc::composite<cyc::Root>(bsc::initial<S>, bsc::state<T>), bsc::state<S> / bsc::raise(ping{}) = bsc::state<T>,
        bsc::state<T> + bsc::event<ping> / [](io& x) { x.out.set(x.got = 9); },
        bsc::state<T> + bsc::event<cyc::kick> = bsc::state<S>);
    machine_t<Backend, decltype(chart)> m{chart, io{}};  // construction settles S -> T and processes ping
    CHECK(m.context().out.get() == 9);
    m.dispatch(cyc::kick{});  // back to S, and the eventless S -> T follows at once
    CHECK(m.template is<T>());
}

namespace cyc {
struct A1;
struct A2;
struct B1;
struct B2;
struct CA;
struct CB;
struct Both;
struct flags {
    bool flag = false;
    int sets = 0;
};
inline constexpr auto set_flag = [](flags& c) {
    c.flag = true;
    ++c.sets;
};
inline constexpr auto clear_flag = [](flags& c) { c.flag = false; };
inline constexpr auto unset = bsc::guard([](flags const& c) { return !c.flag; });
inline constexpr auto is_set = bsc::guard([](flags const& c) { return c.flag; });
// Two components that keep answering each other, as a PLC scan loop does by design.
inline constexpr auto ping_pong = bsc::make_chart<flags>(
    bsc::parallel<Both>(bsc::composite<CA>(bsc::initial<A1>, bsc::state<A2>),
                        bsc::composite<CB>(bsc::initial<B1>, bsc::state<B2>)),
    bsc::state<A1>[unset] / set_flag = bsc::state<A2>, bsc::state<A2>[unset] / set_flag = bsc::state<A1>,
    bsc::state<B1>[is_set] / clear_flag = bsc::state<B2>, bsc::state<B2>[is_set] / clear_flag = bsc::state<B1>,
    bsc::state<Both> + bsc::event<kick> / [](flags& c) { c.sets = 0; });
}  // namespace cyc

TEST_CASE_TEMPLATE("with bsc::scan_policy, eventless transitions run only in step, one per component per cycle",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(cyc::ping_pong), bsc::scan_policy> m{cyc::ping_pong, cyc::flags{}};
    CHECK(m.last_outcome() == bsc::outcome::ignored);  // construction settles nothing
    CHECK(m.active_states().joined() == "Both CA A1 CB B1");
    CHECK(m.dispatch(cyc::kick{}) == bsc::outcome::consumed);  // nor does dispatch
    CHECK(m.active_states().joined() == "Both CA A1 CB B1");
    auto const r = m.step(0ms);  // CA sets the flag, CB (after it) sees it and clears it
    CHECK(r.transitions == 2);
    CHECK(m.active_states().joined() == "Both CA A2 CB B2");
    CHECK(m.context().sets == 1);

    // The same chart under the default (SCXML) policy settles at construction, and here never can.
    machine_t<Backend, decltype(cyc::ping_pong)> settling{cyc::ping_pong, cyc::flags{}};
    CHECK(settling.last_outcome() == bsc::outcome::livelock);
}

namespace cyc {
struct S;
struct T;
struct U;
struct F;
struct ping {};
struct io {
    bsc::output<int> out;
    int got = 0;
    bsc::input<bool> done;
};
// S -> T in a cycle raises ping; T's eventless transition to U is enabled once ping is handled.
inline constexpr auto raiser = bsc::make_chart<io>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<T>, bsc::state<U>, bsc::final_state<F>),
    bsc::state<S>[([](io const&) { return true; })] / bsc::raise(ping{}) = bsc::state<T>,
    bsc::state<T> + bsc::event<ping> / [](io& x) { x.out.set(x.got = 9); },
    bsc::state<T>[([](io const& x) { return x.got == 9; })] = bsc::state<U>,
    bsc::state<U>[([](io const& x) { return x.done.get(); })] = bsc::state<F>,
    bsc::state<U> + bsc::event<kick> = bsc::state<S>);
}  // namespace cyc

TEST_CASE_TEMPLATE("a cycle processes its raised events without settling, then commits the outputs", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::raiser), bsc::scan_policy> m{cyc::raiser, cyc::io{}};
    CHECK(m.template is<cyc::S>());
    auto const r = m.step(0ms);
    CHECK(r.status == bsc::outcome::consumed);
    CHECK(r.transitions == 1);
    CHECK(m.context().out.get() == 9);  // ping handled in the cycle, the output published after it
    CHECK(m.template is<cyc::T>());     // T -> U waits for the next cycle
    CHECK(m.step(1ms).transitions == 1);
    CHECK(m.template is<cyc::U>());
    CHECK(m.step(2ms).status == bsc::outcome::ignored);
}

TEST_CASE_TEMPLATE("a halted machine's cycle runs nothing, leaves the clock and reports halted", Backend, compiled,
                   table) {
    machine_t<Backend, decltype(cyc::raiser), bsc::scan_policy> m{cyc::raiser, cyc::io{}};
    m.step(0ms);
    m.step(1ms);
    m.context().done.set(true);
    CHECK(m.step(2ms).transitions == 1);
    CHECK(m.halted());
    auto const r = m.step(5ms);
    CHECK(r.status == bsc::outcome::halted);
    CHECK(r.transitions == 0);
    CHECK(m.now() == 2ms);
    CHECK(m.last_outcome() == bsc::outcome::halted);
}

namespace cyc {
struct Q;
struct Q1;
struct Q2;
struct Z;
struct order_data {
    bsc::input<bool> ready;
    bsc::input<int> counted;  // the timeouts that the first row does not count (set by the test)
    int timeouts = 0;
};
// Q1 has a timeout declared between two eventless transitions; Q, its parent, a longer one.
inline constexpr auto competing = bsc::make_chart<order_data>(
    bsc::composite<Root>(bsc::initial<Q>, bsc::composite<Q>(bsc::initial<Q1>, bsc::state<Q2>), bsc::state<Z>),
    bsc::state<Q1>[([](order_data const& d) { return d.ready.get() && d.timeouts > d.counted.get(); })] = bsc::state<Z>,
    bsc::state<Q1> + bsc::after(100ms) / [](order_data& d) { ++d.timeouts; },  // internal: re-armed when it fires
    bsc::state<Q1>[([](order_data const& d) { return d.ready.get(); })] = bsc::state<Q2>,
    bsc::state<Q> + bsc::after(150ms) = bsc::state<Z>, bsc::state<Z> + bsc::event<kick> = bsc::state<Q>);

struct row_log {  // the rows of the transitions fired, how many received bsc::eventless, and the timeouts' delays
    std::array<int, 16> rows{};
    std::size_t calls = 0;
    int eventless = 0;
    std::vector<bsc::duration> timeouts;
    void on_row(int row) { rows[calls++ % rows.size()] = row; }
    template <class Src, class Dst, class E>
    void on_transition(Src, Dst, E const& e) {
        eventless += std::is_same_v<E, bsc::eventless>;
        if constexpr (std::is_same_v<E, bsc::timeout_elapsed>) timeouts.push_back(e.delay);
    }
};
}  // namespace cyc

TEST_CASE_TEMPLATE(
    "a timeout competes with its state's eventless transitions in declaration order, deepest state first", Backend,
    compiled, table) {
    using cyc::Q1, cyc::Q2, cyc::Z;
    machine_t<Backend, decltype(cyc::competing), bsc::default_policy, cyc::row_log> m{cyc::competing, cyc::order_data{},
                                                                                      cyc::row_log{}};
    auto const& d = m.context();
    m.step(0ms);
    CHECK(m.step(99ms).status == bsc::outcome::ignored);
    CHECK(m.step(100ms).transitions == 1);  // Q1's timeout, internal: Q1 stays, re-armed at 100 ms
    CHECK(m.step(110ms).transitions == 0);  // so it is not due again before 200 ms
    m.step(200ms);                          // Q's timeout (150 ms) is due too: the deeper state's wins
    CHECK(d.timeouts == 2);
    CHECK(m.template is<Q1>());
    d.counted.set(d.timeouts);  // the first row counts the timeouts from here
    d.ready.set(true);
    m.step(300ms);  // the timeout is declared before Q1 [ready]: it wins
    CHECK(d.timeouts - d.counted.get() == 1);
    CHECK(m.template is<Q1>());
    m.step(310ms);  // Q1 [ready && timeouts > counted], declared before the timeout
    CHECK(m.template is<Z>());
    d.ready.set(false);
    m.dispatch(cyc::kick{});  // Q and Q1 armed at 310 ms
    d.ready.set(true);
    d.counted.set(d.timeouts);
    m.step(320ms);  // the timeout is not due: Q1 [ready]
    CHECK(m.template is<Q2>());
    m.step(459ms);
    CHECK(m.template is<Q2>());
    m.step(460ms);  // Q's timeout, 150 ms after Q was entered
    CHECK(m.template is<Z>());
    auto const& log = m.observer();
    REQUIRE(log.calls == 7);
    CHECK(log.eventless == 2);  // the eventless rows 0 and 2; the timeouts receive their delay
    CHECK(log.timeouts == std::vector<bsc::duration>{100ms, 100ms, 100ms, 150ms});
    int const expected[] = {1, 1, 1, 0, 4, 2, 3};  // rows in make_chart's order
    for (std::size_t i = 0; i < 7; ++i) CHECK(log.rows[i] == expected[i]);
}

// ---- several timeouts of one state due at once ----------------------------------------------
// Among the timeout rows of one state that are due in a cycle and whose guards hold, the one that
// came due first fires; at equal due times, the one armed first; then declaration order
// (docs/semantics.md, "Timers").

namespace due {
struct Root;
struct S;
struct Left;
struct kick {};
struct allow {};
struct log_data {
    std::string fired;  // one letter per row fired
    bool allow = false;
};
template <char Letter>
inline constexpr auto note = [](log_data& d) { d.fired += Letter; };
inline constexpr auto allowed = [](log_data const& d) { return d.allow; };
inline constexpr auto let = [](log_data& d) { d.allow = true; };

// An internal 1 s timeout declared before a leaving 3 s one: both come due at 3 s, and the
// leaving one, counting from S's entry, was armed first.
inline constexpr auto ticking_then_leaving = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<Left>), bsc::state<S> + bsc::after(1s) / note<'i'>,
    bsc::state<S> + bsc::after(3s) / note<'L'> = bsc::state<Left>, bsc::state<Left> + bsc::event<kick> = bsc::state<S>);

// The same with delays of zero.
inline constexpr auto zero_delays = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<Left>), bsc::state<S> + bsc::after(0s) / note<'i'>,
    bsc::state<S> + bsc::after(0s) / note<'L'> = bsc::state<Left>, bsc::state<Left> + bsc::event<kick> = bsc::state<S>);

// Two internal timeouts of equal delay.
inline constexpr auto twins = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<Left>), bsc::state<S> + bsc::after(1s) / note<'a'>,
    bsc::state<S> + bsc::after(1s) / note<'b'>, bsc::state<S> + bsc::event<kick> = bsc::state<Left>,
    bsc::state<Left> + bsc::event<kick> = bsc::state<S>);

// A leaving timeout declared before a guarded one that comes due earlier.
inline constexpr auto guarded_earlier = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<Left>),
    bsc::state<S> + bsc::after(3s) / note<'L'> = bsc::state<Left>, bsc::state<S> + bsc::after(1s)[allowed] / note<'g'>,
    bsc::state<Left> + bsc::event<kick> = bsc::state<S>);

// A longer internal timeout declared before a shorter one, with an eventless row between them.
inline constexpr auto longer_first = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<Left>), bsc::state<S> + bsc::after(2s) / note<'l'>,
    bsc::state<S>[allowed] / note<'e'> = bsc::state<Left>, bsc::state<S> + bsc::after(1s) / note<'s'>,
    bsc::state<Left> + bsc::event<kick> = bsc::state<S>, bsc::state<Root> + bsc::event<allow> / let);

struct delays {  // the delays the observer sees, in the order the timeouts fired
    std::vector<bsc::duration> fired;
    template <class Src, class Dst, class E>
    void on_transition(Src, Dst, E const& e) {
        if constexpr (std::is_same_v<E, bsc::timeout_elapsed>) fired.push_back(e.delay);
    }
};

// A local timeout (its target inside its state, which stays active) before a leaving one.
struct Busy;
struct Step;
inline constexpr auto local_then_leaving = bsc::make_chart<log_data>(
    bsc::composite<Root>(bsc::initial<Busy>, bsc::composite<Busy>(bsc::initial<Step>, bsc::state<Step>),
                         bsc::state<Left>),
    bsc::state<Busy> + bsc::after(1s) / note<'l'> = bsc::local(bsc::state<Step>),
    bsc::state<Busy> + bsc::after(3500ms) / note<'L'> = bsc::state<Left>,
    bsc::state<Left> + bsc::event<kick> = bsc::state<Busy>);
}  // namespace due

TEST_CASE_TEMPLATE("a local timeout re-arms, and its state's other timeouts keep counting", Backend, compiled, table) {
    machine_t<Backend, decltype(due::local_then_leaving), bsc::scan_policy> m{due::local_then_leaving, due::log_data{}};
    for (auto t = 0ms; t <= 3s; t += 500ms) m.step(t);
    CHECK(m.context().fired == "lll");  // once a second, not once a cycle after the first second
    CHECK(m.template is<due::Step>());
    m.step(4s);  // Busy's 3.5 s timeout, which the local one did not restart, came due first
    CHECK(m.context().fired == "lllL");
    CHECK(m.template is<due::Left>());
}

TEST_CASE_TEMPLATE(
    "of a state's timeouts due together, the one that came due first fires: a shorter internal "
    "timeout does not starve a longer one",
    Backend, compiled, table) {
    SUBCASE("scanned every second: the leaving timeout fires at 3 s") {
        machine_t<Backend, decltype(due::ticking_then_leaving), bsc::scan_policy, due::delays> m{
            due::ticking_then_leaving, due::log_data{}, due::delays{}};
        for (auto t = 0s; t <= 3s; t += 1s) m.step(t);
        // At 3 s the internal one (armed at 2 s) and the leaving one (armed at 0) are both due
        // at 3 s: the one armed first fires.
        CHECK(m.context().fired == "iiL");
        CHECK(m.template is<due::Left>());
        CHECK(m.observer().fired == std::vector<bsc::duration>{1s, 1s, 3s});
    }
    SUBCASE("scanned every 100 ms: the same") {
        machine_t<Backend, decltype(due::ticking_then_leaving), bsc::scan_policy> m{due::ticking_then_leaving,
                                                                                    due::log_data{}};
        for (auto t = 0ms; t < 3s; t += 100ms) m.step(t);
        CHECK(m.context().fired == "ii");
        m.step(3s);
        CHECK(m.context().fired == "iiL");
        CHECK(m.template is<due::Left>());
    }
    SUBCASE("a jump past both: the internal one came due first (at 1 s), the leaving one follows") {
        machine_t<Backend, decltype(due::ticking_then_leaving), bsc::scan_policy> m{due::ticking_then_leaving,
                                                                                    due::log_data{}};
        m.step(0s);
        m.step(10s);
        CHECK(m.context().fired == "i");  // re-armed at 10 s: not due before 11 s
        m.step(10s);
        CHECK(m.context().fired == "iL");
        CHECK(m.template is<due::Left>());
    }
}

TEST_CASE_TEMPLATE("of two timeouts of delay zero, internal and leaving, the leaving one fires once time advances",
                   Backend, compiled, table) {
    machine_t<Backend, decltype(due::zero_delays), bsc::scan_policy> m{due::zero_delays, due::log_data{}};
    m.step(0ms);  // both due at 0, armed at 0: declaration order
    CHECK(m.context().fired == "i");
    m.step(10ms);  // the internal one re-armed at 0, the cycle it fired in: equal again
    CHECK(m.context().fired == "ii");
    m.step(20ms);  // the internal one is due at 10 ms, the leaving one since 0
    CHECK(m.context().fired == "iiL");
    CHECK(m.template is<due::Left>());
}

TEST_CASE_TEMPLATE("two internal timeouts of equal delay take turns", Backend, compiled, table) {
    SUBCASE("scanned every period") {
        machine_t<Backend, decltype(due::twins), bsc::scan_policy> m{due::twins, due::log_data{}};
        for (auto t = 0s; t <= 6s; t += 1s) m.step(t);
        CHECK(m.context().fired == "ababab");
    }
    SUBCASE("a jump: each fires once, the one armed first before the other") {
        machine_t<Backend, decltype(due::twins), bsc::scan_policy> m{due::twins, due::log_data{}};
        m.step(0s);
        m.step(10s);  // both due at 1 s, armed at 0: declaration order
        m.step(10s);  // b, due at 1 s, before a, now due at 11 s
        m.step(10s);
        CHECK(m.context().fired == "ab");
        m.step(11s);  // both due at 11 s, armed at 10 s: declaration order again
        CHECK(m.context().fired == "aba");
        m.step(11s);
        CHECK(m.context().fired == "abab");
    }
}

TEST_CASE_TEMPLATE("a timeout that came due first but whose guard is false does not hold back a later one", Backend,
                   compiled, table) {
    SUBCASE("the guard false: the leaving timeout fires when due") {
        machine_t<Backend, decltype(due::guarded_earlier), bsc::scan_policy> m{due::guarded_earlier, due::log_data{}};
        for (auto t = 0s; t <= 3s; t += 1s) m.step(t);
        CHECK(m.context().fired == "L");
        CHECK(m.template is<due::Left>());
    }
    SUBCASE("the guard true, a jump: the guarded one, due since 1 s, fires first, declared second") {
        machine_t<Backend, decltype(due::guarded_earlier), bsc::scan_policy> m{due::guarded_earlier,
                                                                               due::log_data{"", true}};
        m.step(0s);
        m.step(5s);
        CHECK(m.context().fired == "g");
        CHECK(m.template is<due::S>());
        m.step(5s);  // re-armed at 5 s; the leaving one is due since 3 s
        CHECK(m.context().fired == "gL");
        CHECK(m.template is<due::Left>());
    }
    SUBCASE("the guard true, scanned every second: at 3 s the leaving one was armed first") {
        machine_t<Backend, decltype(due::guarded_earlier), bsc::scan_policy> m{due::guarded_earlier,
                                                                               due::log_data{"", true}};
        for (auto t = 0s; t <= 3s; t += 1s) m.step(t);
        CHECK(m.context().fired == "ggL");
        CHECK(m.template is<due::Left>());
    }
}

TEST_CASE_TEMPLATE(
    "a longer timeout declared first yields to a shorter one due earlier; eventless rows keep their "
    "place in declaration order",
    Backend, compiled, table) {
    SUBCASE("a jump past both: the shorter fires, then the longer") {
        machine_t<Backend, decltype(due::longer_first), bsc::scan_policy> m{due::longer_first, due::log_data{}};
        m.step(0s);
        m.step(5s);
        CHECK(m.context().fired == "s");
        m.step(5s);
        CHECK(m.context().fired == "sl");
        m.step(5s);  // neither is due: the shorter one at 6 s, the longer one at 7 s
        CHECK(m.context().fired == "sl");
    }
    SUBCASE("the eventless row, declared before the shorter timeout, wins over it") {
        machine_t<Backend, decltype(due::longer_first), bsc::scan_policy> m{due::longer_first, due::log_data{}};
        m.step(0s);
        m.dispatch(due::allow{});
        m.step(1s);  // the longer timeout is not due; the eventless row comes before the shorter one
        CHECK(m.context().fired == "e");
        CHECK(m.template is<due::Left>());
    }
    SUBCASE("once the longer timeout, declared before the eventless row, is due, the timeouts go first") {
        machine_t<Backend, decltype(due::longer_first), bsc::scan_policy> m{due::longer_first, due::log_data{}};
        m.step(0s);
        m.dispatch(due::allow{});
        m.step(5s);  // the longer timeout holds: of the state's timeouts, the one that came due first fires
        CHECK(m.context().fired == "s");
        CHECK(m.template is<due::S>());
        m.step(5s);
        CHECK(m.context().fired == "sl");
        m.step(5s);  // no timeout holds: the eventless row
        CHECK(m.context().fired == "sle");
        CHECK(m.template is<due::Left>());
    }
}

TEST_CASE("channels compare by value: pending and latched (inputs), published and next (outputs)") {
    static_assert(bsc::input<int>{3} == bsc::input<int>{3});
    static_assert(!(bsc::output<int>{3} == bsc::output<int>{4}));
    bsc::input<int> a{1}, b{1};
    CHECK(a == b);
    std::as_const(a).set(2);  // as the environment sets an input: through a const view
    CHECK_FALSE(a == b);      // the same latched value, a different pending one
    std::as_const(b).set(2);
    CHECK(a == b);
    bsc::inout<int> x{5}, y{5};
    x.set(6);
    CHECK_FALSE(x == y);
}
