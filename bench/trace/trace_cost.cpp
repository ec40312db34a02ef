// What a trace stream costs a machine (bsc::tracer, docs/trace.md): the MCS (examples/mcs) on
// the mcs workload's 10,000 recorded presses, without an observer and traced into a 64 KiB
// ring that is drained every 256 presses, as a program that writes the trace out would.
//
//   bench_trace_cost                          Google Benchmark: both, side by side
//   bench_trace_cost --presses N untraced|traced
//                                             N presses and no timing, for callgrind: the
//                                             instructions per press are (count(N) - count(0)) / N;
//                                             prints the frames and bytes written per press

#include <benchmark/benchmark.h>

#include <bsc/bsc.hpp>
#include <bsc/trace.hpp>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "../../examples/mcs/mcs.hpp"
#include "../mcs/mcs_buttons.hpp"
#include "../mcs/mcs_workload.hpp"

namespace {

using tracer = bsc::tracer<decltype(mcs::chart)>;
using untraced = bsc::machine<bsc::chart_ref<mcs::chart>>;
using traced = bsc::machine<bsc::chart_ref<mcs::chart>, bsc::default_policy, tracer>;

std::array<std::byte, 1 << 16> storage;
std::array<std::byte, 4096> sink;
std::size_t drained = 0;  // the bytes read out of the ring

// Presses `count` buttons of the recorded sequence, draining the ring every 256.
template <class Machine>
[[gnu::noinline]] void press(Machine& m, bsc::trace_buffer& buffer, bench::sequence const& presses, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        bench::with_index<mcs_bench::event_count>(presses[i % presses.size()], [&](auto b) {
            m.dispatch(typename mcs_bench::button_at<decltype(b)::value>::type{});
        });
        if (i % 256 == 255)
            while (std::size_t const n = buffer.read(sink)) drained += n;
    }
}

void untraced_presses(benchmark::State& state) {
    auto const presses = mcs_bench::workload::record();
    bsc::trace_buffer buffer{storage};
    untraced m{mcs::chart};
    for (auto _ : state) press(m, buffer, presses, presses.size());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(presses.size()));
}

void traced_presses(benchmark::State& state) {
    auto const presses = mcs_bench::workload::record();
    bsc::trace_buffer buffer{storage};
    traced m{mcs::chart, mcs::panel{}, tracer{mcs::chart, buffer}};
    for (auto _ : state) press(m, buffer, presses, presses.size());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(presses.size()));
    state.counters["dropped"] = static_cast<double>(buffer.dropped());
}

BENCHMARK(untraced_presses);
BENCHMARK(traced_presses);

}  // namespace

int main(int argc, char** argv) {
    if (argc == 4 && std::string_view{argv[1]} == "--presses") {
        std::size_t const count = std::strtoull(argv[2], nullptr, 10);
        std::string_view const which = argv[3];
        auto const presses = mcs_bench::workload::record();
        bsc::trace_buffer buffer{storage};
        if (which == "untraced") {
            untraced m{mcs::chart};
            press(m, buffer, presses, count);
            return m.context().error < 0;
        }
        if (which != "traced") return 2;
        traced m{mcs::chart, mcs::panel{}, tracer{mcs::chart, buffer}};
        std::size_t const dictionary = buffer.size();
        std::uint64_t const before = buffer.written();
        while (buffer.read(sink) != 0) {
        }
        drained = 0;
        press(m, buffer, presses, count);
        std::size_t const bytes = drained + buffer.size();
        if (count > 0)
            std::printf("dictionary %zu bytes; per press: %.2f frames, %.2f bytes; dropped %llu\n", dictionary,
                        static_cast<double>(buffer.written() - before) / static_cast<double>(count),
                        static_cast<double>(bytes) / static_cast<double>(count),
                        static_cast<unsigned long long>(buffer.dropped()));
        return 0;
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
