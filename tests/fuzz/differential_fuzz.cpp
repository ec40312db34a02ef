// libFuzzer target: the compiled and the table-driven back ends, fed the same events and the
// same execution cycles, must agree after every step (see tests/unit/differential.hpp). The
// first byte of an input picks a chart; each following pair of bytes is one step: an event of
// the chart, an unhandled event, a write to the context by the environment, or a cycle,
// step(now), at a time the second byte moves on from the last cycle's (bsc_diff::next_time:
// by nothing, by a few milliseconds, by seconds, or backwards). Any difference aborts.
//
// Build with -DBSC_BUILD_FUZZERS=ON and Clang; run e.g. `differential_fuzz -max_total_time=300`.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../unit/differential.hpp"
#include "../unit/differential_examples.hpp"
#include "../unit/fixtures.hpp"
#include "../unit/generated_charts.hpp"

namespace {

template <class Fixture>
void drive(char const* name, std::uint8_t const* data, std::size_t size) {
    bsc_diff::twin<Fixture> twin;
    std::string diff = twin.start();
    for (std::size_t i = 0; diff.empty() && i + 1 < size; i += 2)
        diff = twin.step(data[i] % bsc_diff::twin<Fixture>::choices, data[i + 1]);
    if (!diff.empty()) {
        std::fprintf(stderr, "back ends differ on chart %s %s\n", name, diff.c_str());
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
    if (size == 0) return 0;
    std::uint8_t const* steps = data + 1;
    std::size_t const n = size - 1;
    switch (data[0] % 23) {
        case 0: drive<fx::hierarchy>("hierarchy", steps, n); break;
        case 1: drive<fx::parallel>("parallel", steps, n); break;
        case 2: drive<fx::history>("history", steps, n); break;
        case 3: drive<fx::conditions>("conditions", steps, n); break;
        case 4: drive<fx::raising>("raising", steps, n); break;
        case 5: drive<fx::halting>("halting", steps, n); break;
        case 6: drive<bsc_diff::mcs_fixture>("mcs", steps, n); break;
        case 7: drive<fx::cycles>("cycles", steps, n); break;
        case 8: drive<fx::scan_cycles>("cycles, scan policy", steps, n); break;
        case 9: drive<bsc_diff::cell_fixture>("manufacturing cell", steps, n); break;
        case 10: drive<gen::generated<1>>("generated 1", steps, n); break;
        case 11: drive<gen::generated<2>>("generated 2", steps, n); break;
        case 12: drive<gen::generated<3>>("generated 3", steps, n); break;
        case 13: drive<gen::generated<7>>("generated 7", steps, n); break;
        case 14: drive<gen::generated<8>>("generated 8", steps, n); break;
        case 15: drive<gen::generated_scan<5>>("generated 5, scan policy", steps, n); break;
        case 16: drive<gen::generated_scan<9>>("generated 9, scan policy", steps, n); break;
        case 17: drive<fx::beyond_core>("beyond the core", steps, n); break;
        case 18: drive<gen::parent_first<1>>("parent-first generated 1", steps, n); break;
        case 19: drive<gen::parent_first<3>>("parent-first generated 3", steps, n); break;
        case 20: drive<gen::parent_first_scan<5>>("parent-first generated 5, scan policy", steps, n); break;
        case 21: drive<gen::parent_first_scan<9>>("parent-first generated 9, scan policy", steps, n); break;
        default: drive<gen::generated_scan<11>>("generated 11, scan policy", steps, n); break;
    }
    return 0;
}
