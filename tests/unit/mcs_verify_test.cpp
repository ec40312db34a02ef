// Exploring the Mode Control Supervisor (examples/mcs): every event offered in every state.

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "../../examples/mcs/mcs.hpp"

// The display only logs what Show printed: it has no influence on the behaviour.
template <>
inline constexpr bool bsc::transient<mcs::display> = true;

namespace {
template <class Machine>
using panel_model =
    bsc::verify::event_model<Machine, mcs::on_p, mcs::off_p, mcs::estop_p, mcs::reset_p, mcs::mem_p, mcs::mdi_p,
                             mcs::tape_p, mcs::hnd_p, mcs::jog_p, mcs::rpd_p, mcs::zrn_p, mcs::edit_p, mcs::setup_p>;

template <class S>
constexpr auto in = [](auto const& m) { return m.template is<S>(); };

// A variant whose cond always holds: Estop can be left without a reset.
inline constexpr auto always = bsc::guard([] { return true; });
inline constexpr auto broken_chart = bsc::make_chart<mcs::panel>(mcs::tree, mcs::show_rows, mcs::figure13(always),
                                                                 mcs::estop_rows, mcs::mode_rows);
}  // namespace

TEST_CASE("MCS: explored, every mode is reachable, E-stop and Off are reachable from every state") {
    bsc::verify::explorer ex{panel_model<mcs::machine>{mcs::machine{mcs::chart, mcs::panel{}}}};
    auto const& st = ex.run();
    REQUIRE(st.complete);
    MESSAGE("MCS: " << st.states << " states, " << st.transitions << " transitions, depth " << st.depth << ", "
                    << st.seconds << " s");
    CHECK(bsc::verify::deadlock_free(ex).holds());
    CHECK(bsc::verify::reachable(ex, "MEM", in<mcs::Mem>).holds());
    CHECK(bsc::verify::reachable(ex, "MDI", in<mcs::Mdi>).holds());
    CHECK(bsc::verify::reachable(ex, "TAPE", in<mcs::Tape>).holds());
    CHECK(bsc::verify::reachable(ex, "Handle", in<mcs::Handle>).holds());
    CHECK(bsc::verify::reachable(ex, "JOG", in<mcs::Jog>).holds());
    CHECK(bsc::verify::reachable(ex, "RPD", in<mcs::Rpd>).holds());
    CHECK(bsc::verify::reachable(ex, "ZRN", in<mcs::Zrn>).holds());
    CHECK(bsc::verify::reachable(ex, "Edit", in<mcs::Edit>).holds());
    CHECK(bsc::verify::reachable(ex, "Setup", in<mcs::Setup>).holds());
    CHECK(bsc::verify::always_reachable(ex, "Emergency stop", in<mcs::Estop>).holds());
    CHECK(bsc::verify::always_reachable(ex, "Off", in<mcs::Off>).holds());
    // The error is set exactly while the stop has not been acknowledged.
    CHECK(bsc::verify::always(ex, "error only in Estop", [](auto const& m) {
              return m.context().error == 0 || m.template is<mcs::Estop>();
          }).holds());
    // Deep history keeps the last mode of each group, yet the operator can always select MEM
    // and Handle again and switch off: the initial state, history included, comes back.
    CHECK(bsc::verify::reinitiable(ex).holds());
}

TEST_CASE("MCS: every state and every transition is exercised by some run") {
    std::vector<bool> fired(200, false);
    using recorded = bsc::machine<decltype(mcs::chart), bsc::default_policy, bsc::verify::row_recorder>;
    bsc::verify::explorer ex{panel_model<recorded>{recorded{mcs::chart, mcs::panel{}, {&fired}}}};
    auto const report = bsc::verify::coverage(ex, fired);
    CHECK_MESSAGE(report.complete(), report.to_string());
}

TEST_CASE("MCS: a variant whose cond always holds is caught with a shortest counterexample") {
    using broken = bsc::machine<decltype(broken_chart)>;
    bsc::verify::explorer ex{panel_model<broken>{broken{broken_chart, mcs::panel{}}}};
    auto const v = bsc::verify::always(
        ex, "error only in Estop", [](auto const& m) { return m.context().error == 0 || m.template is<mcs::Estop>(); });
    REQUIRE(v.fails());
    REQUIRE(v.trace.size() == 3);
    CHECK(v.trace[1].label == "ESTOP_P");  // the events by their bsc::event_name
    CHECK(v.trace[1].configuration == "MCS Estop");
    CHECK(v.trace[2].label == "OFF_P");
    CHECK(v.trace[2].configuration == "MCS Off");
}
