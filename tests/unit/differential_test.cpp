// The compiled and the table-driven back ends, driven with the same random events, must agree
// after every event: outcome, configuration bytes, active states, is<S>(), context and the
// observer's full trace. Charts: the hand-written fixtures of fixtures.hpp, the Mode Control
// Supervisor of examples/mcs, and charts generated at compile time (generated_charts.hpp).

#include <doctest/doctest.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "../../examples/mcs/mcs.hpp"
#include "differential.hpp"
#include "fixtures.hpp"
#include "generated_charts.hpp"

namespace {

constexpr int events_per_chart = 10'000;

struct mcs_fixture {
    using policy = bsc::default_policy;
    static constexpr auto const& chart = mcs::chart;
    static mcs::panel initial() { return {}; }
    static void perturb(mcs::panel& p, std::uint32_t) { p.display.clear(); }
    static bool same(mcs::panel const& a, mcs::panel const& b) {
        return a.error == b.error && a.display.text() == b.display.text();
    }
};

// Runs events_per_chart random steps; returns the first difference, or "".
template <class Fixture>
std::string run_differential(std::uint32_t seed, char const* label) {
    auto const t0 = std::chrono::steady_clock::now();
    bsc_diff::twin<Fixture> twin;
    std::mt19937 rng{seed};
    std::string diff = twin.start();
    for (int i = 0; i < events_per_chart && diff.empty(); ++i) {
        std::uint32_t const r = rng();
        diff = twin.step(r % bsc_diff::twin<Fixture>::choices, r >> 8);
    }
    auto const& t = twin.counts();
    CHECK_MESSAGE(t.outcomes[static_cast<std::size_t>(bsc::outcome::consumed)] > 0, label, ": nothing fired");
    // BSC_DIFF_STATS=1 prints what each run exercised.
    if (std::getenv("BSC_DIFF_STATS"))
        std::printf("%-20s consumed %5zu ignored %5zu overflow %4zu livelock %5zu halted %4zu restarts %4zu  %5.0f ms\n",
                    label, t.outcomes[0], t.outcomes[1], t.outcomes[2], t.outcomes[3], t.outcomes[4], t.restarts,
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    return diff;
}

template <std::uint64_t... Seeds>
void run_generated() {
    (
        [] {
            std::string const label = "generated chart " + std::to_string(Seeds);
            INFO(label);
            std::string const diff = run_differential<gen::generated<Seeds>>(static_cast<std::uint32_t>(Seeds),
                                                                             label.c_str());
            CHECK_MESSAGE(diff.empty(), diff);
        }(),
        ...);
}

}  // namespace

TEST_CASE("differential: hand-written charts, 10,000 random events each") {
    auto check = [](std::string const& diff) { CHECK_MESSAGE(diff.empty(), diff); };
    check(run_differential<fx::hierarchy>(1, "hierarchy"));
    check(run_differential<fx::parallel>(2, "parallel"));
    check(run_differential<fx::history>(3, "history"));
    check(run_differential<fx::conditions>(4, "conditions"));
    check(run_differential<fx::raising>(5, "raising"));
    check(run_differential<fx::halting>(6, "halting"));
    check(run_differential<mcs_fixture>(7, "mcs"));
}

TEST_CASE("differential: charts generated from seeds, 10,000 random events each") {
    run_generated<1, 2, 3, 4>();
}
