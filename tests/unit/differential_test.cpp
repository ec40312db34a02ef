// The compiled and the table-driven back ends, driven with the same random events and
// execution cycles (step(now) at the same random times), must agree after every step: outcome
// and step report, clock, configuration bytes, active states, is<S>(), context and the
// observer's full trace. Charts: the hand-written fixtures of fixtures.hpp, the Mode Control
// Supervisor of examples/mcs, the manufacturing cell controller of examples/manufacturing_cell,
// and charts generated at compile time (generated_charts.hpp), under both policies.

#include <doctest/doctest.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "differential.hpp"
#include "differential_examples.hpp"
#include "fixtures.hpp"
#include "generated_charts.hpp"

namespace {

constexpr int steps_per_chart = 10'000;

// Runs `steps` random steps; returns the first difference, or "".
template <class Fixture>
std::string run_differential(std::uint32_t seed, char const* label, int steps = steps_per_chart) {
    auto const t0 = std::chrono::steady_clock::now();
    bsc_diff::twin<Fixture> twin;
    std::mt19937 rng{seed};
    std::string diff = twin.start();
    for (int i = 0; i < steps && diff.empty(); ++i) {
        std::uint32_t const r = rng();
        diff = twin.step(r % bsc_diff::twin<Fixture>::choices, r >> 8);
    }
    auto const& t = twin.counts();
    INFO(std::string(label));
    CHECK_MESSAGE(t.outcomes[static_cast<std::size_t>(bsc::outcome::consumed)] > 0, "nothing fired");
    using tables = bsc::table::tables<typename bsc_diff::twin<Fixture>::chart_type, typename Fixture::policy>;
    if constexpr (tables::has_conditions) CHECK_MESSAGE(t.cycle_transitions > 0, "no cycle fired a transition");
    CHECK_MESSAGE(t.backwards > 0, "time never went backwards");
    // BSC_DIFF_STATS=1 prints what each run exercised.
    if (std::getenv("BSC_DIFF_STATS"))
        std::printf(
            "%-20s consumed %5zu ignored %5zu overflow %4zu livelock %5zu halted %4zu restarts %4zu "
            "cycles %5zu (transitions %5zu, backwards %2zu)  %5.0f ms\n",
            label, t.outcomes[0], t.outcomes[1], t.outcomes[2], t.outcomes[3], t.outcomes[4], t.restarts, t.cycles,
            t.cycle_transitions, t.backwards,
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    return diff;
}

template <template <std::uint64_t> class Fixture, std::uint64_t... Seeds>
void run_generated(char const* what) {
    (
        [what] {
            std::string const label = what + std::to_string(Seeds);
            INFO(label);
            std::string const diff = run_differential<Fixture<Seeds>>(static_cast<std::uint32_t>(Seeds), label.c_str());
            CHECK_MESSAGE(diff.empty(), diff);
        }(),
        ...);
}

template <std::uint64_t Seed>
using generated = gen::generated<Seed>;

}  // namespace

TEST_CASE("differential: hand-written charts, 10,000 random events and cycles each") {
    auto check = [](std::string const& diff) { CHECK_MESSAGE(diff.empty(), diff); };
    check(run_differential<fx::hierarchy>(1, "hierarchy"));
    check(run_differential<fx::parallel>(2, "parallel"));
    check(run_differential<fx::history>(3, "history"));
    check(run_differential<fx::conditions>(4, "conditions"));
    check(run_differential<fx::raising>(5, "raising"));
    check(run_differential<fx::halting>(6, "halting"));
    check(run_differential<bsc_diff::mcs_fixture>(7, "mcs"));
    check(run_differential<fx::cycles>(8, "cycles"));
    check(run_differential<fx::scan_cycles>(9, "cycles, scan policy"));
    check(run_differential<fx::beyond_core>(11, "beyond the core"));
}

TEST_CASE("differential: the manufacturing cell controller, 20,000 random cycles and sensor changes") {
    std::string const diff = run_differential<bsc_diff::cell_fixture>(10, "manufacturing cell", 2 * steps_per_chart);
    CHECK_MESSAGE(diff.empty(), diff);
}

TEST_CASE("differential: charts generated from seeds, 10,000 random events and cycles each") {
    run_generated<generated, 2, 4, 7, 9>("generated chart ");
    run_generated<gen::generated_scan, 5, 11>("generated chart, scan policy, ");
}

TEST_CASE("differential: parent-first charts generated from seeds, 10,000 random events and cycles each") {
    run_generated<gen::parent_first, 2, 4, 7>("parent-first generated chart ");
    run_generated<gen::parent_first_scan, 5, 11>("parent-first generated chart, scan policy, ");
}
