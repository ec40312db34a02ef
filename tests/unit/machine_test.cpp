// The compiled machine as an object: its size, its names, its observers, copies, and
// evaluation at compile time.

#include <doctest/doctest.h>

#include <string>
#include <string_view>
#include <typeinfo>

#include "trace.hpp"
#include "inside.hpp"

namespace mt {
struct go {};
struct back {};
struct Root;
struct A;
struct A1;
struct A2;
struct B;
struct B1;
struct B2;
struct P;
struct R1;
struct R2;
struct X;
struct Y;
struct counter {
    int count = 0;
};

// 4 composites (Root, A, B, R1), one parallel (P), basic states.
inline constexpr auto chart = bsc::make_chart<counter>(
    bsc::composite<Root>(bsc::initial<A>, bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>),
                         bsc::composite<B>(bsc::deep_history, bsc::initial<B1>, bsc::state<B2>),
                         bsc::parallel<P>(bsc::composite<R1>(bsc::initial<X>), bsc::state<Y>)),
    bsc::state<A1> + bsc::event<go> = bsc::state<A2>, bsc::state<A2> + bsc::event<go> = bsc::state<B>,
    bsc::state<B1> + bsc::event<go> / [](counter& c) { ++c.count; } = bsc::state<B2>,
    bsc::state<B2> + bsc::event<go> = bsc::state<P>, bsc::state<P> + bsc::event<back> = bsc::state<A>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<A> + bsc::event<back> = bsc::state<B>);

struct partial {  // only one hook: the others are not required
    int exits = 0;
    void on_exit(auto) { ++exits; }
};
struct row_log {  // on_row: the position of the fired row in make_chart's arguments
    int calls = 0;
    int last = -1;
    void on_row(int row) {
        ++calls;
        last = row;
    }
};
}  // namespace mt

TEST_CASE("the active configuration takes one byte per composite state") {
    using machine = bsc::machine<decltype(mt::chart)>;
    CHECK(sizeof(machine::configuration_type) == 4);
    bsc::machine m{mt::chart, mt::counter{}};
    CHECK(sizeof(m.active_configuration()) == 4);
}

TEST_CASE("is<S> and active_states follow the configuration, composites and parallel states included") {
    bsc::machine m{mt::chart, mt::counter{}};
    CHECK(m.is<mt::Root>());
    CHECK(m.is<mt::A>());
    CHECK(m.is<mt::A1>());
    CHECK_FALSE(m.is<mt::A2>());
    CHECK_FALSE(m.is<mt::B>());
    CHECK_FALSE(m.is<mt::B1>());  // B's byte says B1, but B is inactive
    m.dispatch(mt::go{});
    m.dispatch(mt::go{});
    m.dispatch(mt::go{});
    m.dispatch(mt::go{});
    CHECK(m.is<mt::P>());
    CHECK(m.is<mt::X>());
    CHECK(m.is<mt::Y>());
    CHECK(m.active_states().joined() == "Root P R1 X Y");
    CHECK(m.active_states().contains("Y"));
    CHECK(m.active_states().size() == 5);
    CHECK(bsc::name_of<mt::R1> == "R1");
    CHECK(bsc::qualified_name<mt::R1> == "mt::R1");
}

TEST_CASE("a machine is a value: copies run independently") {
    bsc::machine a{mt::chart, mt::counter{}};
    a.dispatch(mt::go{});
    auto b = a;
    b.dispatch(mt::go{});
    CHECK(a.is<mt::A2>());
    CHECK(b.is<mt::B1>());
}

TEST_CASE("observers see entries, exits and transitions in order; a machine without one stores nothing for it") {
    std::string trace;
    bsc::machine m{mt::chart, mt::counter{}, bsc_test::trace_observer{&trace}};
    CHECK(trace == "+Root +A +A1");
    trace.clear();
    m.dispatch(mt::go{});
    m.dispatch(mt::go{});
    CHECK(trace == "-A1 A1>A2 +A2 -A2 -A A2>B +B +B1");

    using mt::partial;
    bsc::machine<decltype(mt::chart), bsc::default_policy, partial> p{mt::chart, mt::counter{}, partial{}};
    p.dispatch(mt::go{});
    CHECK(p.observer().exits == 1);
    bsc::machine<decltype(mt::chart), bsc::default_policy, mt::row_log> r{mt::chart, mt::counter{}, mt::row_log{}};
    r.dispatch(mt::go{});  // A1 -> A2, the first row
    CHECK(r.observer().calls == 1);
    CHECK(r.observer().last == 0);
    r.dispatch(mt::go{});  // A2 -> B, the second
    CHECK(r.observer().calls == 2);
    CHECK(r.observer().last == 1);
    CHECK(sizeof(bsc::machine<decltype(mt::chart)>) ==
          sizeof(bsc::machine<decltype(mt::chart), bsc::default_policy, bsc::no_observer>));
}

TEST_CASE("guards and actions take the arguments they need") {
    struct number {
        int n;
    };
    struct ctx {
        int sum = 0;
    };
    struct S;
    struct T;
    static constexpr auto chart = bsc::make_chart<ctx>(
        bsc::composite<mt::Root>(bsc::initial<S>, bsc::state<T>),
        bsc::state<S> + bsc::event<number>[([] { return true; })] / [] {},
        bsc::state<S> + bsc::event<number>[([](ctx const& c) { return c.sum < 100; })] / [](ctx& c) { c.sum += 1; },
        bsc::state<S> + bsc::event<number>[([](ctx const&, number const& e) { return e.n == 5; })] /
                            [](ctx& c, number const& e) { c.sum += e.n; },
        bsc::state<S> + bsc::event<mt::go> = bsc::state<T>, bsc::state<T> + bsc::event<mt::go> = bsc::state<S>);
    bsc::machine m{chart, ctx{}};
    CHECK(m.dispatch(number{5}) == bsc::outcome::consumed);  // the first, unguarded-in-effect, wins
    CHECK(m.context().sum == 0);
}

namespace mt {
struct small {
    int n = 0;
};
inline constexpr auto constexpr_chart = bsc::make_chart<small>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
    bsc::state<A> + bsc::event<go> / [](small& s) { s.n += 1; } = bsc::state<B>,
    bsc::state<B> + bsc::event<go> / bsc::raise(back{}) = bsc::state<A>,
    bsc::state<A> + bsc::event<back> / [](small& s) { s.n += 10; });

constexpr int run_at_compile_time() {
    bsc::machine m{constexpr_chart, small{}};
    m.dispatch(go{});
    m.dispatch(go{});
    return m.is<A>() ? m.context().n : -1;
}
}  // namespace mt

TEST_CASE("a machine runs in constant expressions") {
    static_assert(mt::run_at_compile_time() == 11);
    CHECK(mt::run_at_compile_time() == 11);
}

TEST_CASE("dispatch with allow_unhandled accepts an event no transition handles, and ignores it") {
    struct stranger {};
    bsc::machine m{mt::chart, mt::counter{}};
    CHECK(m.dispatch(stranger{}, bsc::allow_unhandled) == bsc::outcome::ignored);
    CHECK(m.is<mt::A1>());
}

namespace mt {
// Rules defined once and reused: two charts share a group of rows.
inline constexpr auto common_rules = bsc::rows(bsc::state<A> + bsc::event<go> = bsc::state<B>,
                                               bsc::rows(bsc::state<B> + bsc::event<back> = bsc::state<A>));
inline constexpr auto base = bsc::make_chart<counter>(bsc::composite<Root>(bsc::initial<A>, bsc::state<B>),
                                                      common_rules);
inline constexpr auto extended = bsc::make_chart<counter>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>), common_rules,
    bsc::state<B> + bsc::event<go> / [](counter& c) { ++c.count; });
}  // namespace mt

TEST_CASE("groups of rows (bsc::rows) are flattened into the chart, so rules can be shared") {
    bsc::machine b{mt::base, mt::counter{}};
    bsc::machine e{mt::extended, mt::counter{}};
    b.dispatch(mt::go{});
    e.dispatch(mt::go{});
    CHECK(b.dispatch(mt::go{}) == bsc::outcome::ignored);
    CHECK(e.dispatch(mt::go{}) == bsc::outcome::consumed);
    CHECK(e.context().count == 1);
    CHECK(b.dispatch(mt::back{}) == bsc::outcome::consumed);
    CHECK(b.is<mt::A>());
}

// ---- what the compiled machine decides at compile time ------------------------------------
namespace mt2 {
struct tick {};
struct go {};
struct W;
template <int R>
struct G;
template <int R>
struct On;
template <int R>
struct Off;
struct log_ctx {
    std::string log;
};
template <int R>
inline constexpr auto note = [](log_ctx& c) { c.log += std::to_string(R); };
template <int R>
inline constexpr auto exit_note = [](log_ctx& c) { c.log += "x" + std::to_string(R); };
template <int R>
inline constexpr auto entry_note = [](log_ctx& c) { c.log += "e" + std::to_string(R); };

template <int R>
constexpr auto region() {
    return bsc::composite<G<R>>(bsc::initial<Off<R>>, bsc::state<On<R>>);
}
template <int R>
constexpr auto region_rows() {
    return bsc::rows(bsc::state<Off<R>> + bsc::event<tick> / note<R> = bsc::state<On<R>>,
                     bsc::state<On<R>> + bsc::event<tick> / note<R> = bsc::state<Off<R>>,
                     bsc::state<On<R>> + bsc::on_exit / exit_note<R>, bsc::state<On<R>> + bsc::on_entry / entry_note<R>);
}
// tick stays inside each region; go leaves the parallel state from region 1, so its transition
// conflicts with region 0's, and SCXML keeps the one earlier in document order.
inline constexpr auto wide = bsc::make_chart<log_ctx>(
    bsc::parallel<W>(region<0>(), region<1>(), region<2>()), region_rows<0>(), region_rows<1>(), region_rows<2>(),
    bsc::state<On<0>> + bsc::event<go> / note<7> = bsc::state<Off<0>>,
    bsc::state<On<1>> + bsc::event<go> / note<8> = bsc::state<W>);

inline constexpr auto raising = bsc::make_chart<log_ctx>(
    bsc::composite<struct RRoot>(bsc::initial<Off<0>>, bsc::state<On<0>>),
    bsc::state<Off<0>> + bsc::event<tick> / [](log_ctx&, tick const&, auto& raise) { raise(go{}); } = bsc::state<On<0>>,
    bsc::state<On<0>> + bsc::event<go> / note<1> = bsc::state<Off<0>>);
}  // namespace mt2

TEST_CASE("transitions that stay inside their regions fire without run-time conflict resolution, in SCXML order") {
    using plan = inside::plan<decltype(mt2::wide)>;
    constexpr int tick = inside::trigger_of<decltype(mt2::wide), mt2::tick>;
    constexpr int go = inside::trigger_of<decltype(mt2::wide), mt2::go>;
    static_assert(plan::region_local<tick>);
    static_assert(!plan::region_local<go>);  // the transition to W leaves the parallel state

    bsc::machine fast{mt2::wide};
    bsc::table::machine reference{mt2::wide};
    CHECK(fast.dispatch(mt2::tick{}) == bsc::outcome::consumed);
    reference.dispatch(mt2::tick{});
    // Actions in document order, then the entries in document order.
    CHECK(fast.context().log == "012e0e1e2");
    CHECK(fast.context().log == reference.context().log);
    fast.context().log.clear();
    reference.context().log.clear();
    CHECK(fast.dispatch(mt2::tick{}) == bsc::outcome::consumed);
    reference.dispatch(mt2::tick{});
    // All exits first, innermost and last region first; then the actions.
    CHECK(fast.context().log == "x2x1x0012");
    CHECK(fast.context().log == reference.context().log);
    CHECK(fast.active_states() == reference.active_states());
    // go: region 1's transition leaves W and conflicts with region 0's, which comes first and wins.
    fast.dispatch(mt2::tick{});
    reference.dispatch(mt2::tick{});
    fast.context().log.clear();
    reference.context().log.clear();
    fast.dispatch(mt2::go{});
    reference.dispatch(mt2::go{});
    CHECK(fast.context().log == reference.context().log);
    CHECK(fast.context().log == "x07");
    CHECK(fast.is<mt2::On<1>>());
}

TEST_CASE("a chart none of whose actions can raise carries no event queue") {
    using quiet = bsc::machine<decltype(mt2::wide)>;
    using noisy = bsc::machine<decltype(mt2::raising)>;
    static_assert(quiet::queue_capacity == 0);
    static_assert(noisy::queue_capacity == bsc::default_policy::queue_capacity);
    bsc::machine m{mt2::raising};
    CHECK(m.dispatch(mt2::tick{}) == bsc::outcome::consumed);
    CHECK(m.context().log == "1");  // the raised go was processed
    CHECK(m.is<mt2::Off<0>>());
}

TEST_CASE("bsc::chart_ref names a chart by its variable: the same machine, with short symbol names") {
    bsc::machine<bsc::chart_ref<mt2::wide>> named{mt2::wide};
    bsc::machine plain{mt2::wide};
    static_assert(sizeof(named) == sizeof(plain));
    for (int i = 0; i < 3; ++i) {
        CHECK(named.dispatch(mt2::tick{}) == plain.dispatch(mt2::tick{}));
        CHECK(named.active_configuration() == plain.active_configuration());
    }
    CHECK(named.dispatch(mt2::go{}) == plain.dispatch(mt2::go{}));
    CHECK(named.context().log == plain.context().log);
    CHECK(std::string_view(typeid(named).name()).size() * 4 < std::string_view(typeid(plain).name()).size());
    bsc::table::machine<bsc::chart_ref<mt2::wide>> table{mt2::wide};
    CHECK(table.dispatch(mt2::tick{}) == bsc::outcome::consumed);
}

namespace mt2 {
struct reset {};
template <int R>
struct Mid;
template <int R>
constexpr auto plain_region() {
    return bsc::composite<G<R>>(bsc::initial<Off<R>>, bsc::state<Mid<R>>, bsc::state<On<R>>);
}
template <int R>
inline constexpr auto tag = [](log_ctx& c, auto const&) { c.log += static_cast<char>('a' + R); };
template <int R>
constexpr auto plain_rows() {
    return bsc::rows(bsc::state<Off<R>> + bsc::event<tick> / note<R> = bsc::state<Mid<R>>,
                     bsc::state<Mid<R>> + bsc::event<tick> / note<R> = bsc::state<On<R>>,
                     bsc::state<On<R>> + bsc::event<tick> / note<R> = bsc::state<Off<R>>,
                     bsc::state<Mid<R>> + bsc::event<reset> / tag<R> = bsc::state<Off<R>>,
                     bsc::state<On<R>> + bsc::event<reset> / tag<R> = bsc::state<Off<R>>);
}
struct entries {
    std::string* out;
    void on_entry(auto state) { *out += state.name; }
};
// No guards and no entry or exit actions: tick and reset fire in each region as it is selected.
inline constexpr auto plain = bsc::make_chart<log_ctx>(bsc::parallel<W>(plain_region<0>(), plain_region<1>(), plain_region<2>()),
                                                       plain_rows<0>(), plain_rows<1>(), plain_rows<2>(),
                                                       bsc::state<Mid<1>> + bsc::event<go> / note<9>);
}  // namespace mt2

TEST_CASE("without guards, entry or exit actions, parallel transitions fire as they are selected, with the same effects") {
    using plan = inside::plan<decltype(mt2::plain)>;
    static_assert(plan::fires_at_selection<inside::trigger_of<decltype(mt2::plain), mt2::tick>>);
    static_assert(plan::fires_at_selection<inside::trigger_of<decltype(mt2::plain), mt2::reset>>);
    static_assert(!inside::plan<decltype(mt2::wide)>::fires_at_selection<inside::trigger_of<decltype(mt2::wide), mt2::tick>>);  // entry/exit notes
    bsc::machine fast{mt2::plain};
    bsc::table::machine reference{mt2::plain};
    std::uint32_t seed = 7;
    for (int i = 0; i < 600; ++i) {
        seed = seed * 1664525u + 1013904223u;
        switch ((seed >> 16) % 4) {
        case 0:
        case 1:
            CHECK(fast.dispatch(mt2::tick{}) == reference.dispatch(mt2::tick{}));
            break;
        case 2:
            CHECK(fast.dispatch(mt2::reset{}) == reference.dispatch(mt2::reset{}));
            break;
        default:
            CHECK(fast.dispatch(mt2::go{}) == reference.dispatch(mt2::go{}));
        }
        REQUIRE(fast.active_configuration() == reference.active_configuration());
        REQUIRE(fast.context().log == reference.context().log);
    }
    CHECK(fast.context().log.size() > 1000);
    // With an observer, the same chart takes the select-then-fire path, and agrees.
    std::string trace;
    bsc::machine<decltype(mt2::plain), bsc::default_policy, mt2::entries> observed{mt2::plain, {}, mt2::entries{&trace}};
    observed.dispatch(mt2::tick{});
    observed.dispatch(mt2::reset{});
    CHECK(trace == "WG<0>Off<0>G<1>Off<1>G<2>Off<2>Mid<0>Mid<1>Mid<2>Off<0>Off<1>Off<2>");
    CHECK(observed.context().log == "012abc");
}
