// bsc::measure_latency (<bsc/benchmark.hpp>) on a chart whose slowest pair is known: in Idle,
// `work` runs an action that loops a thousand times; from Idle, `deep` enters three levels and
// a parallel state. Run plainly, the figures are times, never asserted (tests/README.md): the
// test checks the pairs, their accounts and the bound from the chart. Run under callgrind
// (`latency_test --callgrind FILE`, ctest benchmark.latency_instructions) they are instruction
// counts, the same on every run, and the slowest pair must be `work` in Idle, even after a dump
// the program asked for itself. Also: a scan chart, states from a scenario of the user's,
// the bound of charts that raise, settle, halt and run parallel components, and the slowest
// pairs handed to Google Benchmark.

#include <bsc/benchmark.hpp>
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define LATENCY_TEST_CALLGRIND 1
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct work {};
struct deep {};
struct back {};
struct Root;
struct Idle;
struct Outer;
struct Middle;
struct Split;
struct Left;
struct Right;
struct ctx {
    unsigned sum = 0;  // written by `work`'s loop, so that the loop is not optimised away
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(
        bsc::initial<Idle>,
        bsc::composite<Outer>(
            bsc::initial<Middle>,
            bsc::composite<Middle>(bsc::initial<Split>, bsc::parallel<Split>(bsc::state<Left>, bsc::state<Right>)))),
    bsc::state<Idle> + bsc::event<work> /
                           [](ctx& c) {
                               unsigned volatile n = 1000;
                               for (unsigned i = 0; i < n; ++i) c.sum = c.sum * 31u + i;
                           },
    bsc::state<Idle> + bsc::event<deep> = bsc::state<Outer>, bsc::state<Outer> + bsc::event<back> = bsc::state<Idle>);

using machine = bsc::machine<bsc::chart_ref<chart>>;

// A scan chart: a lamp that follows a switch, one cycle late.
struct Lamp;
struct Off;
struct On;
struct lamp_io {
    bsc::input<bool> on;
};
inline constexpr auto lamp_chart = bsc::make_chart<lamp_io>(
    bsc::composite<Lamp>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](lamp_io const& io) { return io.on.get(); })] = bsc::state<On>,
    bsc::state<On>[([](lamp_io const& io) { return !io.on.get(); })] = bsc::state<Off>);
using lamp = bsc::machine<bsc::chart_ref<lamp_chart>, bsc::scan_policy>;

// A scan chart with a timeout: Wait gives way to Done 100 ms after it was entered.
struct Timed;
struct Wait;
struct Done;
inline constexpr auto timed_chart = bsc::make_chart<lamp_io>(
    bsc::composite<Timed>(bsc::initial<Wait>, bsc::state<Done>),
    bsc::state<Wait> + bsc::after(std::chrono::milliseconds{100}) = bsc::state<Done>,
    bsc::state<Done>[([](lamp_io const& io) { return io.on.get(); })] = bsc::state<Wait>);
using timed = bsc::machine<bsc::chart_ref<timed_chart>, bsc::scan_policy>;

// A chart that raises, settles eventless transitions and can halt (a final child of the root).
struct kick {};
struct Top;
struct First;
struct Second;
struct End;
inline constexpr auto busy_chart = bsc::make_chart<int>(
    bsc::composite<Top>(bsc::initial<First>, bsc::state<Second>, bsc::final_state<End>),
    bsc::state<First> + bsc::event<kick> / bsc::raise(kick{}) = bsc::state<Second>,
    bsc::state<Second> + bsc::event<kick> = bsc::state<End>,
    bsc::state<Second>[([] { return false; })] = bsc::state<First>);
using busy = bsc::machine<bsc::chart_ref<busy_chart>>;

// Parallel components of a scan chart: the root's, A's and B's.
struct R;
struct P;
struct A;
struct A1;
struct A2;
struct B;
struct B1;
struct B2;
inline constexpr auto never = [](lamp_io const&) { return false; };
inline constexpr auto parallel_chart = bsc::make_chart<lamp_io>(
    bsc::composite<R>(bsc::initial<P>, bsc::parallel<P>(bsc::composite<A>(bsc::initial<A1>, bsc::state<A2>),
                                                        bsc::composite<B>(bsc::initial<B1>, bsc::state<B2>))),
    bsc::state<A1>[never] = bsc::state<A2>, bsc::state<A2>[never] = bsc::state<A1>,
    bsc::state<B1>[never] = bsc::state<B2>, bsc::state<B2>[never] = bsc::state<B1>);
using parallel_scan = bsc::machine<bsc::chart_ref<parallel_chart>, bsc::scan_policy>;

int failures = 0;
void expect(bool ok, char const* what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
    }
}

}  // namespace

template <>
inline constexpr bool bsc::transient<ctx> = true;  // the sum would make every state new

int main(int argc, char** argv) {
    // --callgrind FILE: run under callgrind with --callgrind-out-file=FILE.
    bool const under_callgrind = argc > 2 && std::strcmp(argv[1], "--callgrind") == 0;
    bsc::verify::event_model<machine, work, deep, back> model{machine{chart}};

    bsc::latency_options options;
    options.repetitions = 3;
    options.batch = 4;
    options.worst = 6;  // every pair
    if (under_callgrind) options.callgrind_out_file = argv[2];
    auto const report = bsc::measure_latency(model, options);
    std::fputs(report.to_string().c_str(), stdout);

    // Two states (Idle; Outer with its descendants), three events each.
    expect(report.states == 2 && report.labels == 3 && report.pairs == 6, "6 pairs: 2 states x 3 events");
    expect(report.complete, "the exploration is complete");
    expect(report.worst.size() == 6, "every pair named");

    // The bound: Root, Outer, Middle, Split, Left, Right active at once; Idle -> Outer has the
    // root as its domain: 5 states exit at most (Outer and what is below), 5 enter.
    expect(report.bound.has_value(), "a bound for a machine");
    if (report.bound) {
        expect(report.bound->states_at_once == 6, "6 states active at once");
        expect(report.bound->states_per_transition == 10, "one transition exits and enters at most 10 states");
        expect(report.bound->transitions_per_microstep == 2, "two transitions per microstep (Left, Right)");
        expect(report.bound->microsteps == 1, "one microstep: nothing raised, no eventless transition");
        // One microstep: two transitions of at most 10 each, but no more than 6 states out and 6 in.
        expect(report.bound->states_per_run == 12, "12 states per run: one microstep, at most 2 x 6");
    }

    // Every named pair's account is what the dispatch does; deep in Idle enters 5 states.
    int deep_in_idle = 0;
    for (auto const& p : report.worst) {
        if (p.event == "deep" && p.configuration == "Root Idle") {
            ++deep_in_idle;
            expect(p.exited == 1 && p.entered == 5 && p.transitions == 1, "deep in Idle: exits 1, enters 5");
            expect(!p.account.empty() && p.account.front() == "exit Idle", "deep's account begins with exit Idle");
        }
        if (p.event == "work" && p.configuration == "Root Idle")
            expect(p.account.size() == 1 && p.account.front() == "transition Idle -> internal on work",
                   "work in Idle: one internal transition");
        if (p.event == "deep" && p.configuration != "Root Idle") expect(p.account.empty(), "deep ignored in Outer");
    }
    expect(deep_in_idle == 1, "deep in Idle named once");

    if (under_callgrind) {
        expect(report.unit == "instructions", "instructions counted under callgrind");
        expect(!report.worst.empty() && report.worst.front().event == "work" &&
                   report.worst.front().configuration == "Root Idle",
               "the slowest pair is work in Idle");
        expect(!report.worst.empty() && report.worst.front().median >= 1000, "the loop's thousand turns counted");
#if defined(LATENCY_TEST_CALLGRIND)
        // A dump the program asks for itself shifts callgrind's numbering: the counts stay the same.
        CALLGRIND_DUMP_STATS_AT("the program's own");
#endif
        auto const again = bsc::measure_latency(model, options);
        expect(again.unit == "instructions" && again.max == report.max && again.median == report.median,
               "the same counts again, after a dump of the program's own");
        // Where callgrind's dumps cannot be read, every pair is timed.
        bsc::latency_options elsewhere = options;
        elsewhere.callgrind_out_file = "/nonexistent/callgrind.out.%p";
        expect(bsc::measure_latency(model, elsewhere).unit == "ns", "timed where the dumps cannot be read");
    } else {
        expect(report.unit == "ns", "times outside callgrind");
    }

    // From states given by the user (a scenario): Idle, then Outer.
    machine m{chart};
    std::vector<machine> starts{m};
    m.dispatch(deep{});
    starts.push_back(m);
    auto const from_scenario = bsc::measure_latency(model, std::span<machine const>{starts}, options);
    expect(from_scenario.states == 2 && from_scenario.pairs == 6 && !from_scenario.complete,
           "a scenario's states measured, not called complete");

    // A scan chart: each choice of inputs, then one step.
    using namespace std::chrono_literals;
    auto const on_off = [](lamp_io const& io, std::size_t choice) { io.on.set(choice == 1); };
    auto const on_off_label = [](std::size_t choice) { return std::string(choice == 1 ? "on=1" : "on=0"); };
    bsc::verify::cycle_model scan{lamp{lamp_chart}, 10ms, 2, on_off, on_off_label};
    auto const cycles = bsc::measure_latency(scan, options);
    std::fputs(cycles.to_string().c_str(), stdout);
    expect(cycles.complete && cycles.labels == 2 && cycles.pairs == cycles.states * 2 && cycles.offered == "inputs",
           "a scan chart's pairs");
    expect(cycles.bound && cycles.bound->microsteps == 1 && cycles.bound->transitions_per_microstep == 1,
           "a cycle of one component: one microstep, one transition");
    bool switched_on = false;
    for (auto const& p : cycles.worst)
        for (auto const& line : p.account)
            switched_on = switched_on || (line == "transition Off -> On on condition" && p.configuration == "Lamp Off");
    expect(switched_on, "a cycle of Off switches the lamp on, and the account says so");

    // A scan chart measured from a user's states, whatever their clock: one period on from each.
    // Wait was entered at 0 ms; from the state after the cycle at 0 ms, the next cycle (50 ms)
    // leaves it; from the state after the cycle at 50 ms, the next (100 ms) takes the timeout.
    bsc::verify::cycle_model timed_scan{timed{timed_chart}, 50ms, 1, [](lamp_io const&, std::size_t) {},
                                        [](std::size_t) { return std::string("scan"); }};
    timed t{timed_chart};
    t.step(0ms);
    std::vector<timed> early{t};
    t.step(50ms);
    std::vector<timed> late{t};
    auto const from_early = bsc::measure_latency(timed_scan, std::span<timed const>{early}, options);
    auto const from_late = bsc::measure_latency(timed_scan, std::span<timed const>{late}, options);
    expect(from_early.worst.size() == 1 && from_early.worst.front().explained &&
               from_early.worst.front().account.empty(),
           "50 ms after Wait was entered, nothing fires");
    expect(from_late.worst.size() == 1 && from_late.worst.front().account.size() == 3 &&
               from_late.worst.front().account[1] == "transition Wait -> Done on after(100ms)",
           "100 ms after Wait was entered, the timeout fires");

    // The bound of a chart that raises (256 internal events), settles eventless transitions
    // (64 + 1 after each) and can halt (every active state exits once more).
    bsc::verify::event_model<busy, kick> busy_model{busy{busy_chart}};
    auto const busy_report = bsc::measure_latency(busy_model, options);
    expect(busy_report.bound && busy_report.bound->microsteps == 257 * 66, "257 x 66 microsteps");
    expect(busy_report.bound && busy_report.bound->states_at_once == 2 &&
               busy_report.bound->states_per_transition == 2 && busy_report.bound->states_per_run == 257 * 66 * 2 + 2,
           "per run: 2 states per microstep, then the halt's");

    // In a cycle, one transition per BSC component: the root's, A's and B's.
    bsc::verify::cycle_model parallel_model{parallel_scan{parallel_chart}, 10ms, 1, [](lamp_io const&, std::size_t) {},
                                            [](std::size_t) { return std::string("scan"); }};
    auto const parallel_report = bsc::measure_latency(parallel_model, options);
    expect(parallel_report.bound && parallel_report.bound->transitions_per_microstep == 3,
           "three components in a cycle: the root, A and B");

    // The slowest pairs handed to Google Benchmark: one benchmark each, and each runs.
    bsc::register_latency_benchmarks("latency_test", model, report);
    char program[] = "latency_test";
    char min_time[] = "--benchmark_min_time=0.001";
    char* gb_argv[] = {program, min_time, nullptr};
    int gb_argc = 2;
    ::benchmark::Initialize(&gb_argc, gb_argv);
    expect(::benchmark::RunSpecifiedBenchmarks() == report.worst.size(), "one Google Benchmark per named pair");

    if (failures == 0) std::puts("latency_test: all checks passed");
    return failures == 0 ? 0 : 1;
}
