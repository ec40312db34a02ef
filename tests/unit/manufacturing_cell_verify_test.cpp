// Exploring the manufacturing cell (examples/manufacturing_cell/verification.hpp): the
// controller in closed loop with a finite plant, every arrival pattern at once. [BSC] is the
// Basic Statechart paper (docs/references.md).

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "../../examples/manufacturing_cell/verification.hpp"

namespace {
template <class Loop>
bool device(Loop const& s, bsc::output<bool> cell::data::*actuator) {
    return (s.controller.context().*actuator).get();
}

// Constraint 3 dropped: the table may turn with nothing at P1..P3.
inline constexpr auto g13_without_constraint_3 = bsc::guard(
    [](cell::data const& d) { return d.E1 && d.E2 && d.E3 && d.E4; });
inline constexpr auto broken = cell::make_controller(cell::g4, g13_without_constraint_3);
}  // namespace

TEST_CASE("manufacturing cell: deadlock-free, reinitiable and live, as the BSC paper reports") {
    bsc::verify::explorer ex{cell::finite::model(cell::chart)};
    auto const& st = ex.run();
    REQUIRE(st.complete);
    MESSAGE("manufacturing cell: " << st.states << " states, " << st.transitions << " transitions, depth " << st.depth
                                   << ", " << st.key_bytes << " bytes per state key, " << st.seconds << " s");
    CHECK(st.key_bytes <= 64);
    CHECK(bsc::verify::deadlock_free(ex).holds());
    // Reinitiability as [BSC] means it, over configurations: the components' states and an
    // empty cell come back. The exact initial valuation does not: in the empty cell E1..E4
    // alternate for ever, and the start (BeltOff with E1..E4 all false) is never met again.
    CHECK(bsc::verify::reinitiable(ex).fails());
    CHECK(bsc::verify::reinitiable(ex, [](auto const& s, auto const& initial) {
              return s.controller.active_configuration() == initial.controller.active_configuration() &&
                     s.plant.at == initial.plant.at && !s.plant.waiting && !s.plant.carrying;
          }).holds());
    // Vivacity: every device can operate again, from every reachable state.
    CHECK(bsc::verify::always_reachable(ex, "belt on", [](auto const& s) {
              return device(s, &cell::data::belt);
          }).holds());
    CHECK(bsc::verify::always_reachable(ex, "drill on", [](auto const& s) {
              return device(s, &cell::data::drill);
          }).holds());
    CHECK(bsc::verify::always_reachable(ex, "test on", [](auto const& s) {
              return device(s, &cell::data::test);
          }).holds());
    CHECK(bsc::verify::always_reachable(ex, "robot on", [](auto const& s) {
              return device(s, &cell::data::robot);
          }).holds());
    CHECK(bsc::verify::always_reachable(ex, "table turning", [](auto const& s) {
              return device(s, &cell::data::valve);
          }).holds());
    // Constraint 2: no device works without a piece at its position.
    CHECK(bsc::verify::always(ex, "drill only on a piece", [](auto const& s) {
              return !device(s, &cell::data::drill) || s.plant.at[1];
          }).holds());
    CHECK(bsc::verify::always(ex, "test only on a piece", [](auto const& s) {
              return !device(s, &cell::data::test) || s.plant.at[2];
          }).holds());
    // Constraint 3 and the plant's physical limits.
    CHECK(bsc::verify::always(ex, "no empty turn", [](auto const& s) { return !s.plant.empty_turn; }).holds());
    CHECK(bsc::verify::always(ex, "no collision", [](auto const& s) { return !s.plant.collision; }).holds());
    // Every piece that arrives is eventually stored... if no other piece keeps arriving
    // forever is not required: leads-to holds without fairness here, since the cell always
    // clears P4 within bounded time.
    CHECK(bsc::verify::leads_to(
              ex, "piece at P4 --> P4 cleared", [](auto const& s) { return s.plant.at[3]; },
              [](auto const& s) { return !s.plant.at[3]; })
              .holds());
}

TEST_CASE("manufacturing cell: a controller without constraint 3 is caught turning an empty table") {
    bsc::verify::explorer ex{cell::finite::model(broken)};
    auto const v = bsc::verify::always(ex, "no empty turn", [](auto const& s) { return !s.plant.empty_turn; });
    REQUIRE(v.fails());
    // The shortest run: the empty cell finishes a phase (E1..E4), the table advances for
    // arm_cycles cycles with nothing on it.
    CHECK(v.trace.size() > 2);
    CHECK(v.trace.back().configuration.find("P=0000") != std::string::npos);
    CHECK(v.trace.back().configuration.find("S1") != std::string::npos);
    MESSAGE(v.to_string());
}
