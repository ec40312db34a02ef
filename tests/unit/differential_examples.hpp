#pragma once
// The example charts as fixtures of differential.hpp (see fixtures.hpp for what a fixture
// provides): the Mode Control Supervisor of examples/mcs, driven by events, and the
// manufacturing cell controller of examples/manufacturing_cell, driven by execution cycles
// under bsc::scan_policy with its sensors written by the environment.

#include <cstdint>

#include "../../examples/manufacturing_cell/controller.hpp"
#include "../../examples/mcs/mcs.hpp"

namespace bsc_diff {

struct mcs_fixture {
    using policy = bsc::default_policy;
    static constexpr auto const& chart = mcs::chart;
    static mcs::panel initial() { return {}; }
    static void perturb(mcs::panel& p, std::uint32_t) { p.display.clear(); }
    static bool same(mcs::panel const& a, mcs::panel const& b) {
        return a.error == b.error && a.display.text() == b.display.text();
    }
};

/// The controller of the cell with the paper's guards; the environment turns one sensor on or
/// off at a time, as the plant would, except that any sensor may change at any moment.
struct cell_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = cell::chart;
    static cell::data initial() { return {}; }
    static void perturb(cell::data const& d, std::uint32_t r) {
        bsc::input<bool> const* const sensors[] = {&d.IN, &d.P1, &d.P2, &d.P3, &d.P4, &d.S1};
        bsc::input<bool> const& s = *sensors[r % 6];
        s.set(!s.pending());
    }
    static bool same(cell::data const& a, cell::data const& b) {
        auto const same_channel = [](auto const& x, auto const& y) {
            return x.get() == y.get() && x.pending() == y.pending();
        };
        return same_channel(a.IN, b.IN) && same_channel(a.P1, b.P1) && same_channel(a.P2, b.P2) &&
               same_channel(a.P3, b.P3) && same_channel(a.P4, b.P4) && same_channel(a.S1, b.S1) &&
               same_channel(a.belt, b.belt) && same_channel(a.drill, b.drill) && same_channel(a.test, b.test) &&
               same_channel(a.robot, b.robot) && same_channel(a.valve, b.valve) && a.E1 == b.E1 && a.E2 == b.E2 &&
               a.E3 == b.E3 && a.E4 == b.E4 && a.T1 == b.T1 && a.T2 == b.T2 && a.T3 == b.T3;
    }
};

}  // namespace bsc_diff
