#pragma once
// The small program around a chart in the header and small-chart compile-time probes: what the
// peers' benchmark programs include around theirs (<chrono> to time a loop, <iostream> to print
// the time and the machine's size), so that a probe and a peer's program differ only by the
// library and the chart (scripts/peer_compile.py, scripts/perf_gate.py).

#include <chrono>
#include <iostream>

namespace probe_driver {

template <class Loop>
void time_loop(Loop const& loop) {
    auto const start = std::chrono::steady_clock::now();
    loop();
    auto const took = std::chrono::steady_clock::now() - start;
    std::cout << "took " << std::chrono::duration_cast<std::chrono::milliseconds>(took).count() << " ms\n";
}

template <class Machine>
void print_size(Machine const& machine) {
    std::cout << "it takes " << sizeof(machine) << " bytes\n";
}

// The program of the header probes: a loop timed and a size printed, with no chart, so that a
// probe differs from its reference by an #include only.
inline int program_without_chart() {
    int counted = 0;
    time_loop([&] {
        for (int i = 0; i < 1'000'000; ++i) counted += i & 1;
    });
    print_size(counted);
    return 0;
}

}  // namespace probe_driver
