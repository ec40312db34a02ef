// Fault injection (fault_injection.hpp) at every call site of generated charts: two charts
// compiled from their seeds and 1,000 charts drawn at run time on four skeletons
// (generated_charts.hpp), half of them under the scan policy. Generated rows never take
// bsc::action_failed, so every fault reaches the caller.

#include <doctest/doctest.h>

#include <cstdint>

#include "fault_injection.hpp"
#include "generated_charts.hpp"

namespace {

constexpr int draws_per_skeleton = 250;
constexpr int steps_per_draw = 12;

template <class Backend, std::uint64_t K, class Policy>
faults::totals inject_into_draws() {
    faults::totals all;
    for (std::uint64_t d = 0; d < draws_per_skeleton; ++d) {
        gen::draw<gen::first_skeleton + K>(d);
        INFO("skeleton " << K << ", draw " << d);
        auto const t = faults::inject_everywhere<Backend, gen::skeleton<K, Policy>>(steps_per_draw,
                                                                                    static_cast<std::uint32_t>(d));
        CHECK(t.violations == 0);
        CHECK(t.thrown == t.sites);
        all += t;
    }
    return all;
}

}  // namespace

TEST_CASE_TEMPLATE("a fault at any guard or action of a generated chart leaves a legal configuration", Backend,
                   bsc_test::compiled, bsc_test::table) {
    faults::totals t;
    t += faults::inject_everywhere<Backend, gen::generated<1>>(80, 3);
    t += faults::inject_everywhere<Backend, gen::generated_scan<5>>(80, 3);
    MESSAGE("2 compiled generated charts: " << t.sites << " call sites");
    CHECK(t.sites > 200);
    CHECK(t.thrown == t.sites);
    CHECK(t.violations == 0);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of 1,000 charts drawn on skeletons leaves a legal configuration",
                   Backend, bsc_test::compiled, bsc_test::table) {
    faults::totals t;
    t += inject_into_draws<Backend, 0, gen::limits>();
    t += inject_into_draws<Backend, 1, gen::scan_limits>();
    t += inject_into_draws<Backend, 2, gen::limits>();
    t += inject_into_draws<Backend, 3, gen::scan_limits>();
    MESSAGE("1,000 drawn charts: " << t.sites << " call sites");
    CHECK(t.sites > 10'000);
    CHECK(t.thrown == t.sites);
    CHECK(t.violations == 0);
}
