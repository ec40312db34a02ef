// The cost of one execution cycle of the manufacturing cell controller (examples/
// manufacturing_cell): bsc's machine::step next to a hand-written scan loop of the same
// controller, as a PLC programmer would write it in C++ (enums, switch, if; an input image
// latched at the start of the scan, an output image published at its end; the BSC timers).
//
// Both replay the same recorded sequence of inputs: the plant model is run once in closed
// loop with the bsc controller, and the inputs it presented on each cycle are recorded, so
// that the timed loops measure the controllers alone. Before any timing, both controllers are
// run over the whole recording and must publish the same outputs on every cycle (and the
// outputs recorded in closed loop); otherwise the benchmark aborts.
//
//   cmake --preset release && cmake --build --preset release -j1 --target bench_manufacturing_cell
//   ./build/release/bench/bench_manufacturing_cell --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true        (one command line)
//
// `per_cycle` is the time of one execution cycle (inputs written, one step, outputs read).
//
// Built with BENCH_CELL_INSNS defined (target bench_manufacturing_cell_insns), the same file is
// the driver of the instruction counts, as bench/insns_main.cpp is for the other workloads:
// `bench_manufacturing_cell_insns IMPLEMENTATION CYCLES` runs CYCLES cycles of the recording
// (from a fresh controller each time round) with bsc_compiled or hand_written;
// scripts/benchmarks.py counts them with callgrind, with CYCLES and with none.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "../examples/manufacturing_cell/controller.hpp"
#include "../examples/manufacturing_cell/monitor.hpp"
#include "../examples/manufacturing_cell/plant.hpp"

namespace {

using namespace std::chrono_literals;

// ---- The hand-written scan loop ------------------------------------------------------------

namespace scan {

/// A BSC timer (the Basic Statechart paper [BSC] in docs/references.md, section III.C), as
/// docs/semantics.md states it: start() during cycle k, timing from cycle k+1, tm at the first
/// cycle at least `limit` after that.
struct timer {
    enum class phase : std::uint8_t { idle, pending, running };
    bsc::duration limit{};
    bsc::duration started{};
    phase ph = phase::idle;
    bool tm = false;

    void start() {
        ph = phase::pending;
        tm = false;
    }
    void reset() {
        ph = phase::idle;
        tm = false;
    }
    void update(bsc::duration now) {
        if (ph == phase::pending) {
            ph = phase::running;
            started = now;
        }
        if (ph == phase::running && now - started >= limit) tm = true;
    }
};

enum class belt_state : std::uint8_t { off, on, done };
enum class device_state : std::uint8_t { off, on };
enum class table_state : std::uint8_t { returned, advancing, returning };

/// The controller of the paper's Fig. 6 as a scan: the components in the paper's order, each
/// taking at most one transition per scan, with the guards g1..g15 of Table I.
struct controller {
    // Process images: `pending` is written by the plant between scans, latched into `in` at
    // the start of a scan; `next` is written by the logic, published into `out` at its end.
    cell::sensors pending{};
    cell::sensors in{};
    cell::actuators next{};
    cell::actuators out{};
    bool E1 = false, E2 = false, E3 = false, E4 = false;
    timer T1{cell::drill_time}, T2{cell::test_time}, T3{cell::robot_time};
    belt_state belt = belt_state::off;
    device_state drill = device_state::off, test = device_state::off, robot = device_state::off;
    table_state table = table_state::returned;

    void scan(bsc::duration now) {
        T1.update(now);
        T2.update(now);
        T3.update(now);
        in = pending;

        switch (belt) {
        case belt_state::off:
            if (!in.P1 && !E1 && in.IN) {  // g1
                next.belt = true;
                belt = belt_state::on;
            } else if (!in.P1 && !E1 && !in.IN) {  // g3
                E1 = true;
                belt = belt_state::done;
            }
            break;
        case belt_state::on:
            if (in.P1) {  // g2
                next.belt = false;
                E1 = true;
                belt = belt_state::done;
            }
            break;
        case belt_state::done:
            if (!E1) belt = belt_state::off;  // a new phase
            break;
        }

        switch (drill) {
        case device_state::off:
            if (in.P2 && !E2) {  // g4
                next.drill = true;
                T1.start();
                drill = device_state::on;
            } else if (!in.P2 && !E2) {  // g6
                E2 = true;
            }
            break;
        case device_state::on:
            if (T1.tm) {  // g5
                next.drill = false;
                T1.reset();
                E2 = true;
                drill = device_state::off;
            }
            break;
        }

        switch (test) {
        case device_state::off:
            if (in.P3 && !E3) {  // g7
                next.test = true;
                T2.start();
                test = device_state::on;
            } else if (!in.P3 && !E3) {  // g9
                E3 = true;
            }
            break;
        case device_state::on:
            if (T2.tm) {  // g8
                next.test = false;
                T2.reset();
                E3 = true;
                test = device_state::off;
            }
            break;
        }

        switch (robot) {
        case device_state::off:
            if (in.P4 && !E4) {  // g10
                next.robot = true;
                T3.start();
                robot = device_state::on;
            } else if (!in.P4 && !E4) {  // g12
                E4 = true;
            }
            break;
        case device_state::on:
            if (T3.tm) {  // g11
                next.robot = false;
                T3.reset();
                E4 = true;
                robot = device_state::off;
            }
            break;
        }

        switch (table) {
        case table_state::returned:
            if (E1 && E2 && E3 && E4 && (in.P1 || in.P2 || in.P3)) {  // g13
                next.valve = true;
                table = table_state::advancing;
            } else if (E1 && E2 && E3 && E4 && !in.P1 && !in.P2 && !in.P3) {  // g15
                E1 = E2 = E3 = E4 = false;
            }
            break;
        case table_state::advancing:
            if (in.S1) {  // g14
                next.valve = false;
                table = table_state::returning;
            }
            break;
        case table_state::returning:
            if (!in.S1) {  // the arm has left its end position: a new phase
                E1 = E2 = E3 = E4 = false;
                table = table_state::returned;
            }
            break;
        }

        out = next;
    }
};

/// A scan controller in the state the bsc machine is in.
controller like(cell::machine const& m) {
    controller c;
    auto const& d = m.context();
    c.E1 = d.E1;
    c.E2 = d.E2;
    c.E3 = d.E3;
    c.E4 = d.E4;
    c.belt = m.is<cell::BeltOn>() ? belt_state::on : m.is<cell::BeltDone>() ? belt_state::done : belt_state::off;
    c.drill = m.is<cell::DrillOn>() ? device_state::on : device_state::off;
    c.test = m.is<cell::TestOn>() ? device_state::on : device_state::off;
    c.robot = m.is<cell::RobotOn>() ? device_state::on : device_state::off;
    c.table = m.is<cell::CylinderAdvancing>()   ? table_state::advancing
              : m.is<cell::CylinderReturning>() ? table_state::returning
                                                : table_state::returned;
    c.out = c.next = cell::read_outputs(d);
    return c;
}

}  // namespace scan

// ---- The recorded input sequence -------------------------------------------------------------

struct recorded_cycle {
    bsc::duration time{};
    cell::sensors in;
    cell::actuators out;
};

constexpr bsc::duration period = 100ms;

unsigned pack(cell::actuators const& a) {
    return unsigned(a.belt) | unsigned(a.drill) << 1 | unsigned(a.test) << 2 | unsigned(a.robot) << 3 |
           unsigned(a.valve) << 4;
}

[[noreturn]] void fail(char const* what, std::size_t cycle) {
    std::fprintf(stderr, "bench_manufacturing_cell: %s at cycle %zu\n", what, cycle);
    std::abort();
}

/// 40 pieces at random gaps (seed 1), in closed loop until every piece is stored.
std::vector<recorded_cycle> record() {
    cell::machine m{cell::chart};
    cell::closed_loop loop{m, cell::arrivals::random(40, 1, 500ms, 8s), period};
    std::vector<recorded_cycle> cycles;
    while (!loop.done() && loop.cycles() < 100000) {
        cell::cycle_record const r = loop.cycle();
        cycles.push_back({r.time, r.latched, r.out});
    }
    if (!loop.run(100000) || !loop.monitor().ok()) fail("the recording run did not complete cleanly", cycles.size());
    return cycles;
}

/// Runs both controllers over the recording; aborts at the first cycle where they differ.
void check_equivalence(std::vector<recorded_cycle> const& rec) {
    cell::machine m{cell::chart};
    scan::controller c = scan::like(m);
    for (std::size_t i = 0; i < rec.size(); ++i) {
        cell::write_inputs(m.context(), rec[i].in);
        m.step(rec[i].time);
        c.pending = rec[i].in;
        c.scan(rec[i].time);
        cell::actuators const a = cell::read_outputs(m.context());
        if (!(a == rec[i].out)) fail("bsc differs from the closed-loop recording", i);
        if (!(c.out == a)) fail("the scan loop and bsc publish different outputs", i);
        auto const& d = m.context();
        if (c.E1 != d.E1 || c.E2 != d.E2 || c.E3 != d.E3 || c.E4 != d.E4)
            fail("the scan loop and bsc hold different E1..E4", i);
    }
}

std::vector<recorded_cycle> const& recording() {
    static std::vector<recorded_cycle> const rec = [] {
        auto r = record();
        check_equivalence(r);
        return r;
    }();
    return rec;
}

// One replay of `cycles` cycles of the recording by a controller, from its starting state,
// starting again whenever the recording ends (time must not run backwards within a run):
// `cycle(controller, recorded)` runs one cycle and returns the outputs it published, packed.
template <class Controller, class Cycle>
unsigned replay(std::vector<recorded_cycle> const& rec, Controller const& start, std::size_t cycles, Cycle cycle) {
    Controller c = start;
    unsigned acc = 0;
    for (std::size_t i = 0; i < cycles; ++i) {
        if (i % rec.size() == 0) c = start;
        acc += cycle(c, rec[i % rec.size()]);
    }
    return acc;
}

unsigned replay_bsc(std::vector<recorded_cycle> const& rec, cell::machine const& start, std::size_t cycles) {
    return replay(rec, start, cycles, [](cell::machine& m, recorded_cycle const& r) {
        cell::write_inputs(m.context(), r.in);
        m.step(r.time);
        return pack(cell::read_outputs(m.context()));
    });
}

unsigned replay_scan(std::vector<recorded_cycle> const& rec, scan::controller const& start, std::size_t cycles) {
    return replay(rec, start, cycles, [](scan::controller& c, recorded_cycle const& r) {
        c.pending = r.in;
        c.scan(r.time);
        return pack(c.out);
    });
}

#if !defined(BENCH_CELL_INSNS)
void report(benchmark::State& state, std::size_t cycles) {
    auto const total = static_cast<double>(cycles) * static_cast<double>(state.iterations());
    state.SetItemsProcessed(static_cast<std::int64_t>(total));
    state.counters["cycles"] = static_cast<double>(cycles);
    state.counters["per_cycle"] = benchmark::Counter(total, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Each iteration replays the whole recording from the starting state (a copy of a freshly
// constructed controller, which costs a few hundred bytes of copying per replay).

void bm_bsc_step(benchmark::State& state) {
    auto const& rec = recording();
    cell::machine const start{cell::chart};
    for (auto _ : state) benchmark::DoNotOptimize(replay_bsc(rec, start, rec.size()));
    report(state, rec.size());
}

void bm_hand_written_scan(benchmark::State& state) {
    auto const& rec = recording();
    scan::controller const start = scan::like(cell::machine{cell::chart});
    for (auto _ : state) benchmark::DoNotOptimize(replay_scan(rec, start, rec.size()));
    report(state, rec.size());
}

#endif

}  // namespace

#if defined(BENCH_CELL_INSNS)
int main(int argc, char** argv) {
    bool const asked = argc == 2 && (std::string_view{argv[1]} == "--help" || std::string_view{argv[1]} == "-h");
    if (argc != 3 || asked || argv[1][0] == '-') {  // a flag other than --help is unknown
        std::fprintf(asked ? stdout : stderr,
                     "usage: %s IMPLEMENTATION CYCLES\n"
                     "Runs CYCLES scan cycles of the manufacturing cell's controller and prints a checksum\n"
                     "(no flags, no defaults: both arguments are required).\n"
                     "  -h, --help  print this text and exit\n"
                     "IMPLEMENTATION is one of:\n  bsc_compiled\n  hand_written\n",
                     argv[0]);
        if (asked) return 0;
        return 2;
    }
    std::string_view const impl = argv[1];
    std::size_t const cycles = std::strtoull(argv[2], nullptr, 10);
    auto const& rec = recording();
    unsigned acc = 0;
    if (impl == "bsc_compiled")
        acc = replay_bsc(rec, cell::machine{cell::chart}, cycles);
    else if (impl == "hand_written")
        acc = replay_scan(rec, scan::like(cell::machine{cell::chart}), cycles);
    else
        return std::fprintf(stderr, "%s: no implementation %s\n", argv[0], argv[1]), 2;
    std::printf("cell %s %zu %x\n", argv[1], cycles, acc);
    return 0;
}
#else
BENCHMARK(bm_bsc_step);
BENCHMARK(bm_hand_written_scan);
#endif
