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
    std::cout << "machine of " << sizeof(machine) << " bytes\n";
}

}  // namespace probe_driver
