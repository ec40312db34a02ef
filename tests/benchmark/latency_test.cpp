// bsc::measure_latency (<bsc/benchmark.hpp>) on a chart whose slowest pair is known: in Idle,
// `work` runs an action that loops a thousand times; from Idle, `deep` enters three levels and
// a parallel state. Run plainly, the figures are times and only their shape is asserted (times
// are never asserted: tests/README.md); run under callgrind (`latency_test --callgrind`, ctest
// benchmark.latency_instructions) they are instruction counts, the same on every run, and the
// slowest pair must be `work` in Idle.

#include <bsc/benchmark.hpp>
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

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
    expect(report.min <= report.median && report.median <= report.p99 && report.p99 <= report.max,
           "min <= median <= p99 <= max");
    for (auto const& p : report.worst) expect(p.min <= p.median && p.median <= p.max, "a pair's min <= median <= max");
    for (std::size_t k = 1; k < report.worst.size(); ++k)
        expect(report.worst[k - 1].median >= report.worst[k].median, "the named pairs slowest first");

    // The bound: Root, Outer, Middle, Split, Left, Right active at once; Idle -> Outer has the
    // root as its domain: 5 states exit at most (Outer and what is below), 5 enter.
    expect(report.bound.has_value(), "a bound for a machine");
    if (report.bound) {
        expect(report.bound->states_at_once == 6, "6 states active at once");
        expect(report.bound->states_per_transition == 10, "one transition exits and enters at most 10 states");
        expect(report.bound->components == 2, "two components (Left, Right)");
        expect(report.bound->microsteps == 1, "one microstep: nothing raised, no eventless transition");
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
        // The same counts on a second run.
        auto const again = bsc::measure_latency(model, options);
        expect(again.max == report.max && again.median == report.median, "the same counts again");
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
    bsc::verify::cycle_model scan{lamp{lamp_chart}, 10ms, 2,
                                  [](lamp_io const& io, std::size_t choice) { io.on.set(choice == 1); },
                                  [](std::size_t choice) { return std::string(choice == 1 ? "on=1" : "on=0"); }};
    auto const cycles = bsc::measure_latency(scan, options);
    std::fputs(cycles.to_string().c_str(), stdout);
    expect(cycles.complete && cycles.labels == 2 && cycles.pairs == cycles.states * 2, "a scan chart's pairs");
    expect(cycles.bound && cycles.bound->microsteps == 1 && cycles.bound->components == 1, "a cycle: one microstep");
    bool switched_on = false;
    for (auto const& p : cycles.worst)
        for (auto const& line : p.account)
            switched_on = switched_on || (line == "transition Off -> On on condition" && p.configuration == "Lamp Off");
    expect(switched_on, "a cycle of Off switches the lamp on, and the account says so");

    if (failures == 0) std::puts("latency_test: all checks passed");
    return failures == 0 ? 0 : 1;
}
