// The BSC execution cycle (docs/semantics.md, "The execution cycle"): channels, variables,
// components, BSC timers and state-scoped timeouts.

#include <doctest/doctest.h>

#include <chrono>

#include <bsc/bsc.hpp>

using namespace std::chrono_literals;

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
    bsc::composite<Root>(bsc::initial<P>,
                         bsc::parallel<P>(bsc::composite<C1>(bsc::initial<Idle1>, bsc::state<Busy1>),
                                          bsc::composite<C2>(bsc::initial<Idle2>, bsc::state<Busy2>),
                                          bsc::composite<C3>(bsc::initial<Idle3>, bsc::state<Busy3>))),
    bsc::state<Idle1>[([](plant const& p) { return p.start.get(); })] / [](plant& p) {
        p.var = 1;
        p.lamp.set(7);
    } = bsc::state<Busy1>,
    bsc::state<Busy1>[([](plant const& p) { return !p.start.get(); })] = bsc::state<Idle1>,
    bsc::state<Idle2>[([](plant const& p) { return p.var == 1; })] / [](plant& p) {
        p.seen_lamp = p.lamp.get();  // published value: still the old one during the cycle
        p.seen_var = p.var;
    } = bsc::state<Busy2>,
    bsc::state<Busy2>[([](plant const& p) { return p.var == 0; })] = bsc::state<Idle2>,
    bsc::state<Idle3>[([](plant const& p) { return p.var == 2; })] = bsc::state<Busy3>,
    bsc::state<Busy3>[([](plant const& p) { return p.var == 0; })] = bsc::state<Idle3>,
    bsc::state<Busy2> + bsc::event<kick> / [](plant& p) { p.var = 2; });
}  // namespace cyc

TEST_CASE("inputs written between cycles are latched at the start of the next cycle") {
    bsc::machine m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    CHECK_FALSE(m.context().start.get());  // not yet latched
    CHECK(m.context().start.pending());
    auto const r = m.step(0ms);
    CHECK(m.context().start.get());
    CHECK(m.is<cyc::Busy1>());
    CHECK(r.transitions == 2);  // C1, then C2 which sees C1's variable at once
}

TEST_CASE("a variable written by a component is visible at once to the components after it") {
    bsc::machine m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    CHECK(m.is<cyc::Busy2>());
    CHECK(m.context().seen_var == 1);
}

TEST_CASE("outputs are double-buffered: published at the end of the cycle") {
    bsc::machine m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    CHECK(m.context().seen_lamp == 0);  // C2 read the published value during the cycle
    CHECK(m.context().lamp.get() == 7);  // published after it
}

TEST_CASE("each component fires at most one transition per cycle, in declaration order") {
    bsc::machine m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    m.context().start.set(false);
    auto const r = m.step(1ms);  // C1 goes back to Idle1; C2 and C3 see no change of var
    CHECK(r.transitions == 1);
    CHECK(m.is<cyc::Idle1>());
    CHECK(m.is<cyc::Busy2>());
}

TEST_CASE("dispatch settles eventless transitions at once, whatever the cycle rules") {
    bsc::machine m{cyc::chart, cyc::plant{}};
    m.context().start.set(true);
    m.step(0ms);
    m.dispatch(cyc::kick{});  // var = 2: C3's eventless transition follows within the dispatch
    CHECK(m.is<cyc::Busy3>());
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

TEST_CASE("a state-scoped timeout fires at the first cycle at or after its delay, armed on entry") {
    bsc::machine m{cyc::chain, cyc::chain_data{}};
    m.step(0ms);
    m.step(50ms);
    m.dispatch(cyc::kick{});  // enters B at the machine's time, 50 ms
    CHECK(m.is<cyc::B>());
    m.step(100ms);
    CHECK(m.is<cyc::B>());   // 50 ms in B
    m.step(149ms);
    CHECK(m.is<cyc::B>());
    m.step(150ms);           // 100 ms in B
    CHECK(m.is<cyc::C>());   // entered at 150 ms
    m.step(200ms);
    CHECK(m.is<cyc::C>());
    m.step(250ms);
    CHECK(m.is<cyc::D>());
}

TEST_CASE("a jump of many periods takes one transition per component, not the missed cycles") {
    bsc::machine m{cyc::chain, cyc::chain_data{}};
    m.dispatch(cyc::kick{});
    auto const r = m.step(10s);
    CHECK(r.transitions == 1);
    CHECK(m.is<cyc::C>());  // C's timeout is armed at 10 s
    m.step(10s);
    CHECK(m.is<cyc::C>());
    m.step(10s + 100ms);
    CHECK(m.is<cyc::D>());
}

TEST_CASE("time never runs backwards for the machine: an earlier time is reported and ignored") {
    bsc::machine m{cyc::chain, cyc::chain_data{}};
    m.step(1s);
    m.dispatch(cyc::kick{});  // B armed at 1 s
    auto const r = m.step(500ms);
    CHECK(r.clock_went_backwards);
    CHECK(m.now() == 1s);
    CHECK(m.is<cyc::B>());
    CHECK_FALSE(m.step(1050ms).clock_went_backwards);
    CHECK(m.is<cyc::B>());
    m.step(1100ms);
    CHECK(m.is<cyc::C>());
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
    bsc::state<Off>[([](drill_data const& d) { return d.piece.get(); })] / [](drill_data& d) {
        d.motor.set(true);
        d.t1.start();
    } = bsc::state<On>,
    bsc::state<On>[([](drill_data const& d) { return d.t1.tm(); })] / [](drill_data& d) {
        d.motor.set(false);
        d.t1.reset();
    } = bsc::state<Off>);
}  // namespace cyc

TEST_CASE("a BSC timer starts timing at the cycle after start() and expires at the first cycle at its limit") {
    bsc::machine m{cyc::drill, cyc::drill_data{}};
    m.context().piece.set(true);
    m.step(0ms);  // cycle 0: start() requested
    CHECK(m.is<cyc::On>());
    CHECK(m.context().motor.get());
    CHECK_FALSE(m.context().t1.running());
    m.context().piece.set(false);
    m.step(100ms);  // cycle 1: timing begins (t = 100 ms)
    CHECK(m.context().t1.running());
    m.step(200ms);
    m.step(300ms);
    CHECK_FALSE(m.context().t1.tm());
    CHECK(m.is<cyc::On>());
    m.step(399ms);
    CHECK(m.is<cyc::On>());
    m.step(400ms);  // 300 ms after timing began: tm, and the guard sees it in this cycle
    CHECK(m.is<cyc::Off>());
    CHECK_FALSE(m.context().motor.get());
    CHECK_FALSE(m.context().t1.tm());  // reset by the action
}

TEST_CASE("dispatch latches inputs at its start and commits outputs at its end") {
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
        bsc::state<S> + bsc::event<go> / [](io& x) {
            x.seen = x.in.get();
            x.out.set(x.in.get() * 2);
        },
        bsc::state<S> + bsc::event<cyc::kick> = bsc::state<T>, bsc::state<T> + bsc::event<cyc::kick> = bsc::state<S>);
    bsc::machine m{chart, io{}};
    m.context().in.set(21);
    m.dispatch(go{});
    CHECK(m.context().seen == 21);
    CHECK(m.context().out.get() == 42);
}

TEST_CASE("an inout channel is read as latched and written for the next cycle") {
    bsc::inout<int> ch{1};
    ch.set(5);
    CHECK(ch.get() == 1);
    ch.commit();
    CHECK(ch.get() == 5);
    ch.set(6);
    ch.latch();
    CHECK(ch.get() == 6);
}

TEST_CASE("components entered during a cycle first run in the next cycle") {
    struct data {
        bool in = false;
    };
    struct Q;
    struct R1;
    struct R2;
    struct X;
    struct Y;
    struct Z;
    struct W;
    static constexpr auto chart = bsc::make_chart<data>(
        bsc::composite<cyc::Root>(bsc::initial<X>,
                                  bsc::parallel<Q>(bsc::composite<R1>(bsc::initial<Y>, bsc::state<W>),
                                                   bsc::composite<R2>(bsc::initial<Z>))),
        bsc::state<X>[([](data const& d) { return d.in; })] = bsc::state<Q>,
        bsc::state<Y>[([](data const& d) { return d.in; })] = bsc::state<W>,
        bsc::state<Q> + bsc::event<cyc::kick> = bsc::state<X>, bsc::state<W> + bsc::event<cyc::kick> = bsc::state<Y>);
    bsc::machine m{chart, data{}};
    m.context().in = true;
    auto const r = m.step(0ms);
    CHECK(r.transitions == 1);
    CHECK(m.is<Y>());
    m.step(1ms);
    CHECK(m.is<W>());
}

TEST_CASE("events raised in a cycle are processed at its end, before the outputs are committed") {
    struct ping {};
    struct io {
        bsc::output<int> out;
        int got = 0;
    };
    struct S;
    struct T;
    static constexpr auto chart = bsc::make_chart<io>(
        bsc::composite<cyc::Root>(bsc::initial<S>, bsc::state<T>),
        bsc::state<S> / bsc::raise(ping{}) = bsc::state<T>,
        bsc::state<T> + bsc::event<ping> / [](io& x) { x.out.set(x.got = 9); },
        bsc::state<T> + bsc::event<cyc::kick> = bsc::state<S>);
    bsc::machine m{chart, io{}};  // construction settles S -> T and processes ping
    CHECK(m.context().out.get() == 9);
    m.dispatch(cyc::kick{});  // back to S, and the eventless S -> T follows at once
    CHECK(m.is<T>());
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

TEST_CASE("with bsc::scan_policy, eventless transitions run only in step, one per component per cycle") {
    bsc::machine<decltype(cyc::ping_pong), bsc::scan_policy> m{cyc::ping_pong, cyc::flags{}};
    CHECK(m.last_outcome() == bsc::outcome::ignored);  // construction settles nothing
    CHECK(m.active_states().joined() == "Both CA A1 CB B1");
    CHECK(m.dispatch(cyc::kick{}) == bsc::outcome::consumed);  // nor does dispatch
    CHECK(m.active_states().joined() == "Both CA A1 CB B1");
    auto const r = m.step(0ms);  // CA sets the flag, CB (after it) sees it and clears it
    CHECK(r.transitions == 2);
    CHECK(m.active_states().joined() == "Both CA A2 CB B2");
    CHECK(m.context().sets == 1);

    // The same chart under the default (SCXML) policy settles at construction, and here never can.
    bsc::machine settling{cyc::ping_pong, cyc::flags{}};
    CHECK(settling.last_outcome() == bsc::outcome::livelock);
}
