#pragma once
// Hand-written charts shared by the back-end equivalence tests (differential_test.cpp and
// tests/fuzz/differential_fuzz.cpp). Each fixture is a struct with
//   chart                    the chart
//   policy                   the limits it runs under
//   initial()                the context it starts from
//   perturb(context&, r)     a write between two dispatches or cycles: an input set as the
//                            environment sets it (through a const view), or a variable of the
//                            chart changed as no environment can (the harnesses pass the
//                            writable context, inside::context), to reach more states
// Their contexts keep a hash of every action, entry and exit in the order they ran, so a
// difference of order shows in the context as well as in the observer's trace.

#include <chrono>
#include <cstdint>
#include <utility>

#include <bsc/bsc.hpp>

#include "inside.hpp"

namespace fx {

struct go {};
struct back {};
struct tick {};
struct ping {};
struct pong {};
struct e1 {};
struct num {
    int n = 0;
};

struct ctx {
    int a = 0;
    int b = 0;
    int c = 0;
    std::uint32_t log = 0;  // the order of everything that ran
    friend constexpr bool operator==(ctx const&, ctx const&) = default;
};

constexpr std::uint32_t mix(std::uint32_t h, std::uint32_t v) { return (h ^ v) * 16777619u + 1u; }

/// An action (entry, exit or transition) that records `id` in the context's log.
template <int Id>
inline constexpr auto note = bsc::action([](ctx& c) { c.log = mix(c.log, Id); });

inline constexpr auto a_even = bsc::guard([](ctx const& c) { return c.a % 2 == 0; });
inline constexpr auto a_big = bsc::guard([](ctx const& c) { return c.a > 2; });
inline constexpr auto n_even = bsc::guard([](ctx const&, num const& e) { return e.n % 2 == 0; });
inline constexpr auto n_triple = bsc::guard([](ctx const&, num const& e) { return e.n % 3 == 0; });
inline constexpr auto add_n = bsc::action([](ctx& c, num const& e) {
    c.a = (c.a + e.n) % 8;
    c.log = mix(c.log, 100u + static_cast<std::uint32_t>(e.n));
});
inline constexpr auto inc_a = bsc::action([](ctx& c) { c.a = (c.a + 1) % 8; });
inline constexpr auto inc_b = bsc::action([](ctx& c) { c.b = (c.b + 1) % 8; });

inline void perturb_ab(ctx& c, std::uint32_t r) {
    if (r & 1u)
        c.a = static_cast<int>((r >> 1) % 8);
    else
        c.b = static_cast<int>((r >> 1) % 8);
}

// ---- hierarchy: nesting, domains, self transitions, transitions of the root, internal ones -----
namespace hier {
struct Root;
struct A;
struct A1;
struct A11;
struct A12;
struct A2;
struct B;
struct B1;
struct B2;
struct B21;
struct B22;
struct C;
}  // namespace hier

struct hierarchy {
    using policy = bsc::default_policy;
    static constexpr auto chart = [] {
        using namespace hier;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(
                bsc::initial<A>,
                bsc::composite<A>(bsc::initial<A1>, bsc::composite<A1>(bsc::initial<A11>, state<A12>), state<A2>),
                bsc::composite<B>(bsc::initial<B1>, state<B1>, bsc::composite<B2>(bsc::initial<B21>, state<B22>)),
                state<C>),
            state<A11> + event<go> = state<A12>, state<A12> + event<go> / note<1> = state<A2>,
            state<A2> + event<go> = state<B>, state<B1> + event<go> = state<B22>, state<B22> + event<go> = state<B21>,
            state<B21> + event<go> / note<2> = state<C>, state<C> + event<go> = state<A11>,
            state<A> + event<back> = state<B>,                    // an ancestor's transition
            state<A1> + event<back>[a_even] / inc_a = state<A1>,  // external self-transition of a composite
            state<B> + event<back> = state<A>, state<B2> + event<back> = state<B>,  // to an ancestor
            state<C> + event<back> = state<A2>,
            state<Root> + event<tick> = state<B2>,        // exits and re-enters the root
            state<A1> + event<tick>[a_big] = state<A12>,  // to a descendant
            state<C> + event<tick> / note<3> = state<C>,
            state<A> + event<ping> / note<4>,  // internal
            state<B2> + event<ping> / inc_a, state<Root> + event<ping> / inc_b,
            state<A12> + event<num>[n_even] / add_n = state<A11>, state<A12> + event<num>[n_triple] = state<B>,
            state<A> + event<num> / add_n, state<B22> + event<num>[n_even] / add_n = state<B1>,
            state<Root> + event<e1>[a_even] = state<Root>,  // the root re-enters itself
            state<Root> + on_entry / note<10>, state<Root> + on_exit / note<11>, state<A> + on_entry / note<12>,
            state<A> + on_exit / note<13>, state<A1> + on_entry / note<14>, state<A1> + on_exit / note<15>,
            state<A11> + on_entry / note<16>, state<A12> + on_exit / note<17>, state<B> + on_entry / note<18>,
            state<B> + on_exit / note<19>, state<B2> + on_entry / note<20>, state<B2> + on_exit / note<21>,
            state<B22> + on_entry / note<22>, state<C> + on_exit / note<23>, state<C> + on_entry / note<24>,
            state<C> + on_entry / note<25>);  // two entry actions: declaration order
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) { perturb_ab(c, r); }
};

// ---- parallel regions: broadcast, conflicts, preemption, nested parallel states ----------------
namespace par {
struct Root;
struct P;
struct R1;
struct R2;
struct X1;
struct X2;
struct Y1;
struct Y2;
struct Q;
struct Q1;
struct Z1;
struct Z2;
struct W;
struct Out;
}  // namespace par

struct parallel {
    using policy = bsc::default_policy;
    static constexpr auto chart = [] {
        using namespace par;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(
                bsc::initial<P>,
                bsc::parallel<P>(
                    bsc::composite<R1>(bsc::initial<X1>, state<X2>),
                    bsc::composite<R2>(bsc::initial<Y1>, state<Y2>,
                                       bsc::parallel<Q>(bsc::composite<Q1>(bsc::initial<Z1>, state<Z2>), state<W>))),
                state<Out>),
            state<X1> + event<go> = state<X2>, state<Y1> + event<go> = state<Y2>, state<X2> + event<back> = state<X1>,
            state<Y2> + event<back> = state<Y1>, state<P> + event<tick> = state<Out>,
            state<Out> + event<tick> = state<Y2>, state<X2> + event<ping> / note<1> = state<X1>,
            state<Y2> + event<ping> / note<2> = state<Out>, state<X2> + event<pong> / note<3> = state<Out>,
            state<Y2> + event<pong> / note<4> = state<Y1>, state<P> + event<e1> = state<Out>,
            state<Y2> + event<e1> = state<Y1>, state<X1> + event<e1> / note<5> = state<X2>,
            state<Y2> + event<num> / add_n,
            state<Y1> + event<tick>[a_even] = state<Q>,  // preempts P + tick when a is even
            state<Z1> + event<go> = state<Z2>, state<Z2> + event<go> = state<Z1>, state<W> + event<go> / note<6>,
            state<Q> + event<back> = state<Y1>, state<Z2> + event<pong> / note<7> = state<Out>,
            state<W> + event<e1> = state<Y2>, state<Z1> + event<num>[n_even] / add_n = state<Z2>,
            state<W> + event<num>[n_triple] / note<8> = state<W>, state<Out> + event<go> = state<P>,
            state<Out> + event<back> = state<X2>, state<Out> + event<num>[a_big] = state<Z2>,
            state<P> + event<num>[a_even] / inc_a,  // internal, from above both regions
            state<P> + on_entry / note<10>, state<P> + on_exit / note<11>, state<R1> + on_entry / note<12>,
            state<R2> + on_exit / note<13>, state<Q> + on_entry / note<14>, state<Q> + on_exit / note<15>,
            state<W> + on_entry / note<16>, state<Z2> + on_exit / note<17>, state<Out> + on_entry / note<18>,
            state<X2> + on_entry / note<19>, state<Y2> + on_exit / note<20>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) { perturb_ab(c, r); }
};

// ---- history: shallow and deep, nested, with explicit targets inside ----------------------------
namespace hist {
struct Root;
struct H;
struct H1;
struct K1;
struct K2;
struct L1;
struct L2;
struct H2;
struct M;
struct M1;
struct M2;
struct N;
struct N1;
struct N2;
struct S;
struct S1;
struct S2;
struct T1;
struct T2;
struct O;
}  // namespace hist

struct history {
    using policy = bsc::default_policy;
    static constexpr auto chart = [] {
        using namespace hist;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(bsc::initial<H>,
                                 bsc::composite<H>(bsc::deep_history, bsc::initial<H1>,
                                                   bsc::composite<H1>(bsc::shallow_history, bsc::initial<K1>,
                                                                      bsc::composite<K2>(bsc::initial<L1>, state<L2>)),
                                                   bsc::parallel<H2>(bsc::composite<M>(bsc::initial<M1>, state<M2>),
                                                                     bsc::composite<N>(bsc::shallow_history,
                                                                                       bsc::initial<N1>, state<N2>))),
                                 bsc::composite<S>(bsc::shallow_history, bsc::initial<S1>,
                                                   bsc::composite<S2>(bsc::initial<T1>, state<T2>)),
                                 state<O>),
            state<K1> + event<go> = state<K2>, state<L1> + event<go> = state<L2>, state<L2> + event<go> = state<K1>,
            state<H1> + event<tick> = state<H2>, state<M1> + event<go> = state<M2>, state<M2> + event<go> = state<M1>,
            state<N1> + event<tick> = state<N2>, state<N2> + event<tick> = state<H1>,
            state<H> + event<back> = state<S>,  // leave H: its history is kept
            state<S1> + event<go> = state<S2>, state<T1> + event<go> = state<T2>, state<T2> + event<go> = state<S1>,
            state<S> + event<back> = state<O>, state<O> + event<back> = state<H>,  // re-enter H by history
            state<O> + event<go> = state<S>,                                       // re-enter S by history
            state<O> + event<pong> = state<L2>,  // explicit targets inside history states win
            state<O> + event<e1> = state<N2>, state<O> + event<ping> = state<T2>, state<S> + event<tick> = state<H>,
            state<H2> + event<back>[a_even] = state<M2>, state<M> + event<ping> / inc_a = state<M>,
            state<N> + event<pong> = state<N>, state<K2> + event<e1> = state<O>,
            state<H1> + event<num>[n_even] / add_n = state<H1>, state<S2> + event<num>[n_triple] = state<T1>,
            state<H> + on_entry / note<10>, state<H> + on_exit / note<11>, state<H1> + on_entry / note<12>,
            state<K2> + on_entry / note<13>, state<L2> + on_exit / note<14>, state<H2> + on_entry / note<15>,
            state<N> + on_exit / note<16>, state<N2> + on_entry / note<17>, state<S> + on_entry / note<18>,
            state<T2> + on_entry / note<19>, state<O> + on_exit / note<20>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) { perturb_ab(c, r); }
};

// ---- guards over the context and eventless transitions ------------------------------------------
namespace cond {
struct Root;
struct A;
struct A1;
struct A2;
struct B;
struct C;
struct C1;
struct C2;
struct D;
}  // namespace cond

struct conditions {
    using policy = bsc::default_policy;
    static constexpr auto chart = [] {
        using namespace cond;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        auto const a_over_3 = bsc::guard([](ctx const& c) { return c.a > 3; });
        auto const b_odd = bsc::guard([](ctx const& c) { return c.b % 2 == 1; });
        auto const c_over_5 = bsc::guard([](ctx const& c) { return c.c > 5; });
        auto const n_positive = bsc::guard([](ctx const&, num const& e) { return e.n > 0; });
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, state<A2>), state<B>,
                                 bsc::composite<C>(bsc::initial<C1>, state<C2>), state<D>),
            state<A1>[a_over_3] / [](ctx& c) { c.a -= 2; } = state<A2>,  // eventless
            state<A2>[b_odd] / inc_b = state<B>, state<B> + event<num>[n_positive] / add_n = state<C>,
            state<B> + event<num> / inc_b,  // an internal transition after a guarded one
            state<C1> + event<go>[a_even] = state<C2>, state<C1> + event<go> = state<A>,
            state<C2>[c_over_5] / [](ctx& c) { c.c = 0; } = state<A1>,
            state<C2> + event<tick> / [](ctx& c) { c.c += 3; },
            state<C>[!a_even && a_big] = state<D>,  // eventless from a composite
            state<D> + event<go> / inc_a = state<B>, state<D>[b_odd && a_even] = state<A2>,
            state<A> + event<num> / add_n, state<A2> + event<go> = state<A1>, state<B> + event<go> = state<A>,
            state<A> + event<tick> / inc_b, state<B> + event<tick>[a_even] / inc_a = state<B>,
            state<A> + on_entry / note<10>, state<A> + on_exit / note<11>, state<B> + on_entry / note<12>,
            state<C2> + on_entry / note<13>, state<D> + on_exit / note<14>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) {
        if (r % 3 == 2)
            c.c = static_cast<int>((r >> 2) % 8);
        else
            perturb_ab(c, r);
    }
};

// ---- raised events, a small queue and low limits: overflow and livelock outcomes ---------------
namespace rais {
struct Root;
struct A;
struct B;
struct C;
struct C1;
struct C2;
}  // namespace rais

struct small_limits : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 3;
    static constexpr std::size_t max_eventless_steps = 5;
    static constexpr std::size_t max_internal_events = 12;
};

struct raising {
    using policy = small_limits;
    static constexpr auto chart = [] {
        using namespace rais;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        auto const a_is_7 = bsc::guard([](ctx const& c) { return c.a == 7; });
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(bsc::initial<A>, state<B>, bsc::composite<C>(bsc::initial<C1>, state<C2>)),
            state<A> + event<go> / (bsc::raise(ping{}), bsc::raise(pong{}), note<1>) = state<B>,
            state<B> + event<ping> / note<2> = state<C>, state<C> + event<pong> / bsc::seq(bsc::raise(back{}), note<3>),
            state<C> + event<back> = state<A>, state<B> + on_entry / bsc::raise(tick{}),
            state<C1> + event<tick> = state<C2>,
            state<C2> + event<tick>[a_even] / bsc::raise(tick{}),  // raises itself: stopped by the limit
            state<C2> + event<go> = state<C1>,
            state<A> + event<num>[([](ctx const&, num const& e) { return e.n > 3; })] /
                           [](ctx& c, num const& e, auto& raise) {
                               c.log = mix(c.log, static_cast<std::uint32_t>(e.n));
                               raise(num{e.n - 1});
                               raise(num{e.n - 2});  // the queue fills up: overflow
                           },
            state<A> + event<num> / inc_b, state<B> + event<num> / add_n, state<B> + event<back> = state<A>,
            state<A>[a_is_7] / inc_b = state<B>,  // a guarded eventless cycle while a == 7
            state<B>[a_is_7] / note<4> = state<A>, state<C> + event<e1> / bsc::raise(e1{}),  // raises itself
            state<A> + event<e1> = state<C2>, state<A> + on_entry / note<10>, state<A> + on_exit / note<11>,
            state<C> + on_entry / note<12>, state<C2> + on_exit / note<13>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) {
        if (r % 4 == 0)
            c.a = 7;
        else
            perturb_ab(c, r);
    }
};

// ---- a final child of the root: the machine halts ------------------------------------------------
namespace halt {
struct Root;
struct A;
struct B;
struct B1;
struct B2;
struct F;
}  // namespace halt

struct halting {
    using policy = bsc::default_policy;
    static constexpr auto chart = [] {
        using namespace halt;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(bsc::initial<A>, bsc::composite<B>(bsc::initial<B1>, state<B2>), bsc::final_state<F>),
            state<A> + event<go> = state<B>, state<B1> + event<go> = state<B2>,
            state<B2> + event<go>[a_big] / note<1> = state<F>, state<B2> + event<back> = state<A>,
            state<A> + event<tick> = state<B2>, state<B> + event<e1>[a_even] = state<F>, state<B1> + event<num> / add_n,
            state<B> + event<back> = state<A>, state<F> + on_entry / note<10>, state<B> + on_exit / note<11>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) { perturb_ab(c, r); }
};

// ---- beyond the core: a local transition, event families, any_event, done events, an initial
// action, a history state, deferred and delayed events, several targets -------------------------
namespace beyond {
// A family: a row on fam takes fam_a and fam_b; fam_b is named by no row (the twin dispatches
// it as one of the fixture's extra events, and an action raises it).
struct fam {
    int n = 0;
};
struct fam_a : fam {};
struct fam_b : fam_a {};
struct Root;
struct W;
struct W1;
struct W2;
struct WF;
struct P;
struct R1;
struct R2;
struct X1;
struct XF;
struct Y1;
struct YF;
struct C;
struct F;
struct WH;
struct D1;
struct D2;
struct D2a;
struct D2b;
struct D3;
struct XQ;
struct XQ1;
struct XQ2;
struct XQ1a;
struct XQ1b;
struct XQ2a;
struct XQ2b;
}  // namespace beyond

struct beyond_core {
    using policy = bsc::default_policy;
    using extra_events = inside::type_list<beyond::fam_b>;
    static constexpr auto chart = [] {
        using namespace beyond;
        using bsc::state, bsc::event, bsc::on_entry, bsc::on_exit;
        return bsc::make_chart<ctx>(
            bsc::composite<Root>(
                bsc::initial<W>,
                bsc::composite<W>(bsc::initial<W1>, bsc::deep_history_state<WH, W2>, state<W1>, state<W2>,
                                  bsc::final_state<WF>),
                bsc::parallel<P>(bsc::composite<R1>(bsc::initial<X1>, state<X1>, bsc::final_state<XF>),
                                 bsc::composite<R2>(bsc::initial<Y1>, state<Y1>, bsc::final_state<YF>)),
                state<C>, bsc::final_state<F>,
                // A deep initial, and one state in each region (initial<A, B>).
                bsc::composite<D1>(bsc::initial<D2b>, bsc::composite<D2>(bsc::initial<D2a>, state<D2a>, state<D2b>)),
                bsc::composite<D3>(
                    bsc::initial<XQ1b, XQ2b>,
                    bsc::parallel<XQ>(bsc::composite<XQ1>(bsc::initial<XQ1a>, state<XQ1a>, state<XQ1b>),
                                      bsc::composite<XQ2>(bsc::initial<XQ2a>, state<XQ2a>, state<XQ2b>)))),
            state<W1> + event<go> = state<W2>, state<W2> + event<go>[a_big] / note<1> = state<WF>,
            state<W> + event<back> / note<2> = bsc::local(state<W1>),
            state<W> + event<bsc::done<W>> / note<3> = state<P>, state<W2> + event<e1> / bsc::raise(fam_b{}),
            state<W2> + event<fam_a> / note<12> = state<C>, state<X1> + event<tick> = state<XF>,
            state<Y1> + event<ping> = state<YF>, state<R1> + event<bsc::done<R1>> / note<5>,
            state<P> + event<bsc::done<P>> / note<4> = state<C>, state<P> + event<back> = state<C>,
            state<C> + event<tick> / bsc::defer, state<W1> + event<tick>[a_even] / bsc::defer,
            state<C> + event<e1>[a_big] = bsc::targets(state<XF>, state<YF>), state<C> + event<back> = state<D1>,
            state<D2b> + event<go> = state<D2a>, state<D2a> + event<back> = state<D3>,
            state<D2a> + event<go> = state<C>, state<XQ1b> + event<go> = state<XQ1a>,
            state<XQ2b> + event<go> = state<XQ2a>, state<D3> + event<back> = state<C>,
            state<D1> + bsc::on_initial / note<17>, state<XQ2b> + on_entry / note<18>,
            state<W2> + event<pong> / bsc::raise_after(std::chrono::milliseconds{30}, ping{}, 2),
            state<W1> + event<pong> / bsc::cancel_delayed(2), state<C> + event<fam_a> / inc_b = state<W>,
            state<C> + event<fam> / note<6> = state<F>, state<C> + event<bsc::any_event>[a_even] / note<7>,
            state<C> + event<pong> = state<WH>, state<W> + bsc::on_initial / note<15>,
            state<WH> + bsc::on_initial / note<16>, state<F> + on_entry / note<8>, state<F> + on_exit / note<13>,
            state<W> + on_exit / note<9>, state<W> + on_entry / note<10>, state<P> + on_exit / note<11>,
            state<Root> + on_exit / note<14>);
    }();
    static ctx initial() { return {}; }
    static void perturb(ctx& c, std::uint32_t r) { perturb_ab(c, r); }
};

// ---- BSC execution cycles: components, timeouts, channels and a timer ------------------------------
namespace cyc {
struct Root;
struct P;
struct R1;
struct X1;
struct X2;
struct X3;
struct R2;
struct Y1;
struct Y2;
struct Y3;
struct Z;
struct Z1;
struct Z2;
struct W;
struct R3;
struct V1;
struct V2;
struct Out;
struct O1;
struct O2;
struct End;
}  // namespace cyc

/// Two channels hold the same values: the one read in this cycle and the one written for the next.
template <class Channel>
constexpr bool same_channel(Channel const& a, Channel const& b) {
    return a.get() == b.get() && a.pending() == b.pending();
}

/// A context with a variable of each kind the cycle treats differently: an input, an output
/// and an inout channel, a BSC timer, and plain variables.
struct cycle_ctx {
    bsc::input<int> in;
    bsc::output<int> out;
    bsc::inout<int> io;
    bsc::timer t{std::chrono::milliseconds{30}};
    int a = 0;
    int b = 0;
    std::uint32_t log = 0;
    // Channels have no == of their own: compared by the value read and the value written.
    friend constexpr bool operator==(cycle_ctx const& x, cycle_ctx const& y) {
        return same_channel(x.in, y.in) && same_channel(x.out, y.out) && same_channel(x.io, y.io) && x.t == y.t &&
               x.a == y.a && x.b == y.b && x.log == y.log;
    }
};

template <int Id>
inline constexpr auto cnote = bsc::action([](cycle_ctx& c) { c.log = mix(c.log, Id); });

/// A parallel state of three components, one holding a parallel state of its own (so that a
/// cycle may enter components, which wait for the next), next to a composite; eventless
/// transitions reading what earlier components wrote in the same cycle, the latched input and
/// the inout channel; timeouts on basic, composite and parallel states, internal ones (never
/// re-armed), guarded ones, ones competing with eventless transitions and several of one state
/// competing by due time; raised events; a final state. Under bsc::default_policy and under a
/// scan policy.
template <class Policy>
struct cycling {
    using policy = Policy;
    static constexpr auto chart = [] {
        using namespace cyc;
        using namespace std::chrono_literals;
        using bsc::state, bsc::event, bsc::after, bsc::on_entry, bsc::on_exit;
        auto const in_over_2 = bsc::guard([](cycle_ctx const& c) { return c.in.get() > 2; });
        auto const in_is_7 = bsc::guard([](cycle_ctx const& c) { return c.in.get() == 7; });
        auto const io_over_3 = bsc::guard([](cycle_ctx const& c) { return c.io.get() > 3; });
        auto const expired = bsc::guard([](cycle_ctx const& c) { return c.t.tm(); });
        auto const a_over_2 = bsc::guard([](cycle_ctx const& c) { return c.a > 2; });
        auto const a_even_c = bsc::guard([](cycle_ctx const& c) { return c.a % 2 == 0; });
        auto const b_odd = bsc::guard([](cycle_ctx const& c) { return c.b % 2 == 1; });
        auto const a_is_7 = bsc::guard([](cycle_ctx const& c) { return c.a == 7; });
        auto const inc_a_c = bsc::action([](cycle_ctx& c) { c.a = (c.a + 1) % 8; });
        auto const inc_b_c = bsc::action([](cycle_ctx& c) { c.b = (c.b + 1) % 8; });
        return bsc::make_chart<cycle_ctx>(
            bsc::composite<Root>(
                bsc::initial<P>,
                bsc::parallel<P>(
                    bsc::composite<R1>(bsc::initial<X1>, state<X2>, state<X3>),
                    bsc::composite<R2>(bsc::shallow_history, bsc::initial<Y1>, state<Y2>,
                                       bsc::parallel<Y3>(bsc::composite<Z>(bsc::initial<Z1>, state<Z2>), state<W>)),
                    bsc::composite<R3>(bsc::initial<V1>, state<V2>)),
                bsc::composite<Out>(bsc::initial<O1>, state<O2>), bsc::final_state<End>),
            // R1: the input, a timer started by an action, a timeout competing with an eventless one.
            state<X1>[in_over_2] /
                [](cycle_ctx& c) {
                    c.out.set(c.in.get());
                    c.a = (c.a + 1) % 8;
                } = state<X2>,
            state<X2> + after(20ms) / [](cycle_ctx& c) { c.t.start(); } = state<X3>,
            state<X3>[expired] / ([](cycle_ctx& c) { c.t.reset(); }, cnote<1>) = state<X1>,
            state<X3> + after(45ms) / cnote<2> = state<X1>,
            state<R1> + after(300ms)[a_even_c] / inc_b_c,  // internal, on a component's root
            // R2: reads the variable R1 wrote in this cycle; a parallel state entered by a timeout.
            state<Y1>[a_over_2] / inc_b_c = state<Y2>, state<Y2> + after(10ms) = state<Y3>,
            state<Y2> + event<go> = state<Y1>, state<Z1>[b_odd] / [](cycle_ctx& c) { c.io.set(c.b); } = state<Z2>,
            state<Z2> + after(40ms)[a_even_c] / bsc::raise(ping{}) = state<Z1>,
            state<W> + after(25ms) / inc_a_c,  // internal, on a region that is a basic state
            state<Y3> + after(60ms) / cnote<3> = state<Y1>, state<Z> + event<back> = state<Z2>,
            // R3: the inout channel as latched; raises an event handled at the end of the cycle.
            state<V1>[io_over_3] = state<V2>, state<V2> + after(15ms) / bsc::raise(tick{}) = state<V1>,
            // The parallel state as a whole: an event, an eventless and a timeout transition.
            state<P> + event<tick>[a_over_2] / cnote<4> = state<Out>, state<P>[in_is_7] = state<Out>,
            state<P> + after(500ms) = state<Out>, state<P> + event<go> / inc_a_c,
            // Out: re-enters P, or goes to a state inside it.
            state<O1> + after(30ms) = state<O2>, state<O2>[b_odd] / inc_b_c = state<P>,
            state<O2> + event<go> = state<Y3>, state<Out> + event<ping> / cnote<5>,
            state<Out> + after(200ms) = state<R2>, state<Root> + event<e1>[a_is_7] = state<End>,
            state<P> + on_entry / cnote<10>, state<P> + on_exit / cnote<11>, state<R2> + on_exit / cnote<12>,
            state<Y3> + on_entry / cnote<13>, state<Z2> + on_exit / cnote<14>, state<W> + on_entry / cnote<15>,
            state<Out> + on_entry / cnote<16>, state<O2> + on_exit / cnote<17>,
            state<X2> + on_entry / [](cycle_ctx& c) { c.out.set(c.out.pending() + 1); },
            // Several timeouts of one state, which compete by due time: a second internal one on
            // W of the same delay, and on X3 a guarded internal one shorter than its leaving one.
            state<W> + after(25ms) / cnote<6>, state<X3> + after(30ms)[b_odd] / cnote<7>);
    }();
    static cycle_ctx initial() { return {}; }
    static void perturb(cycle_ctx& c, std::uint32_t r) {
        switch (r % 4) {
            case 0:
            case 1: std::as_const(c.in).set(static_cast<int>((r >> 2) % 9)); break;
            case 2: c.a = static_cast<int>((r >> 2) % 8); break;
            default: c.b = static_cast<int>((r >> 2) % 8); break;
        }
    }
};

/// A scan policy with low limits.
struct scan_limits : bsc::scan_policy {
    static constexpr std::size_t queue_capacity = 3;
    static constexpr std::size_t max_internal_events = 12;
};

using cycles = cycling<bsc::default_policy>;
using scan_cycles = cycling<scan_limits>;

}  // namespace fx
