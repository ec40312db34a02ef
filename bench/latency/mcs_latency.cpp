// The dispatch latency of the Mode Control Supervisor (examples/mcs), pair by pair: every panel
// event in every reachable state (bsc::measure_latency, <bsc/benchmark.hpp>). Prints the report;
// with --benchmark, also times the slowest pairs with Google Benchmark (its flags follow).
// Under callgrind the figures are instructions. docs/benchmarks.md shows its output.

#include <cstdio>
#include <cstring>

#include <bsc/benchmark.hpp>
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "mcs/mcs.hpp"

// The display only logs what Show printed: left out of the explored state.
template <>
inline constexpr bool bsc::transient<mcs::display> = true;

int main(int argc, char** argv) {
    bsc::verify::event_model<mcs::machine, mcs::on_p, mcs::off_p, mcs::estop_p, mcs::reset_p, mcs::mem_p, mcs::mdi_p,
                             mcs::tape_p, mcs::hnd_p, mcs::jog_p, mcs::rpd_p, mcs::zrn_p, mcs::edit_p, mcs::setup_p>
        model{mcs::machine{mcs::chart, mcs::panel{}}};
    auto const report = bsc::measure_latency(model);
    std::fputs(report.to_string().c_str(), stdout);
    if (argc > 1 && std::strcmp(argv[1], "--benchmark") == 0) {
        bsc::register_latency_benchmarks("mcs", model, report);
        ::benchmark::Initialize(&argc, argv);
        ::benchmark::RunSpecifiedBenchmarks();
    }
    return report.complete && !report.worst.empty() ? 0 : 1;
}
