// The manufacturing cell at work: the controller of the Basic Statechart paper (controller.hpp)
// runs in closed loop with a plant model (plant.hpp) at a fixed scan period, and every cycle is
// checked against the paper's requirements (monitor.hpp).
//
//   manufacturing_cell [--pieces N] [--seed S] [--period MS] [--quiet] [--vcd FILE] [--trace FILE]
//
// Without --seed the pieces arrive by a fixed script (a steady start, a burst, stragglers);
// with --seed they arrive at random gaps of 0.5 s to 12 s drawn from that seed. The trace has one
// line per cycle in which an output, a sensor or a component's state changes:
//
//        t [s]  Belt Drill Test Robot Table      | outputs                     | sensors            | E1-4
//        2.900  Done On    Off  Off   Returned   | ---- drill ---- ----- ----- | -- -- P2 -- -- --  | 1011
//
// (the time of the cycle, the active state of each component after it, the outputs it
// published, the sensors it latched, and E1..E4 after it)
//
// When the cell has nothing to do, the belt alternates between Off and Done while E1..E4 are
// set and reset (the paper's empty cell); after its first two cycles such a run is folded into
// one line. The run exits with status 1 if a piece was not stored or a requirement was
// violated. With --vcd every cycle is also recorded in FILE as a waveform (bsc::vcd_recorder:
// the components' states, the sensors, the actuators, E1..E4 and the timers), for GTKWave.
// With --trace it is recorded in FILE as a trace stream (bsc::tracer, docs/trace.md): every
// cycle, exit, transition and entry, and the values that changed, for the inspector's page.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <bsc/trace.hpp>
#include <bsc/vcd.hpp>

#include "controller.hpp"
#include "monitor.hpp"
#include "plant.hpp"

namespace {

using namespace std::chrono_literals;

struct options {
    int pieces = 8;
    bool random = false;
    std::uint32_t seed = 0;
    bsc::duration period = 100ms;
    bool quiet = false;
    std::string vcd;    // the waveform file, if any
    std::string trace;  // the trace file, if any
};

// The example's machine: the controller with a tracer, whose frames are read only with --trace.
using machine = bsc::machine<bsc::chart_ref<cell::chart>, bsc::scan_policy, bsc::tracer<decltype(cell::chart)>>;

// The active state of each component, in the paper's order.
struct snapshot {
    std::string_view belt, drill, test, robot, table;
    cell::actuators out;
    cell::sensors in;
    bool operator==(snapshot const&) const = default;
};

snapshot take(machine const& m, cell::sensors const& in) {
    snapshot s;
    s.belt = m.is<cell::BeltOn>() ? "On" : m.is<cell::BeltDone>() ? "Done" : "Off";
    s.drill = m.is<cell::DrillOn>() ? "On" : "Off";
    s.test = m.is<cell::TestOn>() ? "On" : "Off";
    s.robot = m.is<cell::RobotOn>() ? "On" : "Off";
    s.table = m.is<cell::CylinderAdvancing>()   ? "Advancing"
              : m.is<cell::CylinderReturning>() ? "Returning"
                                                : "Returned";
    s.out = cell::read_outputs(m.context());
    s.in = in;
    return s;
}

// Only the belt's Off/Done differs: a phase in which nothing had to be done.
bool only_belt_idles(snapshot const& a, snapshot const& b) {
    snapshot x = a;
    x.belt = b.belt;
    return x == b && a.belt != "On" && b.belt != "On";
}

void print_header() {
    std::printf(
        "    t [s]  Belt Drill Test Robot Table      | outputs                     | sensors            | E1-4\n");
}

void print_line(bsc::duration t, snapshot const& s, cell::data const& d) {
    auto const on = [](bool b, char const* name, char const* off) { return b ? name : off; };
    std::printf("%9.3f  %-4s %-5s %-4s %-5s %-10s | %s %s %s %s %s | %s %s %s %s %s %s  | %d%d%d%d\n",
                std::chrono::duration<double>(t).count(), s.belt.data(), s.drill.data(), s.test.data(), s.robot.data(),
                s.table.data(), on(s.out.belt, "belt", "----"), on(s.out.drill, "drill", "-----"),
                on(s.out.test, "test", "----"), on(s.out.robot, "robot", "-----"), on(s.out.valve, "valve", "-----"),
                on(s.in.IN, "IN", "--"), on(s.in.P1, "P1", "--"), on(s.in.P2, "P2", "--"), on(s.in.P3, "P3", "--"),
                on(s.in.P4, "P4", "--"), on(s.in.S1, "S1", "--"), d.E1, d.E2, d.E3, d.E4);
}

std::vector<bsc::duration> scripted_arrivals(int pieces) {
    // A steady start (one piece every 6 s), a burst of three, then stragglers every 20 s.
    std::vector<bsc::duration> times;
    for (int i = 0; i < pieces; ++i) {
        if (i < 3)
            times.push_back(i * 6s);
        else if (i < 6)
            times.push_back(20s);
        else
            times.push_back(20s + (i - 5) * 20s);
    }
    return times;
}

// Prints the usage text to `to`; returns the exit status: 0 when asked for, 2 after a wrong flag.
int usage(std::FILE* to, int status) {
    std::fprintf(
        to,
        "usage: manufacturing_cell [--pieces N] [--seed S] [--period MS] [--quiet] [--vcd FILE] [--trace FILE]\n"
        "Runs pieces through the manufacturing cell in closed loop with its plant and checks the run.\n"
        "  --pieces N   pieces to run through the cell, 0 to 10000 (default: 8)\n"
        "  --seed S     random arrivals from seed S (default: the fixed script of arrivals)\n"
        "  --period MS  scan period in milliseconds, 1 to 1000 (default: 100)\n"
        "  --quiet      print the summary only (default: print every piece's events too)\n"
        "  --vcd FILE   record every cycle in FILE as a value change dump, for GTKWave (default: none)\n"
        "  --trace FILE record every cycle in FILE as a trace stream, for the inspector (default: none)\n"
        "  -h, --help   print this text and exit\n");
    return status;
}

bool parse(int argc, char** argv, options& o) {
    for (int i = 1; i < argc; ++i) {
        std::string_view const a = argv[i];
        auto const value = [&](long& v) {
            if (i + 1 >= argc) return false;
            char* end = nullptr;
            v = std::strtol(argv[++i], &end, 10);
            return end != nullptr && *end == '\0';
        };
        long v = 0;
        if (a == "--quiet") {
            o.quiet = true;
        } else if (a == "--pieces" && value(v) && v >= 0 && v <= 10000) {
            o.pieces = static_cast<int>(v);
        } else if (a == "--seed" && value(v) && v >= 0) {
            o.random = true;
            o.seed = static_cast<std::uint32_t>(v);
        } else if (a == "--vcd" && i + 1 < argc) {
            o.vcd = argv[++i];
        } else if (a == "--trace" && i + 1 < argc) {
            o.trace = argv[++i];
        } else if (a == "--period" && value(v) && v > 0 && v <= 1000) {
            o.period = std::chrono::milliseconds{v};
        } else {
            return false;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    options o;
    for (int i = 1; i < argc; ++i)
        if (std::string_view{argv[i]} == "--help" || std::string_view{argv[i]} == "-h") return usage(stdout, 0);
    if (!parse(argc, argv, o)) return usage(stderr, 2);
    auto const arrivals = o.random ? cell::arrivals::random(o.pieces, o.seed, 500ms, 12s) : scripted_arrivals(o.pieces);

    auto const ms = [](bsc::duration d) {
        return static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(d).count());
    };
    std::printf("Manufacturing cell: %d pieces (%s), scan period %ld ms, T1 %ld ms, T2 %ld ms, T3 %ld ms\n", o.pieces,
                o.random ? ("random arrivals, seed " + std::to_string(o.seed)).c_str() : "scripted arrivals",
                ms(o.period), ms(cell::drill_time), ms(cell::test_time), ms(cell::robot_time));

    // The trace's ring, drained after every cycle: 64 KiB holds the dictionary and many cycles.
    static std::array<std::byte, 1 << 16> trace_storage;
    bsc::trace_buffer trace_buffer{o.trace.empty() ? std::span<std::byte>{} : std::span<std::byte>{trace_storage}};
    std::ofstream trace_file;
    if (!o.trace.empty()) {
        trace_file.open(o.trace, std::ios::binary);
        if (!trace_file) {
            std::fprintf(stderr, "manufacturing_cell: cannot write %s\n", o.trace.c_str());
            return 2;
        }
    }
    auto const drain_trace = [&] {
        std::array<std::byte, 4096> chunk;
        while (std::size_t const n = trace_buffer.read(chunk))
            trace_file.write(reinterpret_cast<char const*>(chunk.data()), static_cast<std::streamsize>(n));
    };

    machine m{cell::chart, cell::data{}, bsc::tracer{cell::chart, trace_buffer}};
    cell::closed_loop loop{m, arrivals, o.period};
    std::ofstream vcd_file;
    std::optional<bsc::vcd_recorder<machine>> vcd;
    if (!o.vcd.empty()) {
        vcd_file.open(o.vcd);
        if (!vcd_file) {
            std::fprintf(stderr, "manufacturing_cell: cannot write %s\n", o.vcd.c_str());
            return 2;
        }
        vcd.emplace(vcd_file, m);
    }
    // Enough for every piece to go through the cell one after the other, after the last arrival.
    bsc::duration const last_arrival = arrivals.empty() ? bsc::duration{} : arrivals.back();
    long const max_cycles = static_cast<long>((last_arrival + (o.pieces + 5) * 30s) / o.period);

    if (!o.quiet) print_header();
    snapshot last{}, before_last{};
    long cycle = 0;
    long folded = 0;
    auto const flush = [&] {
        if (folded > 0)
            std::printf(
                "           ... %ld more cycles: the belt alternates Off/Done, E1..E4 are set and reset"
                " (empty phases, g15)\n",
                folded);
        folded = 0;
    };
    while (!loop.done() && loop.cycles() < max_cycles) {
        cell::cycle_record const r = loop.cycle();
        if (vcd) vcd->sample();
        if (trace_file.is_open()) {
            m.observer().sample(m);
            drain_trace();
        }
        snapshot const now = take(m, r.latched);
        if (!o.quiet && (cycle == 0 || now != last)) {
            // An empty phase alternates two snapshots that differ only in the belt's state.
            if (cycle >= 2 && now == before_last && only_belt_idles(last, now)) {
                ++folded;
            } else {
                flush();
                print_line(r.time, now, m.context());
            }
        }
        before_last = last;
        last = now;
        ++cycle;
    }
    if (!o.quiet) flush();
    bool const finished = loop.run(max_cycles);  // checks the end of the run

    cell::plant const& p = loop.plant();
    std::printf("\nsummary: %zu pieces in, %zu stored, %d table turns, %ld cycles (%.1f s)\n", p.pieces().size(),
                p.stored(), p.turns(), loop.cycles(), std::chrono::duration<double>(loop.cycles() * o.period).count());
    for (cell::piece const& x : p.pieces())
        if (!o.quiet)
            std::printf("  piece %d: in at %.1f s, drilled %d, tested %d, %s at %.1f s\n", x.id,
                        std::chrono::duration<double>(x.arrived).count(), x.drilled, x.tested,
                        x.stored ? "stored" : "NOT stored", std::chrono::duration<double>(x.stored_at).count());

    bool ok = finished && loop.monitor().ok();
    if (vcd) {
        vcd_file.flush();
        if (vcd_file) {
            std::printf("waveform: %zu samples of %zu variables in %s\n", vcd->samples(), vcd->variables(),
                        o.vcd.c_str());
        } else {
            std::printf("FAILED: could not write the waveform to %s\n", o.vcd.c_str());
            ok = false;
        }
    }
    if (trace_file.is_open()) {
        trace_file.flush();
        if (trace_file && trace_buffer.dropped() == 0) {
            std::printf("trace: %llu frames in %s\n", static_cast<unsigned long long>(trace_buffer.written()),
                        o.trace.c_str());
        } else {
            std::printf("FAILED: could not write the whole trace to %s\n", o.trace.c_str());
            ok = false;
        }
    }
    if (!finished) std::printf("FAILED: not every piece was stored within %ld cycles\n", max_cycles);
    for (std::string const& v : loop.monitor().violations()) std::printf("VIOLATION %s\n", v.c_str());
    if (ok)
        std::printf("ok: every piece drilled, tested and stored; constraints 1-3, synchronisation and timing held\n");
    return ok ? 0 : 1;
}
