// Fault injection (fault_injection.hpp) at every call site of the example controllers: the
// MCS, the manufacturing cell controller and the five controllers of the production cell.
// No row of these charts takes bsc::action_failed, so every fault reaches the caller.

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "../../examples/production_cell/controllers.hpp"
#include "differential_examples.hpp"
#include "fault_injection.hpp"

namespace {

void toggle(bsc::input<bool> const& flag) { flag.set(!flag.pending()); }

// The production cell's controllers, their sensors and the other actors' signals written at
// random by the environment (through the const view it has of a context).
struct feed_belt_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::feed_belt_chart;
    static pcell::feed_belt_ctl initial() { return {}; }
    static void perturb(pcell::feed_belt_ctl const& c, std::uint32_t r) {
        bsc::input<bool> const* const flags[] = {&c.on, &c.sensor, &c.table_ready};
        toggle(*flags[r % 3]);
    }
};

struct table_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::table_chart;
    static pcell::table_ctl initial() { return {}; }
    static void perturb(pcell::table_ctl const& c, std::uint32_t r) {
        bsc::input<bool> const* const flags[] = {&c.on, &c.fed, &c.taken};
        bsc::input<std::uint8_t> const* const sensors[] = {&c.height, &c.angle};
        if (r % 2 == 0)
            toggle(*flags[(r >> 1) % 3]);
        else
            sensors[(r >> 1) % 2]->set(static_cast<std::uint8_t>((r >> 3) % 8));
    }
};

struct robot_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::robot_chart;
    static pcell::robot_ctl initial() { return {}; }
    static void perturb(pcell::robot_ctl const& c, std::uint32_t r) {
        bsc::input<bool> const* const flags[] = {&c.on, &c.table_ready, &c.press_load_ready, &c.press_unload_ready,
                                                 &c.belt_ready};
        bsc::input<std::uint8_t> const* const sensors[] = {&c.angle, &c.ext1, &c.ext2};
        if (r % 2 == 0)
            toggle(*flags[(r >> 1) % 5]);
        else
            sensors[(r >> 1) % 3]->set(static_cast<std::uint8_t>((r >> 3) % 8));
    }
};

struct press_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::press_chart;
    static pcell::press_ctl initial() { return {}; }
    static void perturb(pcell::press_ctl const& c, std::uint32_t r) {
        bsc::input<bool> const* const flags[] = {&c.on, &c.loaded, &c.unloaded};
        bsc::input<std::uint8_t> const* const sensors[] = {&c.level, &c.arm1_ext, &c.arm2_ext};
        if (r % 2 == 0)
            toggle(*flags[(r >> 1) % 3]);
        else
            sensors[(r >> 1) % 3]->set(static_cast<std::uint8_t>((r >> 3) % 8));
    }
};

struct deposit_belt_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::deposit_belt_chart;
    static pcell::deposit_belt_ctl initial() { return {}; }
    static void perturb(pcell::deposit_belt_ctl const& c, std::uint32_t r) {
        bsc::input<bool> const* const flags[] = {&c.on, &c.dropped};
        toggle(*flags[r % 2]);
    }
};

// Every fault reaches the caller and no run breaks the ledger or the configuration.
template <class Backend, class Fixture>
void check_every_site(std::string const& name, int steps, std::uint32_t seed, long at_least) {
    auto const t = faults::inject_everywhere<Backend, Fixture>(steps, seed);
    MESSAGE(name << ": " << t.sites << " call sites, " << t.thrown << " faults reached the caller");
    CHECK(t.sites >= at_least);
    CHECK(t.thrown == t.sites);
    CHECK(t.violations == 0);
}

}  // namespace

TEST_CASE_TEMPLATE("a fault at any guard or action of the MCS leaves a legal configuration", Backend,
                   bsc_test::compiled, bsc_test::table) {
    check_every_site<Backend, bsc_diff::mcs_fixture>("MCS", 400, 1, 100);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of the manufacturing cell leaves a legal configuration", Backend,
                   bsc_test::compiled, bsc_test::table) {
    check_every_site<Backend, bsc_diff::cell_fixture>("cell", 120, 2, 400);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of the production cell's controllers leaves a legal configuration",
                   Backend, bsc_test::compiled, bsc_test::table) {
    check_every_site<Backend, feed_belt_fixture>("feed belt", 120, 3, 20);
    check_every_site<Backend, table_fixture>("table", 120, 4, 50);
    check_every_site<Backend, robot_fixture>("robot", 120, 4, 100);
    check_every_site<Backend, press_fixture>("press", 120, 5, 50);
    check_every_site<Backend, deposit_belt_fixture>("deposit belt", 120, 6, 20);
}
