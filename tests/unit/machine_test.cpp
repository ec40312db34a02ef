// What is particular to the compiled back end (bsc::machine): evaluation in constant
// expressions, the dispatch plans it computes at compile time (region-local firing, firing at
// selection), the queue it leaves out of charts that cannot raise, and bsc::chart_ref. The
// interface it shares with bsc::table::machine is tested in interface_test.cpp.

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <typeinfo>

#include "inside.hpp"

namespace mt {
struct go {};
struct back {};
struct Root;
struct A;
struct B;
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
inline constexpr auto exit_note = [](log_ctx& c) {  // appended in two: GCC 12 -O3 misfires -Wrestrict on "x" + s
    c.log += 'x';
    c.log += std::to_string(R);
};
template <int R>
inline constexpr auto entry_note = [](log_ctx& c) {
    c.log += 'e';
    c.log += std::to_string(R);
};

template <int R>
constexpr auto region() {
    return bsc::composite<G<R>>(bsc::initial<Off<R>>, bsc::state<On<R>>);
}
template <int R>
constexpr auto region_rows() {
    return bsc::rows(bsc::state<Off<R>> + bsc::event<tick> / note<R> = bsc::state<On<R>>,
                     bsc::state<On<R>> + bsc::event<tick> / note<R> = bsc::state<Off<R>>,
                     bsc::state<On<R>> + bsc::on_exit / exit_note<R>,
                     bsc::state<On<R>> + bsc::on_entry / entry_note<R>);
}
// tick stays inside each region; go leaves the parallel state from region 1, so its transition
// conflicts with region 0's, and SCXML keeps the one earlier in document order.
inline constexpr auto wide = bsc::make_chart<log_ctx>(bsc::parallel<W>(region<0>(), region<1>(), region<2>()),
                                                      region_rows<0>(), region_rows<1>(), region_rows<2>(),
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
    // What each machine logged since `from` characters of its log (the log is the chart's own:
    // the test reads it, and marks where a step's part begins).
    auto const since = [](auto const& m, std::size_t from) { return m.context().log.substr(from); };
    std::size_t from = fast.context().log.size();
    CHECK(fast.dispatch(mt2::tick{}) == bsc::outcome::consumed);
    reference.dispatch(mt2::tick{});
    // All exits first, innermost and last region first; then the actions.
    CHECK(since(fast, from) == "x2x1x0012");
    CHECK(fast.context().log == reference.context().log);
    CHECK(fast.active_states() == reference.active_states());
    // go: region 1's transition leaves W and conflicts with region 0's, which comes first and wins.
    fast.dispatch(mt2::tick{});
    reference.dispatch(mt2::tick{});
    from = fast.context().log.size();
    fast.dispatch(mt2::go{});
    reference.dispatch(mt2::go{});
    CHECK(fast.context().log == reference.context().log);
    CHECK(since(fast, from) == "x07");
    CHECK(fast.is<mt2::On<1>>());
}

TEST_CASE("a chart none of whose actions can raise carries no event queue, on either back end") {
    using quiet = bsc::machine<decltype(mt2::wide)>;
    using noisy = bsc::machine<decltype(mt2::raising)>;
    static_assert(quiet::queue_capacity == 0);
    static_assert(noisy::queue_capacity == bsc::default_policy::queue_capacity);
    // The table-driven machine carries one only where the compiled one does.
    using quiet_table = bsc::table::machine<decltype(mt2::wide)>;
    using noisy_table = bsc::table::machine<decltype(mt2::raising)>;
    static_assert(quiet_table::queue_capacity == 0);
    static_assert(noisy_table::queue_capacity == bsc::default_policy::queue_capacity);
    static_assert(sizeof(quiet) == sizeof(quiet_table));
    static_assert(sizeof(noisy) == sizeof(noisy_table));
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
inline constexpr auto plain = bsc::make_chart<log_ctx>(
    bsc::parallel<W>(plain_region<0>(), plain_region<1>(), plain_region<2>()), plain_rows<0>(), plain_rows<1>(),
    plain_rows<2>(), bsc::state<Mid<1>> + bsc::event<go> / note<9>);
}  // namespace mt2

TEST_CASE(
    "without guards, entry or exit actions, parallel transitions fire as they are selected, with the same effects") {
    using plan = inside::plan<decltype(mt2::plain)>;
    static_assert(plan::fires_at_selection<inside::trigger_of<decltype(mt2::plain), mt2::tick>>);
    static_assert(plan::fires_at_selection<inside::trigger_of<decltype(mt2::plain), mt2::reset>>);
    static_assert(!inside::plan<decltype(mt2::wide)>::fires_at_selection<
                  inside::trigger_of<decltype(mt2::wide), mt2::tick>>);  // entry/exit notes
    bsc::machine fast{mt2::plain};
    bsc::table::machine reference{mt2::plain};
    std::uint32_t seed = 7;
    for (int i = 0; i < 600; ++i) {
        seed = seed * 1664525u + 1013904223u;
        switch ((seed >> 16) % 4) {
            case 0:
            case 1: CHECK(fast.dispatch(mt2::tick{}) == reference.dispatch(mt2::tick{})); break;
            case 2: CHECK(fast.dispatch(mt2::reset{}) == reference.dispatch(mt2::reset{})); break;
            default: CHECK(fast.dispatch(mt2::go{}) == reference.dispatch(mt2::go{}));
        }
        REQUIRE(fast.active_configuration() == reference.active_configuration());
        REQUIRE(fast.context().log == reference.context().log);
    }
    CHECK(fast.context().log.size() > 1000);
    // With an observer, the same chart takes the select-then-fire path, and agrees.
    std::string trace;
    bsc::machine<decltype(mt2::plain), bsc::default_policy, mt2::entries> observed{
        mt2::plain, {}, mt2::entries{&trace}};
    observed.dispatch(mt2::tick{});
    observed.dispatch(mt2::reset{});
    CHECK(trace == "WG<0>Off<0>G<1>Off<1>G<2>Off<2>Mid<0>Mid<1>Mid<2>Off<0>Off<1>Off<2>");
    CHECK(observed.context().log == "012abc");
}

namespace mt3 {
struct go {};
struct tick {};
struct Root;
struct Outer;
struct Inner;
struct A;
struct InnerDone;
struct OuterDone;
struct After;
struct log {
    std::string text;
};
// Completions two deep: go ends Inner, whose completion ends Outer, whose completion leaves it;
// and `more` rows besides.
template <class... More>
constexpr auto completions_two_deep(More... more) {
    return bsc::make_chart<log>(
        bsc::composite<Root>(bsc::initial<Outer>,
                             bsc::composite<Outer>(bsc::initial<Inner>,
                                                   bsc::composite<Inner>(bsc::initial<A>, bsc::final_state<InnerDone>),
                                                   bsc::final_state<OuterDone>),
                             bsc::state<After>),
        bsc::state<A> + bsc::event<go> / [](log& l) { l.text += "a"; } = bsc::state<InnerDone>,
        bsc::state<Inner> + bsc::event<bsc::done<Inner>> / [](log& l) { l.text += "i"; } = bsc::state<OuterDone>,
        bsc::state<Outer> + bsc::event<bsc::done<Outer>> / [](log& l) { l.text += "o"; } = bsc::state<After>, more...);
}
inline constexpr auto chained = completions_two_deep(
    bsc::state<After> + bsc::event<go> / [](log& l) { l.text += "r"; } = bsc::state<Outer>);
struct no_queue : bsc::default_policy {
    static constexpr std::size_t queue_capacity = 0;
};
// The same with an eventless row: taken before queued events, it could add one more.
inline constexpr auto chained_eventless = completions_two_deep(
    bsc::state<After> + bsc::event<tick> = bsc::state<Outer>,
    bsc::state<After>[([](log const& l) { return l.text.size() > 100; })] = bsc::state<Outer>);
}  // namespace mt3

TEST_CASE("a chart that queues only done events, one at a time, keeps one slot for them, on either back end") {
    using compiled = bsc::machine<decltype(mt3::chained)>;
    using table = bsc::table::machine<decltype(mt3::chained)>;
    static_assert(compiled::queue_capacity == 1);
    static_assert(table::queue_capacity == 1);
    static_assert(bsc::machine<decltype(mt3::chained_eventless)>::queue_capacity ==
                  bsc::default_policy::queue_capacity);
    static_assert(bsc::table::machine<decltype(mt3::chained_eventless)>::queue_capacity ==
                  bsc::default_policy::queue_capacity);
    // A policy without a queue still has none: a completion is then an overflow.
    static_assert(bsc::machine<decltype(mt3::chained), mt3::no_queue>::queue_capacity == 0);
    bsc::machine<decltype(mt3::chained), mt3::no_queue> without{mt3::chained};
    CHECK(without.dispatch(mt3::go{}) == bsc::outcome::queue_overflow);
    CHECK(without.is<mt3::InnerDone>());

    compiled fast{mt3::chained};
    table reference{mt3::chained};
    for (int round = 0; round < 3; ++round) {
        CHECK(fast.dispatch(mt3::go{}) == bsc::outcome::consumed);
        CHECK(reference.dispatch(mt3::go{}) == bsc::outcome::consumed);
        CHECK(fast.is<mt3::After>());
        CHECK(fast.active_configuration() == reference.active_configuration());
        CHECK(fast.dispatch(mt3::go{}) == bsc::outcome::consumed);
        CHECK(reference.dispatch(mt3::go{}) == bsc::outcome::consumed);
        CHECK(fast.is<mt3::A>());
    }
    CHECK(fast.context().text ==
          "aior"
          "aior"
          "aior");
    CHECK(reference.context().text == fast.context().text);
}
