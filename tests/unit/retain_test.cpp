// Retentive state (<bsc/retain.hpp>): a machine saved to bytes continues, restored into a fresh
// machine, exactly as the original does, on both back ends; bytes from another chart or layout,
// truncated, extended, corrupted or out of range are refused with the reason and change nothing;
// and the manufacturing cell, its controller restarted mid-run from saved bytes, runs on as if
// nothing had happened.

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends.hpp"
#include "retain_fixture.hpp"
#include "../../examples/manufacturing_cell/controller.hpp"
#include "../../examples/manufacturing_cell/monitor.hpp"
#include "inside.hpp"

namespace retain_test {

using namespace std::chrono_literals;

template <class M>
void refused_unchanged(M& m, std::span<std::byte const> bytes, bsc::restore_error why, std::size_t at) {
    auto const before = bsc::save(m);
    auto const result = bsc::restore(m, bytes);
    CHECK_MESSAGE(result.error == why, bsc::to_string(result));
    CHECK(result.offset == at);
    CHECK_FALSE(result);
    CHECK(bsc::save(m) == before);
}

// Bytes with one value changed and the checksum made right again: the checks behind it must
// still catch the value.
std::vector<std::byte> patched(std::vector<std::byte> bytes, std::size_t at, std::uint8_t value) {
    bytes[at] = std::byte{value};
    std::size_t const n = bytes.size() - 4;
    std::uint32_t const crc = inside::crc32(bytes.data(), n);
    for (std::size_t i = 0; i < 4; ++i) bytes[n + i] = static_cast<std::byte>((crc >> (8 * i)) & 0xffu);
    return bytes;
}

TEST_CASE_TEMPLATE("retain: a restored machine continues exactly as the saved one", Backend, bsc_test::compiled,
                   bsc_test::table) {
    using machine = bsc_test::machine_t<Backend, decltype(chart)>;
    // Saved at every point of the run, the copy's continuation equals the original's.
    for (int save_at = 0; save_at < 40; save_at += 3) {
        machine original{chart, ctx{}};
        for (int k = 0; k < save_at; ++k) drive(original, k);
        auto const bytes = bsc::save(original);
        REQUIRE(bytes.size() == bsc::saved_size<machine>);

        ctx own{};
        own.screen.shown = 42;  // the copy's own display, given where it is built
        machine copy{chart, own};
        auto const result = bsc::restore(copy, bytes);
        REQUIRE_MESSAGE(result, bsc::to_string(result));
        CHECK(bsc::save(copy) == bytes);
        CHECK(copy.context().screen.shown == 42);  // not retained: the copy keeps its own
        CHECK(copy.last_outcome() == original.last_outcome());
        for (int k = save_at; k < 60; ++k) {
            CAPTURE(save_at);
            CAPTURE(k);
            REQUIRE(drive(copy, k) == drive(original, k));
        }
    }
}

TEST_CASE("retain: the two back ends save the same bytes") {
    bsc::machine compiled{chart, ctx{}};
    bsc::table::machine table{chart, ctx{}};
    for (int k = 0; k < 30; ++k) {
        drive(compiled, k);
        drive(table, k);
        REQUIRE(bsc::save(compiled) == bsc::save(table));
    }
    // ... so each restores what the other saved.
    bsc::machine into{chart, ctx{}};
    CHECK(bsc::restore(into, bsc::save(table)));
    CHECK(describe(into) == describe(table));
}

TEST_CASE("retain: history, timeouts and timers survive the restart") {
    bsc::machine m{chart, ctx{}};
    m.step(0ms);
    m.dispatch(go{});    // Hold -> Work (Setup); the timer `settle` starts
    m.step(400ms);       // Setup -> Run (Fast) after 300 ms
    m.dispatch(next{});  // Fast -> Slow: the 1 s timeout starts at 400 ms
    m.step(500ms);
    m.dispatch(leave{});  // Work is left: deep history keeps Run/Slow
    REQUIRE(m.is<Hold>());
    auto const bytes = bsc::save(m);

    bsc::machine fresh{chart, ctx{}};
    REQUIRE(bsc::restore(fresh, bytes));
    CHECK(fresh.now() == 500ms);
    CHECK(fresh.context().settle.running());  // started by the last action, timing since 500 ms
    fresh.step(700ms);
    CHECK(fresh.context().settle.elapsed() == 200ms);
    CHECK_FALSE(fresh.context().settle.tm());
    fresh.dispatch(go{});  // back into Work: deep history restores Slow
    CHECK(fresh.is<Slow>());
    fresh.step(1600ms);
    CHECK(fresh.is<Slow>());  // entered again by the dispatch: its 1 s counts from the clock, 700 ms
    fresh.step(1700ms);
    CHECK(fresh.is<Fast>());
}

TEST_CASE("retain: resume_at moves every time the machine keeps, so the downtime does not count") {
    bsc::machine m{chart, ctx{}};
    m.step(10s);
    m.dispatch(go{});     // Setup; its 300 ms timeout is armed at 10 s; settle starts
    m.step(10s + 100ms);  // settle times from here
    auto const bytes = bsc::save(m);

    bsc::machine resumed{chart, ctx{}};
    REQUIRE(bsc::restore(resumed, bytes, bsc::resume_at{2s}));
    CHECK(resumed.now() == 2s);
    CHECK(resumed.step(2s + 150ms).transitions == 0);
    CHECK(resumed.is<Setup>());
    CHECK(resumed.context().settle.elapsed() == 150ms);  // timing since 10.1 s, now since 2 s
    CHECK(resumed.step(2s + 200ms).transitions >= 1);    // 300 ms after the timeout was armed
    CHECK(resumed.is<Fast>());

    // Without resume_at the saved clock stands, and an earlier time is reported.
    bsc::machine as_saved{chart, ctx{}};
    REQUIRE(bsc::restore(as_saved, bytes));
    CHECK(as_saved.now() == 10s + 100ms);
    CHECK(as_saved.step(2s).clock_went_backwards);

    // A machine that never cycled keeps no time of the caller's: resume_at changes nothing.
    bsc::machine idle{chart, ctx{}};
    bsc::machine copy{chart, ctx{}};
    REQUIRE(bsc::restore(copy, bsc::save(idle), bsc::resume_at{5s}));
    CHECK(bsc::save(copy) == bsc::save(idle));
}

TEST_CASE("retain: bytes that are not this machine's state are refused with the reason, and change nothing") {
    using machine = bsc::machine<decltype(chart)>;
    machine saved{chart, ctx{}};
    saved.dispatch(go{});
    saved.step(1s);
    auto const good = bsc::save(saved);
    std::size_t const n = good.size();

    machine m{chart, ctx{}};
    m.dispatch(back{});
    using bsc::restore_error;
    std::span<std::byte const> const all{good};

    refused_unchanged(m, all.first(0), restore_error::truncated, 0);
    refused_unchanged(m, all.first(3), restore_error::truncated, 3);
    refused_unchanged(m, all.first(20), restore_error::truncated, 20);
    refused_unchanged(m, all.first(n - 1), restore_error::truncated, n - 1);

    auto extended = good;
    extended.push_back(std::byte{0});
    refused_unchanged(m, extended, restore_error::trailing_bytes, n);

    auto foreign = good;
    foreign[0] = std::byte{'B'};
    refused_unchanged(m, foreign, restore_error::not_saved_state, 0);
    std::array<std::byte, 5> const text{std::byte{'h'}, std::byte{'e'}, std::byte{'l'}, std::byte{'l'}, std::byte{'o'}};
    refused_unchanged(m, text, restore_error::not_saved_state, 0);

    refused_unchanged(m, patched(good, 4, 1), restore_error::unsupported_version, 4);  // held no pending events
    refused_unchanged(m, patched(good, 4, 3), restore_error::unsupported_version, 4);
    refused_unchanged(m, patched(good, 6, 1), restore_error::unsupported_version, 4);

    // Any single flipped bit of the fingerprints, the payload or the checksum.
    auto const before_all = bsc::save(m);
    for (std::size_t at = 12; at < n; ++at) {
        auto corrupted = good;
        corrupted[at] ^= std::byte{0x10};
        auto const result = bsc::restore(m, corrupted);
        REQUIRE_MESSAGE(result.error == restore_error::corrupted, at, ": ", bsc::to_string(result));
        CHECK(result.offset == n - 4);
    }
    CHECK(bsc::save(m) == before_all);  // none changed the machine

    // The fingerprints are checked after the checksum: a changed one is another chart or layout.
    refused_unchanged(m, patched(good, 13, static_cast<std::uint8_t>(good[13]) ^ 1u), restore_error::other_chart, 12);
    refused_unchanged(m, patched(good, 27, static_cast<std::uint8_t>(good[27]) ^ 1u), restore_error::other_layout, 20);
    bsc::machine other{other_chart, ctx{}};
    refused_unchanged(other, good, restore_error::other_chart, 12);

    // Values out of range, behind a valid checksum: a configuration byte (one past the last child
    // of its composite), the flag "a cycle has run", the last outcome, a bool of the context.
    using model = inside::model<decltype(chart)>;
    constexpr std::size_t payload = inside::retain_header_size;
    std::size_t const slots = static_cast<std::size_t>(model::tree.slots);
    for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s) {
        if (model::tree.slot[s] < 0) continue;
        std::size_t const at = payload + static_cast<std::size_t>(model::tree.slot[s]);
        refused_unchanged(m, patched(good, at, static_cast<std::uint8_t>(model::tree.child_count[s])),
                          restore_error::invalid_value, at);
        CHECK(bsc::restore(m, patched(good, at, static_cast<std::uint8_t>(model::tree.child_count[s] - 1))));
        m = machine{chart, ctx{}};
        m.dispatch(back{});
    }
    refused_unchanged(m, patched(good, payload + slots + 8, 2), restore_error::invalid_value, payload + slots + 8);
    // The last outcome follows the timeout slots; the context follows it. Its first member is
    // `start` (a bool channel: pending, then current).
    std::size_t const slots_timeouts = inside::timeout_slots<decltype(chart)>;
    std::size_t const outcome_at = payload + slots + 9 + 8 * slots_timeouts;
    refused_unchanged(m, patched(good, outcome_at, 200), restore_error::invalid_value, outcome_at);
    refused_unchanged(m, patched(good, outcome_at + 2, 7), restore_error::invalid_value, outcome_at + 2);

    CHECK(bsc::restore(m, good));  // and the good bytes restore
    CHECK(bsc::save(m) == good);
}

// The same chart over contexts that differ in one way each.
enum class signed_level : std::int8_t { low = -1, high = 1 };
enum class unsigned_level : std::uint8_t { low = 1, high = 2 };
enum legacy_color { red, green };                   // no fixed underlying type: cannot be restored
enum fixed_color : std::uint8_t { cyan, magenta };  // can
static_assert(!inside::has_fixed_underlying_type<legacy_color>);
static_assert(inside::has_fixed_underlying_type<fixed_color>);
static_assert(inside::has_fixed_underlying_type<signed_level>);
struct with_signed_enum {
    bsc::input<bool> start;
    signed_level level{};
};
struct with_unsigned_enum {
    bsc::input<bool> start;
    unsigned_level level{};
};
struct renamed {
    bsc::input<bool> begin;  // `start` in ctx
};
struct original_layout {
    bsc::input<bool> start;
    int a = 0;
    unsigned b = 0;
};
struct reordered {
    bsc::input<bool> start;
    unsigned b = 0;
    int a = 0;
};
struct retyped {
    bsc::input<bool> start;
    int a = 0;
    int b = 0;
};
struct output_instead {
    bsc::output<bool> start;
    int a = 0;
    unsigned b = 0;
};
template <class Context>
inline constexpr auto layout_chart = bsc::make_chart<Context>(bsc::composite<Root>(bsc::initial<Hold>,
                                                                                   bsc::state<Work>),
                                                              bsc::state<Hold> + bsc::event<go> = bsc::state<Work>,
                                                              bsc::state<Work> + bsc::event<back> = bsc::state<Hold>);
template <class Context>
using layout_machine = bsc::machine<decltype(layout_chart<Context>)>;

TEST_CASE("retain: the layout fingerprint tells members' names, order, types and channel kinds apart") {
    using inside::chart_fingerprint;
    using inside::layout_fingerprint;
    // The same states: the chart's fingerprint is the same.
    CHECK(chart_fingerprint<layout_machine<renamed>>() == chart_fingerprint<layout_machine<original_layout>>());
    constexpr std::array<std::uint64_t, 7> layouts = {
        layout_fingerprint<layout_machine<original_layout>>(),   layout_fingerprint<layout_machine<renamed>>(),
        layout_fingerprint<layout_machine<reordered>>(),         layout_fingerprint<layout_machine<retyped>>(),
        layout_fingerprint<layout_machine<output_instead>>(),    layout_fingerprint<layout_machine<with_signed_enum>>(),
        layout_fingerprint<layout_machine<with_unsigned_enum>>()};
    for (std::size_t i = 0; i < layouts.size(); ++i)
        for (std::size_t j = i + 1; j < layouts.size(); ++j) CHECK(layouts[i] != layouts[j]);

    layout_machine<original_layout> source{layout_chart<original_layout>, original_layout{}};
    layout_machine<reordered> target{layout_chart<reordered>, reordered{}};
    auto const result = bsc::restore(target, bsc::save(source));
    CHECK(result.error == bsc::restore_error::other_layout);
    CHECK(bsc::to_string(result) ==
          "saved with another context layout (members, names, types or order differ) (byte 20)");
}

// Two versions of a chart whose state S has the same two timeout rows in another order: the
// bytes hold each row's start, so they must not pass from one to the other.
struct S;
struct T;
struct tick_ctx {
    int ticks = 0;
};
inline constexpr auto tick = [](tick_ctx& c) { ++c.ticks; };
inline constexpr auto ticking_first = bsc::make_chart<tick_ctx>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<T>), bsc::state<S> + bsc::after(1s) / tick,
    bsc::state<S> + bsc::after(10s) = bsc::state<T>, bsc::state<T> + bsc::event<go> = bsc::state<S>);
inline constexpr auto leaving_first = bsc::make_chart<tick_ctx>(
    bsc::composite<Root>(bsc::initial<S>, bsc::state<T>), bsc::state<S> + bsc::after(10s) = bsc::state<T>,
    bsc::state<S> + bsc::after(1s) / tick, bsc::state<T> + bsc::event<go> = bsc::state<S>);

TEST_CASE("retain: the chart fingerprint tells the timeout rows apart") {
    bsc::machine<decltype(ticking_first), bsc::scan_policy> first{ticking_first};
    first.step(0s);
    first.step(5500ms);
    bsc::machine<decltype(leaving_first), bsc::scan_policy> second{leaving_first};
    auto const result = bsc::restore(second, bsc::save(first));
    CHECK(result.error == bsc::restore_error::other_chart);
    CHECK(result.offset == 12);
}

// A context that is a timer only: its bytes follow the machine's, at a known place.
struct timer_ctx {
    bsc::timer t{2s};
};
inline constexpr auto timer_chart = bsc::make_chart<timer_ctx>(
    bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Work>),
    bsc::state<Hold> + bsc::event<go> / [](timer_ctx& c) { c.t.start(); } = bsc::state<Work>,
    bsc::state<Work>[([](timer_ctx const& c) { return c.t.tm(); })] = bsc::state<Hold>);

TEST_CASE("retain: a timer's state that no timer can come to is refused") {
    using machine = bsc::machine<decltype(timer_chart), bsc::scan_policy>;
    machine m{timer_chart};
    m.step(0s);
    auto const idle = bsc::save(m);
    // header, one configuration byte, the clock, the flag, the outcome; then limit, start,
    // elapsed (8 bytes each), phase, expired
    std::size_t const timer_at = inside::retain_header_size + 1 + 8 + 1 + 1;
    machine target{timer_chart};
    refused_unchanged(target, patched(idle, timer_at + 7, 0x80), bsc::restore_error::invalid_value, timer_at);
    refused_unchanged(target, patched(idle, timer_at + 25, 1), bsc::restore_error::invalid_value,
                      timer_at);  // idle, expired
    refused_unchanged(target, patched(idle, timer_at + 16, 5), bsc::restore_error::invalid_value,
                      timer_at);  // idle, elapsed
    refused_unchanged(target, patched(idle, timer_at + 24, 3), bsc::restore_error::invalid_value, timer_at + 24);
    CHECK(bsc::restore(target, patched(idle, timer_at, 7)));  // another limit, not below zero
    CHECK(target.context().t.limit() == std::chrono::nanoseconds{(2'000'000'000 & ~0xff) | 7});

    m.dispatch(go{});
    m.step(1s);
    m.step(3s);  // expired, and left in the same cycle
    CHECK(m.is<Hold>());
    CHECK(bsc::restore(target, bsc::save(m)));
    CHECK(bsc::save(target) == bsc::save(m));
}

// A policy under which a failure is reported, not rethrown.
struct reporting : bsc::default_policy {
    static constexpr bool rethrow_failures = false;
};
struct fail_ctx {
    bool fail = false;
};
inline constexpr auto failing_chart = bsc::make_chart<fail_ctx>(
    bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Work>),
    bsc::state<Hold> + bsc::event<go> /
                           [](fail_ctx& c) {
                               if (c.fail) throw std::runtime_error("jammed");
                           } = bsc::state<Work>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Hold>);

TEST_CASE("retain: a restored machine does not report the exception of its own earlier run") {
    using machine = bsc::machine<decltype(failing_chart), reporting>;
    machine healthy{failing_chart};
    machine target{failing_chart, fail_ctx{true}};
    CHECK(target.dispatch(go{}) == bsc::outcome::failed);
    REQUIRE(target.last_failure() != nullptr);
    REQUIRE(bsc::restore(target, bsc::save(healthy)));
    CHECK(target.last_failure() == nullptr);
    CHECK(target.last_outcome() == healthy.last_outcome());
}

// A chart whose action saves and restores its own machine.
struct probe_ctx {
    std::size_t saved = 1;
    bsc::restore_error restored = bsc::restore_error::none;
};
inline void (*inside_action)(probe_ctx&) = nullptr;
inline constexpr auto probe_chart = bsc::make_chart<probe_ctx>(
    bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Work>),
    bsc::state<Hold> + bsc::event<go> / [](probe_ctx& c) { inside_action(c); } = bsc::state<Work>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Hold>);
using probe_machine = bsc::machine<decltype(probe_chart)>;
inline probe_machine* probed = nullptr;
inline std::vector<std::byte> probe_bytes;

TEST_CASE("retain: save and restore are refused from inside the machine's own action") {
    probe_machine m{probe_chart, probe_ctx{}};
    probed = &m;
    probe_bytes = bsc::save(m);
    inside_action = [](probe_ctx& c) {
        std::array<std::byte, bsc::saved_size<probe_machine>> buffer{};
        c.saved = bsc::save(*probed, buffer);
        c.restored = bsc::restore(*probed, probe_bytes).error;
    };
    m.dispatch(go{});
    CHECK(m.is<Work>());
    CHECK(m.context().saved == 0);
    CHECK(m.context().restored == bsc::restore_error::machine_running);
    CHECK(bsc::save(m).size() == bsc::saved_size<probe_machine>);  // between dispatches it saves

    std::array<std::byte, 10> too_small{};
    CHECK(bsc::save(m, too_small) == 0);
    inside_action = nullptr;
    probed = nullptr;
}

// A machine in the context (a supervisor holding a sub-controller) is saved as a machine.
struct Sub;
struct SubIdle;
struct SubBusy;
struct sub_ctx {
    int jobs = 0;
};
inline constexpr auto sub_chart = bsc::make_chart<sub_ctx>(
    bsc::composite<Sub>(bsc::initial<SubIdle>, bsc::state<SubBusy>),
    bsc::state<SubIdle> + bsc::event<go> / [](sub_ctx& c) { ++c.jobs; } = bsc::state<SubBusy>,
    bsc::state<SubBusy> + bsc::after(1s) = bsc::state<SubIdle>);
using sub_machine = bsc::machine<decltype(sub_chart), bsc::scan_policy>;
struct supervisor_ctx {
    sub_machine sub{sub_chart};
    int orders = 0;
};
struct step_sub {  // the supervisor steps its sub-controller at `now`
    bsc::duration now{};
};
inline constexpr auto supervisor_chart = bsc::make_chart<supervisor_ctx>(
    bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Work>),
    bsc::state<Hold> + bsc::event<go> /
                           [](supervisor_ctx& c) {
                               ++c.orders;
                               c.sub.dispatch(go{});
                           } = bsc::state<Work>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Hold>,
    bsc::state<Root> + bsc::event<step_sub> / [](supervisor_ctx& c, step_sub const& s) { c.sub.step(s.now); });

TEST_CASE("retain: a machine held in the context is saved and restored with its own time") {
    using supervisor = bsc::machine<decltype(supervisor_chart)>;
    supervisor m{supervisor_chart, supervisor_ctx{}};
    m.dispatch(step_sub{5s});
    m.dispatch(go{});
    REQUIRE(m.context().sub.is<SubBusy>());
    auto const bytes = bsc::save(m);
    CHECK(bytes.size() == bsc::saved_size<supervisor>);

    supervisor fresh{supervisor_chart, supervisor_ctx{}};
    REQUIRE(bsc::restore(fresh, bytes, bsc::resume_at{100s}));
    CHECK(fresh.is<Work>());
    CHECK(fresh.context().orders == 1);
    CHECK(fresh.context().sub.context().jobs == 1);
    CHECK(fresh.context().sub.now() == 100s);  // the sub-machine's clock moves with the resumed time
    fresh.dispatch(step_sub{100s + 999ms});
    CHECK(fresh.context().sub.is<SubBusy>());
    fresh.dispatch(step_sub{101s});
    CHECK(fresh.context().sub.is<SubIdle>());
}

// A delayed event sent from a clock of 10 s with a delay of bsc::duration::max() - 10 s: due at
// bsc::duration::max() exactly, the last time a step can reach.
struct ring {};
struct far_ctx {
    int rings = 0;
};
inline constexpr auto far_chart = bsc::make_chart<far_ctx>(
    bsc::composite<Root>(bsc::initial<Hold>, bsc::state<Work>),
    bsc::state<Hold> + bsc::event<go> / bsc::raise_after(bsc::duration::max() - 10s, ring{}, 1) = bsc::state<Work>,
    bsc::state<Work> + bsc::event<ring> / [](far_ctx& c) { ++c.rings; } = bsc::state<Hold>,
    bsc::state<Work> + bsc::event<back> = bsc::state<Hold>);

TEST_CASE_TEMPLATE("retain: a delayed event that resume_at moves past bsc::duration::max() never comes due", Backend,
                   bsc_test::compiled, bsc_test::table) {
    using machine = bsc_test::machine_t<Backend, decltype(far_chart), bsc::scan_policy>;
    machine m{far_chart};
    m.step(10s);
    m.dispatch(go{});
    auto const bytes = bsc::save(m);

    machine same{far_chart};
    REQUIRE(bsc::restore(same, bytes));
    same.step(bsc::duration::max());
    CHECK(same.context().rings == 1);  // at the last instant

    machine resumed{far_chart};
    REQUIRE(bsc::restore(resumed, bytes, bsc::resume_at{11s}));  // a second later: past the end of time
    machine sent_later{far_chart};
    sent_later.step(11s);
    sent_later.dispatch(go{});  // sent from 11 s: not kept either
    CHECK(bsc::save(resumed) == bsc::save(sent_later));
    resumed.step(bsc::duration::max());
    CHECK(resumed.context().rings == 0);
    CHECK(resumed.template is<Work>());
}

// ---- the manufacturing cell ---------------------------------------------------------------------

std::vector<std::string> run_cell(long restart_at) {
    cell::machine m{cell::chart};
    cell::closed_loop loop{m, {0s, 1s, 9s, 9500ms, 30s}, 100ms};
    std::vector<std::string> trace;
    for (long cycle = 0; cycle < 900 && !loop.done(); ++cycle) {
        if (cycle == restart_at) {
            // A power cut: the controller's memory is lost, the plant runs on; the controller
            // restarts from the bytes it saved at the end of the last cycle.
            auto const bytes = bsc::save(m);
            m = cell::machine{cell::chart};
            REQUIRE(bsc::restore(m, bytes));
        }
        cell::cycle_record const r = loop.cycle();
        auto const& d = m.context();
        trace.push_back(std::to_string(r.time.count()) + " " + m.active_states().joined() + " " + std::to_string(d.E1) +
                        std::to_string(d.E2) + std::to_string(d.E3) + std::to_string(d.E4) + " " +
                        std::to_string(d.T1.elapsed().count()) + " " + std::to_string(d.T3.tm()));
    }
    CHECK(loop.done());
    CHECK(loop.monitor().ok());
    return trace;
}

TEST_CASE("retain: the manufacturing cell restarted mid-run from saved bytes continues identically") {
    auto const reference = run_cell(-1);
    REQUIRE(reference.size() > 300);
    // Restarts in every phase: the belt running, drilling, testing, the robot, the table turning.
    for (long at = 1; at < static_cast<long>(reference.size()); at += 23) {
        CAPTURE(at);
        CHECK(run_cell(at) == reference);
    }
}

}  // namespace retain_test
