// What a machine does where a program could otherwise leave it silently wrong: channels and
// timers nested in the context, a dispatch from inside the machine's own actions. Each case runs
// on both back ends.

#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <bsc/verify.hpp>

#include "backends.hpp"
#include "heap_meter.hpp"
#include "inside.hpp"

using namespace std::chrono_literals;
using bsc_test::compiled;
using bsc_test::table;

namespace rob {
struct go {};
struct Root;
struct Idle;
struct Busy;

// ---- channels and timers at any depth --------------------------------------------------------
struct panel {
    std::array<bsc::input<bool>, 4> buttons;
    bsc::output<int> lamp;
    struct {
        bsc::timer settle{10ms};
    } timers;
};
// More members than fit a flat context before, and the I/O in nested structs and arrays.
struct cell_io {
    panel front;
    int v0, v1, v2, v3, v4, v5, v6, v7, v8, v9, v10, v11, v12, v13, v14, v15, v16, v17, v18, v19, v20, v21, v22, v23,
        v24, v25, v26, v27, v28, v29, v30, v31, v32, v33, v34, v35, v36, v37, v38, v39;
    std::array<panel, 2> stations;
    std::array<std::array<bsc::output<bool>, 2>, 3> valves;
};
inline constexpr auto nested = bsc::make_chart<cell_io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](cell_io const& c) { return c.front.buttons[2].get() && c.stations[1].buttons[3].get(); })] /
        [](cell_io& c) {
            c.front.lamp.set(7);
            c.stations[1].lamp.set(9);
            c.valves[2][1].set(true);
            c.stations[0].timers.settle.start();
        } = bsc::state<Busy>,
    bsc::state<Busy>[([](cell_io const& c) { return c.stations[0].timers.settle.tm(); })] /
        [](cell_io& c) { c.valves[2][1].set(false); } = bsc::state<Idle>);
}  // namespace rob

TEST_CASE_TEMPLATE("channels and timers inside nested structs and std::arrays are latched, published and updated",
                   Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::nested), bsc::scan_policy> m{rob::nested};
    auto& io = m.context();
    io.front.buttons[2].set(true);
    io.stations[1].buttons[3].set(true);
    CHECK_FALSE(io.front.buttons[2].get());  // not latched before a cycle
    m.step(0ms);
    CHECK(m.template is<rob::Busy>());
    CHECK(io.front.lamp.get() == 7);  // published at the end of the cycle
    CHECK(io.stations[1].lamp.get() == 9);
    CHECK(io.valves[2][1].get());
    m.step(5ms);  // the timer in stations[0] starts timing in the cycle after start()
    CHECK(io.stations[0].timers.settle.running());
    CHECK(m.template is<rob::Busy>());
    m.step(15ms);  // 10 ms after timing began
    CHECK(io.stations[0].timers.settle.tm());
    CHECK(m.template is<rob::Idle>());
    CHECK_FALSE(io.valves[2][1].get());
}

namespace rob {
// A context with a reference to the plant before its channels: the reference has no default, so
// no shorter list of initialisers is valid and the members must be counted up to the last.
struct plant_model {
    int pieces = 0;
};
struct referencing_io {
    int count = 0;
    plant_model& plant;
    bsc::input<bool> start;
    bsc::output<bool> motor;
};
inline constexpr auto referencing = bsc::make_chart<referencing_io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](referencing_io const& c) { return c.start.get(); })] /
        [](referencing_io& c) {
            c.motor.set(true);
            ++c.plant.pieces;
        } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
static_assert(inside::field_count<referencing_io>() == 4);
}  // namespace rob

TEST_CASE_TEMPLATE("channels after a reference member of the context are latched and published", Backend, compiled,
                   table) {
    rob::plant_model plant;
    bsc_test::machine_t<Backend, decltype(rob::referencing), bsc::scan_policy> m{rob::referencing,
                                                                                 rob::referencing_io{0, plant, {}, {}}};
    m.context().start.set(true);
    m.step(0ms);
    CHECK(m.template is<rob::Busy>());
    CHECK(m.context().motor.get());
    CHECK(plant.pieces == 1);
}

namespace rob {
// A context of what controllers hold besides channels and timers: a list that holds itself, a
// tree of itself, a handle on another machine, an optional value, an owned buffer, a callback;
// none hides state, so all compile, and the channels beside them (one in a static vector) run.
struct list_node {
    int value = 0;
    list_node* next = nullptr;
};
struct tree_node {
    std::vector<tree_node> children;
};
template <class T, std::size_t N>
struct static_vector {  // a fixed-capacity container of the kind embedded code uses
    std::array<T, N> items{};
    std::size_t size = 0;
};
struct tag {  // an event with a constructor and no data
    tag() {}
};
struct peer_data {
    int pokes = 0;
};
struct Peer;
struct Waiting;
struct Poked;
inline constexpr auto peer_chart = bsc::make_chart<peer_data>(
    bsc::composite<Peer>(bsc::initial<Waiting>, bsc::state<Poked>),
    bsc::state<Waiting> + bsc::event<go> / [](peer_data& d) { ++d.pokes; } = bsc::state<Poked>,
    bsc::state<Poked> + bsc::event<go> / [](peer_data& d) { ++d.pokes; } = bsc::state<Waiting>);
using peer_machine = bsc::machine<bsc::chart_ref<peer_chart>>;
struct handles_io {
    list_node head;
    tree_node tree;
    peer_machine* peer = nullptr;
    std::optional<int> last;
    std::unique_ptr<int> buffer;
    std::function<void(int)> report;
    static_vector<bsc::input<int>, 2> levels;  // walked: a struct of a std::array
    bsc::output<int> total;
};
inline constexpr auto handles = bsc::make_chart<handles_io>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle> + bsc::event<tag> /
                           [](handles_io& c) {
                               c.total.set(c.levels.items[0].get() + c.levels.items[1].get());
                               c.last = c.total.pending();
                               if (c.peer != nullptr) c.peer->dispatch(go{});
                           } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Idle>);
}  // namespace rob

TEST_CASE_TEMPLATE("a context of lists, trees, handles and callbacks runs; its nested channels are latched", Backend,
                   compiled, table) {
    rob::peer_machine peer{rob::peer_chart};
    rob::handles_io io{};
    io.peer = &peer;  // a handle on another actor, given where the machine is built
    bsc_test::machine_t<Backend, decltype(rob::handles), bsc::scan_policy> m{rob::handles, std::move(io)};
    m.context().levels.items[0].set(2);
    m.context().levels.items[1].set(5);
    m.step(0ms);  // latches the levels
    m.dispatch(rob::tag{});
    m.step(1ms);  // publishes the total
    CHECK(m.template is<rob::Busy>());
    CHECK(m.context().total.get() == 7);
    CHECK(m.context().last == 7);
    CHECK(peer.context().pokes == 1);
}

namespace rob {
// ---- reentrant dispatch ---------------------------------------------------------------------
struct poke {};
struct Other;
// The machine and the calls it makes on itself are given by the environment, as inputs.
struct reentrant_ctx {
    bsc::input<void*> self;
    bsc::input<bsc::outcome (*)(void*)> dispatch_go;           // calls self->dispatch(go{})
    bsc::input<bsc::outcome (*)(void*)> step_now;              // calls self->step(...)
    bsc::input<bsc::outcome (*)(void*, char const*)> by_name;  // calls self->dispatch_by_name(name)
    bsc::outcome inner = bsc::outcome::consumed;
    bsc::outcome inner_step = bsc::outcome::consumed;
    bsc::outcome inner_by_name = bsc::outcome::consumed;
    bsc::outcome inner_unknown = bsc::outcome::consumed;
    int idle_exits = 0;
    int busy_entries = 0;
};
inline constexpr auto reentrant = bsc::make_chart<reentrant_ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>, bsc::state<Other>),
    bsc::state<Idle> + bsc::on_exit / [](reentrant_ctx& c) { ++c.idle_exits; },
    bsc::state<Busy> + bsc::on_entry / [](reentrant_ctx& c) { ++c.busy_entries; },
    bsc::state<Idle> +
        bsc::event<poke> /
            [](reentrant_ctx& c) {
                c.inner = c.dispatch_go.get()(c.self.get());  // a dispatch from inside the machine's own action
                c.inner_step = c.step_now.get()(c.self.get());
                c.inner_by_name = c.by_name.get()(c.self.get(), "go");
                c.inner_unknown = c.by_name.get()(c.self.get(), "no such event");
            } = bsc::state<Busy>,
    bsc::state<Busy> + bsc::event<go> = bsc::state<Other>, bsc::state<Other> + bsc::event<go> = bsc::state<Idle>);
}  // namespace rob

TEST_CASE_TEMPLATE(
    "a dispatch, by type or by name, or a step from inside the machine's own action is refused and "
    "changes nothing",
    Backend, compiled, table) {
    using machine = bsc_test::machine_t<Backend, decltype(rob::reentrant)>;
    machine m{rob::reentrant};
    m.context().self.set(&m);
    m.context().dispatch_go.set([](void* self) { return static_cast<machine*>(self)->dispatch(rob::go{}); });
    m.context().step_now.set([](void* self) { return static_cast<machine*>(self)->step(1ms).status; });
    m.context().by_name.set(
        [](void* self, char const* name) { return static_cast<machine*>(self)->dispatch_by_name(name); });
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.context().inner == bsc::outcome::reentrant);
    CHECK(m.context().inner_step == bsc::outcome::reentrant);
    CHECK(m.context().inner_by_name == bsc::outcome::reentrant);
    CHECK(m.context().inner_unknown == bsc::outcome::reentrant);  // refused before the name is looked up
    // The outer transition completed once: Idle exited once, Busy entered once, nothing else.
    CHECK(m.template is<rob::Busy>());
    CHECK(m.context().idle_exits == 1);
    CHECK(m.context().busy_entries == 1);
    CHECK(m.last_outcome() == bsc::outcome::consumed);
    CHECK(m.now() == bsc::duration::zero());
    // The machine goes on working.
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
    CHECK(m.template is<rob::Other>());
}

namespace rob {
// ---- timeouts and the clock ------------------------------------------------------------------
struct Heating;
struct Done;
struct oven_ctx {
    int ticks = 0;
};
// An internal timeout fires every 500 ms while Heating is active; the external one after 2 s
// is not blocked by it.
inline constexpr auto oven = bsc::make_chart<oven_ctx>(
    bsc::composite<Root>(bsc::initial<Heating>, bsc::state<Done>),
    bsc::state<Heating> + bsc::after(500ms) / [](oven_ctx& c) { ++c.ticks; },
    bsc::state<Heating> + bsc::after(2s) = bsc::state<Done>, bsc::state<Done> + bsc::event<go> = bsc::state<Heating>);
}  // namespace rob

TEST_CASE_TEMPLATE("an internal timeout fires every period while its state is active, and blocks no other timeout",
                   Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::oven), bsc::scan_policy> m{rob::oven};
    for (auto t = 0ms; t < 2s; t += 100ms) m.step(t);
    CHECK(m.context().ticks == 3);  // at 500, 1000 and 1500 ms
    CHECK(m.template is<rob::Heating>());
    m.step(2s);  // both due at 2 s: the external one, armed at 0 (the internal one at 1.5 s), fires
    CHECK(m.context().ticks == 3);
    CHECK(m.template is<rob::Done>());
    m.step(2100ms);
    m.dispatch(rob::go{});  // re-entered: both count from the last cycle again
    for (auto t = 2200ms; t <= 2600ms; t += 100ms) m.step(t);
    CHECK(m.context().ticks == 4);  // 500 ms after 2100 ms
}

TEST_CASE_TEMPLATE("the clock starts at the first cycle, wherever the caller's time starts", Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::oven), bsc::scan_policy> m{rob::oven};
    CHECK(m.now() == bsc::duration::zero());
    auto const origin = -std::chrono::duration_cast<bsc::duration>(std::chrono::hours{24 * 365});
    auto const first = m.step(origin);
    CHECK_FALSE(first.clock_went_backwards);
    CHECK(m.now() == origin);
    m.step(origin + 499ms);
    CHECK(m.context().ticks == 0);
    m.step(origin + 500ms);  // the timeouts armed at construction count from the first cycle
    CHECK(m.context().ticks == 1);
    CHECK(m.step(origin).clock_went_backwards);
    m.step(origin + 2s);
    m.step(origin + 2s);
    CHECK(m.template is<rob::Done>());
}

TEST_CASE_TEMPLATE("times far apart do not overflow: a delay counts exactly across the whole range", Backend, compiled,
                   table) {
    bsc_test::machine_t<Backend, decltype(rob::oven), bsc::scan_policy> m{rob::oven};
    m.step(bsc::duration::min() + 1s);
    m.step(bsc::duration::max());  // about 584 years later: both timeouts are due, one fires
    CHECK(m.context().ticks == 1);
    m.step(bsc::duration::max());
    CHECK(m.template is<rob::Done>());
}

TEST_CASE("a chart built at run time with a negative or too long delay throws instead of running") {
    auto const build = [](bsc::duration delay) {
        return bsc::make_chart<rob::oven_ctx>(
            bsc::composite<rob::Root>(bsc::initial<rob::Heating>, bsc::state<rob::Done>),
            bsc::state<rob::Heating> + bsc::after(delay) = bsc::state<rob::Done>,
            bsc::state<rob::Done> + bsc::event<rob::go> = bsc::state<rob::Heating>);
    };
    CHECK_THROWS_AS(build(-1ms), std::invalid_argument);
    CHECK_NOTHROW(build(0ms));
    CHECK_THROWS_AS(bsc::after(std::chrono::hours{24 * 365 * 1000}), std::out_of_range);
    CHECK_NOTHROW(bsc::after(std::chrono::hours{24 * 365 * 290}));
}

TEST_CASE("a chart built at run time with a timeout that can never fire throws, naming both rows") {
    // Row 2 (after first) always leaves Heating before row 3 (after second) is due, unless
    // row 3's delay is the shorter one.
    auto const build = [](bsc::duration first, bsc::duration second) {
        return bsc::make_chart<rob::oven_ctx>(
            bsc::composite<rob::Root>(bsc::initial<rob::Heating>, bsc::state<rob::Done>),
            bsc::state<rob::Done> + bsc::event<rob::go> = bsc::state<rob::Heating>,
            bsc::state<rob::Heating> + bsc::after(first) = bsc::state<rob::Done>,
            bsc::state<rob::Heating> + bsc::after(second) = bsc::state<rob::Done>);
    };
    CHECK_THROWS_WITH_AS(
        build(1s, 2s),
        "bsc::make_chart: the timeout row at position 3 can never fire: the unguarded timeout row at "
        "position 2 leaves its state first, every time, with a shorter (or equal) delay, from the same "
        "state or from a state below it that is active whenever it is",
        std::invalid_argument);
    CHECK_THROWS_WITH_AS(build(1s, 1s), doctest::Contains("row at position 3 can never fire"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(build(3s, 2s), doctest::Contains("row at position 2 can never fire"), std::invalid_argument);
}

namespace rob {
// ---- the explorer's verdicts agree with the machine ------------------------------------------
struct Waiting;
struct Expired;
struct nothing {};
// One chart type; each model gives it another delay (after() keeps it in the chart object).
inline auto timed_chart(bsc::duration delay) {
    return bsc::make_chart<nothing>(bsc::composite<Root>(bsc::initial<Waiting>, bsc::final_state<Expired>),
                                    bsc::state<Waiting> + bsc::after(delay) = bsc::state<Expired>);
}
using timed_machine = bsc::machine<decltype(timed_chart(1ms))>;

// The cycle (counted from the first, 0) at which the machine itself expires, found by stepping
// it at the cycle before and at the one predicted: the expiry is at the first cycle whose
// time is at least the delay after the first cycle's.
inline std::uint64_t simulated_expiry(bsc::duration delay, bsc::duration period) {
    auto const predicted = static_cast<std::uint64_t>((delay + period - bsc::duration{1}) / period);
    timed_machine m{timed_chart(delay)};
    m.step(bsc::duration::zero());
    if (predicted == 0) return m.is<Expired>() ? 0 : ~std::uint64_t{0};
    m.step(static_cast<bsc::duration::rep>(predicted - 1) * period);
    if (m.is<Expired>()) return ~std::uint64_t{0};  // too early: the prediction is wrong
    m.step(static_cast<bsc::duration::rep>(predicted) * period);
    return m.is<Expired>() ? predicted : ~std::uint64_t{0};
}

inline auto explore(bsc::duration delay, bsc::duration period, std::size_t max_states) {
    auto model = bsc::verify::cycle_model{timed_machine{timed_chart(delay)}, period, 1,
                                          [](nothing const&, std::size_t) {}};
    return bsc::verify::explorer{model, bsc::verify::limits{max_states, std::size_t{1} << 30}};
}
}  // namespace rob

TEST_CASE("the explorer's verdicts on a timeout agree with the machine for delays of 1 to 10^7 periods") {
    std::mt19937_64 random{2026};
    std::array<bsc::duration, 4> const periods{1ms, 7ms, 1s, 13us};
    int complete = 0, inconclusive = 0;
    for (int model = 0; model < 10'000; ++model) {
        auto const period = periods[random() % periods.size()];
        // Log-uniform over 1 .. 10^7 periods, plus a random part of a period.
        double const exponent = std::uniform_real_distribution<double>{0.0, 7.0}(random);
        auto const whole = static_cast<bsc::duration::rep>(std::pow(10.0, exponent));
        auto const delay = whole * period + bsc::duration{static_cast<bsc::duration::rep>(
                                                random() % static_cast<std::uint64_t>(period.count()))};
        std::uint64_t const expiry = rob::simulated_expiry(delay, period);
        REQUIRE(expiry != ~std::uint64_t{0});
        auto ex = rob::explore(delay, period, 256);
        ex.run();
        auto const reached = bsc::verify::reachable(ex, "Expired",
                                                    [](auto const& m) { return m.template is<rob::Expired>(); });
        auto const never = bsc::verify::always(ex, "not Expired",
                                               [](auto const& m) { return !m.template is<rob::Expired>(); });
        if (ex.stats().complete) {
            ++complete;
            // Reached after exactly `expiry` cycles, and the invariant fails there.
            REQUIRE(reached.holds());
            REQUIRE(reached.trace.size() == expiry + 1);
            REQUIRE(never.fails());
            REQUIRE(never.trace.size() == expiry + 1);
        } else {
            ++inconclusive;
            REQUIRE_FALSE(reached.fails());  // never "unreachable" on an incomplete exploration
            REQUIRE_FALSE(never.holds());
        }
    }
    CHECK(complete > 2'000);
    CHECK(inconclusive > 2'000);
}

TEST_CASE("beyond 16 bits of periods the explorer still counts exactly; beyond its counter it refuses") {
    // 70 s at a 1 ms period: 70,000 cycles, which a 16-bit counter wrapped.
    auto ex = rob::explore(70s, 1ms, 100'000);
    ex.run();
    REQUIRE(ex.stats().complete);
    auto const reached = bsc::verify::reachable(ex, "Expired",
                                                [](auto const& m) { return m.template is<rob::Expired>(); });
    REQUIRE(reached.holds());
    CHECK(reached.trace.size() == 70'001);
    CHECK(bsc::verify::always(ex, "not Expired", [](auto const& m) { return !m.template is<rob::Expired>(); }).fails());
    // More periods than the explorer's 32-bit counter holds: refused with a reason, not explored.
    auto too_long = rob::explore(std::chrono::hours{24 * 365 * 200}, 1ms, 1'000);
    CHECK_THROWS_WITH_AS(too_long.run(), doctest::Contains("more than the explorer counts"), std::length_error);
}

TEST_CASE("an exploration stopped by its memory bound never held more than the bound") {
    std::size_t const bound = std::size_t{4} << 20;
    auto model = bsc::verify::cycle_model{
        rob::timed_machine{rob::timed_chart(std::chrono::hours{24})}, 1ms, 1,
        [](rob::nothing const&, std::size_t) {}};  // 86.4 million cycles: far too many
    std::size_t const before = heap_meter::live();
    heap_meter::reset_peak();
    bsc::verify::explorer limited{model, bsc::verify::limits{100'000'000, bound}};
    auto const& stats = limited.run();
    std::size_t const peak = heap_meter::peak() - before;
    CHECK_FALSE(stats.complete);
    CHECK(stats.stopped_by.find("max_memory_bytes") != std::string::npos);
    CHECK(peak <= bound + bound / 10);
    CHECK(peak > bound / 4);  // and it used a fair part of it
    MESSAGE("states " << stats.states << ", peak heap " << peak << " bytes of a " << bound << "-byte bound");
}

namespace rob {
// ---- exceptions from guards and actions ------------------------------------------------------
struct boom : std::runtime_error {
    boom() : std::runtime_error("boom") {}
};
struct Fault;
struct Outer;
struct Inner;
struct fault_ctx {
    bsc::input<bool> throw_in_action;  // where to throw: the environment's switches
    bsc::input<bool> throw_in_entry;
    bsc::input<bool> throw_in_guard;
    int idle_exits = 0;
    int outer_entries = 0;
    int inner_entries = 0;
    int raised_seen = 0;
    std::string caught;
};
struct raised {};
// Without a row on bsc::action_failed: the caller gets the exception.
inline constexpr auto throwing_rows = bsc::rows(
    bsc::state<Idle> + bsc::on_exit / [](fault_ctx& c) { ++c.idle_exits; },
    bsc::state<Outer> + bsc::on_entry /
                            [](fault_ctx& c) {
                                ++c.outer_entries;
                                if (c.throw_in_entry.get()) throw boom{};
                            },
    bsc::state<Inner> + bsc::on_entry / [](fault_ctx& c) { ++c.inner_entries; },
    bsc::state<Idle> + bsc::event<go>[([](fault_ctx const& c) {
                           if (c.throw_in_guard.get()) throw boom{};
                           return true;
                       })] /
                           [](fault_ctx& c, go const&, auto& raise) {
                               raise(raised{});  // queued before the throw: still processed in this dispatch
                               if (c.throw_in_action.get()) throw boom{};
                           } = bsc::state<Outer>,
    bsc::state<Outer> + bsc::event<raised> / [](fault_ctx& c) { ++c.raised_seen; },
    bsc::state<Outer> + bsc::event<poke> = bsc::state<Idle>);
inline constexpr auto unhandled = bsc::make_chart<fault_ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Outer>(bsc::initial<Inner>)), throwing_rows);
// With one: the chart goes to Fault like on any event.
inline constexpr auto handled = bsc::make_chart<fault_ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Outer>(bsc::initial<Inner>), bsc::state<Fault>),
    throwing_rows,
    bsc::state<Outer> + bsc::event<bsc::action_failed> /
                            [](fault_ctx& c, bsc::action_failed const& f) {
                                try {
                                    std::rethrow_exception(f.error);
                                } catch (std::exception const& e) {
                                    c.caught = e.what();
                                }
                            } = bsc::state<Fault>,
    bsc::state<Fault> + bsc::event<poke> = bsc::state<Idle>);
struct reporting : bsc::default_policy {
    static constexpr bool rethrow_failures = false;
};
}  // namespace rob

TEST_CASE_TEMPLATE("an action that throws: the microstep completes, then the caller gets the exception", Backend,
                   compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::unhandled)> m{rob::unhandled};
    m.context().throw_in_action.set(true);
    CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::boom);
    // The transition led where it leads: Idle exited once, Outer and Inner entered once.
    CHECK(m.template is<rob::Inner>());
    CHECK(m.context().idle_exits == 1);
    CHECK(m.context().outer_entries == 1);
    CHECK(m.context().inner_entries == 1);
    CHECK(m.context().raised_seen == 1);  // the event raised before the throw was processed
    // The machine goes on working, and the next unrelated dispatch finds nothing left over.
    m.context().throw_in_action.set(false);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.template is<rob::Idle>());
    CHECK(m.context().raised_seen == 1);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
    CHECK(m.context().raised_seen == 2);
}

TEST_CASE_TEMPLATE("an entry action that throws leaves a configuration the chart can reach", Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::unhandled)> m{rob::unhandled};
    m.context().throw_in_entry.set(true);
    CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::boom);
    CHECK(m.template is<rob::Outer>());
    CHECK(m.template is<rob::Inner>());  // the default entry went on below the failed entry
    CHECK(m.context().inner_entries == 1);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.template is<rob::Idle>());
}

TEST_CASE_TEMPLATE("a guard that throws does not hold, and its failure reaches the caller", Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::unhandled)> m{rob::unhandled};
    m.context().throw_in_guard.set(true);
    CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::boom);
    CHECK(m.template is<rob::Idle>());
    CHECK(m.context().idle_exits == 0);
    m.context().throw_in_guard.set(false);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
}

TEST_CASE_TEMPLATE("a chart takes bsc::action_failed with an ordinary transition", Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::handled)> m{rob::handled};
    m.context().throw_in_action.set(true);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);  // nothing escapes: the chart handled it
    CHECK(m.template is<rob::Fault>());
    CHECK(m.context().caught == "boom");
    CHECK(m.context().outer_entries == 1);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.template is<rob::Idle>());
}

TEST_CASE_TEMPLATE("under a policy that does not rethrow, the failure is an outcome and last_failure() holds it",
                   Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::unhandled), rob::reporting> m{rob::unhandled};
    m.context().throw_in_action.set(true);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::failed);
    CHECK(m.last_outcome() == bsc::outcome::failed);
    REQUIRE(m.last_failure() != nullptr);
    CHECK_THROWS_AS(std::rethrow_exception(m.last_failure()), rob::boom);
    CHECK(m.template is<rob::Inner>());
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.last_failure() == nullptr);
}

namespace rob {
struct observer_error {};
// Throws from on_entry of Target while `armed`: for Outer, after the action's failure, before
// the run ends.
template <class Target>
struct entry_thrower {
    bool armed = false;
    template <class S>
    void on_entry(bsc::state_tag<S>) {
        if (armed && std::is_same_v<S, Target>) throw observer_error{};
    }
};
}  // namespace rob

TEST_CASE_TEMPLATE("a failure kept by a run that an exception ends goes with that run", Backend, compiled, table) {
    bsc_test::machine_t<Backend, decltype(rob::unhandled), rob::reporting, rob::entry_thrower<rob::Outer>> m{
        rob::unhandled};
    m.context().throw_in_action.set(true);
    m.observer().armed = true;
    // The action's failure is kept, then the observer's exception ends the run: that is what escapes.
    CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::observer_error);
    m.context().throw_in_action.set(false);
    m.observer().armed = false;
    // Nothing of the ended run is reported by the next one, nor by any after it.
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.last_failure() == nullptr);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
    CHECK(m.last_outcome() == bsc::outcome::consumed);
}

TEST_CASE_TEMPLATE("a dispatch whose actions cannot fail reports no failure after one that did", Backend, compiled,
                   table) {
    // The status byte keeps whether the run under way has failed: it must not leak into the next run.
    bsc_test::machine_t<Backend, decltype(rob::unhandled), rob::reporting> m{rob::unhandled};
    m.context().throw_in_action.set(true);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::failed);
    m.context().throw_in_action.set(false);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);  // Outer to Idle: no action, no guard
    CHECK(m.last_outcome() == bsc::outcome::consumed);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::ignored);  // nothing runs at all
    CHECK(m.last_outcome() == bsc::outcome::ignored);
    CHECK(m.last_failure() == nullptr);
}

TEST_CASE_TEMPLATE("under bsc::lean_policy a failure is rethrown once, and the next dispatch runs clean", Backend,
                   compiled, table) {
    // lean_policy keeps no outcome: the failure's mark is cleared all the same.
    bsc_test::machine_t<Backend, decltype(rob::unhandled), bsc::lean_policy> m{rob::unhandled};
    m.context().throw_in_action.set(true);
    CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::boom);
    m.context().throw_in_action.set(false);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
    CHECK(m.dispatch(rob::poke{}) == bsc::outcome::ignored);
    CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
    CHECK(m.template is<rob::Inner>());
}

namespace rob {
struct Start;
struct start_ctx {
    bool fail = true;
};
inline constexpr auto failing_start = bsc::make_chart<start_ctx>(
    bsc::composite<Root>(bsc::initial<Start>, bsc::state<Idle>),
    bsc::state<Start> + bsc::on_entry /
                            [](start_ctx& c) {
                                if (c.fail) throw boom{};
                            },
    bsc::state<Start> + bsc::event<go> = bsc::state<Idle>, bsc::state<Idle> + bsc::event<go> = bsc::state<Start>);
}  // namespace rob

TEST_CASE_TEMPLATE("an entry action that throws during construction: the constructor rethrows", Backend, compiled,
                   table) {
    using machine = bsc_test::machine_t<Backend, decltype(rob::failing_start)>;
    CHECK_THROWS_AS(machine(rob::failing_start, rob::start_ctx{true}), rob::boom);
    machine m{rob::failing_start, rob::start_ctx{false}};
    CHECK(m.template is<rob::Start>());
}

namespace rob {
struct ping {};
struct Armed;
struct Other;
struct Hit;
// go raises ping on the way to Armed; an observer may end that run by throwing on entering Armed,
// before the machine processes ping. Other takes ping too: a ping left over from that run would
// show as Hit after the next dispatch.
struct raising_ctx {};
inline constexpr auto raising = bsc::make_chart<raising_ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Armed>, bsc::state<Other>, bsc::state<Hit>),
    bsc::state<Idle> + bsc::event<go> / bsc::raise(ping{}) = bsc::state<Armed>,
    bsc::state<Armed> + bsc::event<ping> = bsc::state<Hit>, bsc::state<Armed> + bsc::event<poke> = bsc::state<Other>,
    bsc::state<Other> + bsc::event<ping> = bsc::state<Hit>, bsc::state<Hit> + bsc::event<go> = bsc::state<Idle>);
}  // namespace rob

TEST_CASE_TEMPLATE("events raised by a run that an exception ends never reach a later run", Backend, compiled, table) {
    auto check = [](auto& m) {
        m.observer().armed = true;
        CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::observer_error);
        m.observer().armed = false;
        CHECK(m.template is<rob::Armed>());  // the microstep completed; its raised ping went with the run
        CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
        CHECK(m.template is<rob::Other>());
        // The machine goes on raising and processing as before, many times round its queue.
        for (int round = 0; round < 20; ++round) {
            m.observer().armed = round % 3 == 0;
            if (m.template is<rob::Other>()) {
                CHECK(m.dispatch(rob::ping{}) == bsc::outcome::consumed);
                CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
            }
            REQUIRE(m.template is<rob::Idle>());
            if (m.observer().armed) {
                CHECK_THROWS_AS(m.dispatch(rob::go{}), rob::observer_error);
                CHECK(m.dispatch(rob::poke{}) == bsc::outcome::consumed);
            } else {
                CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);  // Armed, then its ping: Hit
                CHECK(m.template is<rob::Hit>());
                CHECK(m.dispatch(rob::go{}) == bsc::outcome::consumed);
            }
        }
    };
    bsc_test::machine_t<Backend, decltype(rob::raising), bsc::default_policy, rob::entry_thrower<rob::Armed>> m{
        rob::raising};
    check(m);
    bsc_test::machine_t<Backend, decltype(rob::raising), bsc::lean_policy, rob::entry_thrower<rob::Armed>> lean{
        rob::raising};
    check(lean);
}
