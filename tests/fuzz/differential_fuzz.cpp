// libFuzzer target: the compiled and the table-driven back ends, fed the same events, must
// agree after every event (see tests/unit/differential.hpp). The first byte of an input picks
// a chart; each following pair of bytes is one step: an event of the chart (or an unhandled
// event, or a write to the context by the environment) and its data. Any difference aborts.
//
// Build with -DBSC_BUILD_FUZZERS=ON and Clang; run e.g. `differential_fuzz -max_total_time=300`.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../../examples/mcs/mcs.hpp"
#include "../unit/differential.hpp"
#include "../unit/fixtures.hpp"
#include "../unit/generated_charts.hpp"

namespace {

struct mcs_fixture {
    using policy = bsc::default_policy;
    static constexpr auto const& chart = mcs::chart;
    static mcs::panel initial() { return {}; }
    static void perturb(mcs::panel& p, std::uint32_t) { p.display.clear(); }
    static bool same(mcs::panel const& a, mcs::panel const& b) {
        return a.error == b.error && a.display.text() == b.display.text();
    }
};

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
    if (size == 0)
        return 0;
    std::uint8_t const* events = data + 1;
    std::size_t const n = size - 1;
    switch (data[0] % 13) {
        case 0: drive<fx::hierarchy>("hierarchy", events, n); break;
        case 1: drive<fx::parallel>("parallel", events, n); break;
        case 2: drive<fx::history>("history", events, n); break;
        case 3: drive<fx::conditions>("conditions", events, n); break;
        case 4: drive<fx::raising>("raising", events, n); break;
        case 5: drive<fx::halting>("halting", events, n); break;
        case 6: drive<mcs_fixture>("mcs", events, n); break;
        case 7: drive<gen::generated<1>>("generated 1", events, n); break;
        case 8: drive<gen::generated<2>>("generated 2", events, n); break;
        case 9: drive<gen::generated<3>>("generated 3", events, n); break;
        case 10: drive<gen::generated<5>>("generated 5", events, n); break;
        case 11: drive<gen::generated<7>>("generated 7", events, n); break;
        default: drive<gen::generated<8>>("generated 8", events, n); break;
    }
    return 0;
}
