// Exploration speed of bsc::verify on the manufacturing cell in closed loop
// (examples/manufacturing_cell/verification.hpp): states explored per second, one core.

#include <benchmark/benchmark.h>

#include <chrono>

#include "../examples/manufacturing_cell/verification.hpp"

namespace {
void explore_cell(benchmark::State& state) {
    auto const scan = std::chrono::milliseconds{state.range(0)};
    std::size_t states = 0, transitions = 0, key = 0;
    for (auto _ : state) {
        bsc::verify::explorer ex{cell::finite::model(cell::chart, scan)};
        auto const& st = ex.run();
        states = st.states;
        transitions = st.transitions;
        key = st.key_bytes;
        benchmark::DoNotOptimize(st.states);
    }
    state.counters["states"] = static_cast<double>(states);
    state.counters["transitions"] = static_cast<double>(transitions);
    state.counters["key_bytes"] = static_cast<double>(key);
    state.counters["states_per_s"] =
        benchmark::Counter(static_cast<double>(states) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate);
}
}  // namespace

// Scan periods of 500, 100 and 50 ms: the same cell, more cycles per timer, more states.
BENCHMARK(explore_cell)->Arg(500)->Arg(100)->Arg(50)->Unit(benchmark::kMillisecond);
