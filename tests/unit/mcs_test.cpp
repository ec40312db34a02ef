// The Mode Control Supervisor example (examples/mcs): every transition of its chart, the
// guard cond both ways, On's history, Show, and the buttons the supervisor ignores.

#include <doctest/doctest.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "../../examples/mcs/mcs.hpp"

namespace {

using bsc::outcome;

std::string config(mcs::machine const& m) { return m.active_states().joined(); }
// The display is the chart's: the test does not clear it, it reads what came after a mark.
std::size_t shown_before = 0;  // the display's lines before the last push (or in_mode)
std::string shown(mcs::machine const& m) { return m.context().display.text_since(shown_before); }

/// Pushes Button, so that shown(m) is what this push displayed.
template <class Button>
outcome push(mcs::machine& m) {
    shown_before = m.context().display.shown();
    return m.dispatch(Button{});
}

/// A work mode: the button that selects it and the configuration it leads to.
template <class Button>
struct mode {
    using button = Button;
    std::string_view config;
};
constexpr std::tuple modes{
    mode<mcs::mem_p>{"MCS On Auto Mem"},   mode<mcs::mdi_p>{"MCS On Auto Mdi"},
    mode<mcs::tape_p>{"MCS On Auto Tape"}, mode<mcs::hnd_p>{"MCS On Manual Handle"},
    mode<mcs::jog_p>{"MCS On Manual Jog"}, mode<mcs::rpd_p>{"MCS On Manual Rpd"},
    mode<mcs::zrn_p>{"MCS On Manual Zrn"}, mode<mcs::edit_p>{"MCS On Edit"},
    mode<mcs::setup_p>{"MCS On Setup"},
};

template <class F>
void for_each_mode(F&& f) {
    std::apply([&](auto... m) { (f(m), ...); }, modes);
}

/// A machine switched on and brought to the mode Button selects (Mem is On's default).
template <class Button>
mcs::machine in_mode() {
    mcs::machine m{mcs::chart};
    m.dispatch(mcs::on_p{});
    if constexpr (!std::is_same_v<Button, mcs::mem_p>) m.dispatch(Button{});
    shown_before = m.context().display.shown();
    return m;
}

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    while (!s.empty()) {
        auto const space = s.find(' ');
        out.push_back(s.substr(0, space));
        s = space == std::string_view::npos ? std::string_view{} : s.substr(space + 1);
    }
    return out;
}

/// What Show displays when the configuration `from` becomes `to` and only the states that
/// differ are left and entered: the states left innermost first, then those entered.
std::string minimal_show(std::string_view from, std::string_view to) {
    auto const a = words(from), b = words(to);
    std::size_t common = 0;
    while (common < a.size() && common < b.size() && a[common] == b[common]) ++common;
    std::string out;
    auto put = [&](char sign, std::string_view state) {
        if (!out.empty()) out += ' ';
        out += sign;
        out += state;
    };
    for (std::size_t i = a.size(); i-- > common;) put('-', a[i]);
    for (std::size_t i = common; i < b.size(); ++i) put('+', b[i]);
    return out;
}

/// Checks that each of Buttons, pushed in m's current state, is ignored and changes nothing.
template <class... Buttons>
void check_ignored(mcs::machine const& m, mcs::button_list<Buttons...>) {
    auto check = [&]<class B>(B) {
        INFO(B::name, " in ", config(m), ", error ", m.context().error);
        mcs::machine copy = m;
        CHECK(push<B>(copy) == outcome::ignored);
        CHECK(copy.active_configuration() == m.active_configuration());
        CHECK(copy.context().error == m.context().error);
        CHECK(shown(copy).empty());
    };
    (check(Buttons{}), ...);
}

using mode_buttons = mcs::button_list<mcs::mem_p, mcs::mdi_p, mcs::tape_p, mcs::hnd_p, mcs::jog_p, mcs::rpd_p,
                                      mcs::zrn_p, mcs::edit_p, mcs::setup_p>;

}  // namespace

namespace {
// Machines in globals, constant-initialised: no constructor runs at startup (constinit does not
// compile otherwise), so a bare-metal startup that skips .init_array finds them entered.
constinit mcs::machine global_mcs{mcs::chart};
constinit bsc::machine<bsc::chart_ref<mcs::chart>, bsc::lean_policy> global_lean_mcs{mcs::chart};
}  // namespace

TEST_CASE("mcs: a machine in a global is constant-initialised (constinit), entered and working") {
    CHECK(config(global_mcs) == "MCS Off");
    CHECK(global_mcs.context().display.text() == "+MCS +Off");
    CHECK(global_lean_mcs.is<mcs::Off>());
    global_lean_mcs.dispatch(mcs::on_p{});
    CHECK(global_lean_mcs.is<mcs::Mem>());
}

TEST_CASE("mcs: power-up: Off, error 0, Show for MCS and Off") {
    mcs::machine m{mcs::chart};
    CHECK(config(m) == "MCS Off");
    CHECK(m.context().error == 0);
    CHECK(m.context().display.text() == "+MCS +Off");
}

TEST_CASE("mcs: Figure 13, Off + On_P = On: the default group Auto and its default mode Mem") {
    mcs::machine m{mcs::chart};
    CHECK(push<mcs::on_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS On Auto Mem");
    CHECK(shown(m) == "-Off +On +Auto +Mem");
    CHECK(m.context().error == 0);
}

TEST_CASE("mcs: Figure 13, On + EStop_P / Set_Error1 = Estop, from every mode") {
    for_each_mode([](auto md) {
        INFO("from ", md.config);
        auto m = in_mode<typename decltype(md)::button>();
        CHECK(push<mcs::estop_p>(m) == outcome::consumed);
        CHECK(config(m) == "MCS Estop");
        CHECK(m.context().error == 1);
        CHECK(shown(m) == minimal_show(md.config, "MCS Estop"));  // e.g. -Mem -Auto -On +Estop
    });
}

TEST_CASE("mcs: Figure 13, Estop + Reset_P / Set_Error0 = Estop is an external self-transition") {
    auto m = in_mode<mcs::jog_p>();
    m.dispatch(mcs::estop_p{});
    REQUIRE(m.context().error == 1);
    CHECK(push<mcs::reset_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS Estop");
    CHECK(m.context().error == 0);
    CHECK(shown(m) == "-Estop +Estop");
}

TEST_CASE("mcs: Figure 13, Estop + Off_P [cond] = Off: cond is false until the stop is reset") {
    auto m = in_mode<mcs::mdi_p>();
    m.dispatch(mcs::estop_p{});

    // cond false: error 1, Off_P is ignored.
    CHECK(push<mcs::off_p>(m) == outcome::ignored);
    CHECK(config(m) == "MCS Estop");
    CHECK(m.context().error == 1);
    CHECK(shown(m).empty());

    // cond true after Reset_P.
    m.dispatch(mcs::reset_p{});
    CHECK(push<mcs::off_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS Off");
    CHECK(m.context().error == 0);
    CHECK(shown(m) == "-Estop +Off");
}

TEST_CASE("mcs: Figure 13, On + Off_P = Off, from every mode") {
    for_each_mode([](auto md) {
        INFO("from ", md.config);
        auto m = in_mode<typename decltype(md)::button>();
        CHECK(push<mcs::off_p>(m) == outcome::consumed);
        CHECK(config(m) == "MCS Off");
        CHECK(m.context().error == 0);
        CHECK(shown(m) == minimal_show(md.config, "MCS Off"));
    });
}

TEST_CASE("mcs: E-stop while Off latches the stop (a choice where the paper is silent)") {
    mcs::machine m{mcs::chart};
    CHECK(push<mcs::estop_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS Estop");
    CHECK(m.context().error == 1);
    CHECK(shown(m) == "-Off +Estop");
    CHECK(push<mcs::on_p>(m) == outcome::ignored);
}

TEST_CASE("mcs: E-stop in Estop after a reset latches the stop again (a choice where the paper is silent)") {
    mcs::machine m{mcs::chart};
    m.dispatch(mcs::estop_p{});
    m.dispatch(mcs::reset_p{});
    REQUIRE(m.context().error == 0);
    CHECK(push<mcs::estop_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS Estop");
    CHECK(m.context().error == 1);
    CHECK(shown(m) == "-Estop +Estop");
    CHECK(push<mcs::off_p>(m) == outcome::ignored);  // cond false again
}

TEST_CASE("mcs: every mode button selects its mode from every other mode, leaving only what differs") {
    for_each_mode([](auto from) {
        for_each_mode([&](auto to) {
            using from_button = typename decltype(from)::button;
            using to_button = typename decltype(to)::button;
            INFO(to_button::name, " from ", from.config);
            auto m = in_mode<from_button>();
            REQUIRE(config(m) == from.config);
            if constexpr (std::is_same_v<from_button, to_button>) {
                check_ignored(m, mcs::button_list<to_button>{});  // already in that mode
            } else {
                CHECK(push<to_button>(m) == outcome::consumed);
                CHECK(config(m) == to.config);
                CHECK(shown(m) == minimal_show(from.config, to.config));  // Mem -> Mdi: -Mem +Mdi
                CHECK(m.context().error == 0);
            }
        });
    });
}

TEST_CASE("mcs: history: left in Jog by E-stop, reset, off and on again, the machine is back in Jog") {
    auto m = in_mode<mcs::jog_p>();
    m.dispatch(mcs::estop_p{});
    m.dispatch(mcs::reset_p{});
    m.dispatch(mcs::off_p{});
    REQUIRE(config(m) == "MCS Off");
    CHECK(push<mcs::on_p>(m) == outcome::consumed);
    CHECK(config(m) == "MCS On Manual Jog");  // not Manual's default, Handle
    CHECK(shown(m) == "-Off +On +Manual +Jog");
}

TEST_CASE("mcs: history: every mode is restored, whether On was left by E-stop or by Off_P") {
    for_each_mode([](auto md) {
        INFO("mode ", md.config);
        auto by_off = in_mode<typename decltype(md)::button>();
        by_off.dispatch(mcs::off_p{});
        CHECK(push<mcs::on_p>(by_off) == outcome::consumed);
        CHECK(config(by_off) == md.config);

        auto by_estop = in_mode<typename decltype(md)::button>();
        by_estop.dispatch(mcs::estop_p{});
        by_estop.dispatch(mcs::reset_p{});
        by_estop.dispatch(mcs::off_p{});
        CHECK(push<mcs::on_p>(by_estop) == outcome::consumed);
        CHECK(config(by_estop) == md.config);
    });
}

TEST_CASE("mcs: history remembers the last mode, not the one the group was entered in") {
    auto m = in_mode<mcs::mdi_p>();
    m.dispatch(mcs::tape_p{});
    m.dispatch(mcs::off_p{});
    m.dispatch(mcs::on_p{});
    CHECK(config(m) == "MCS On Auto Tape");
    m.dispatch(mcs::zrn_p{});
    m.dispatch(mcs::setup_p{});
    m.dispatch(mcs::off_p{});
    m.dispatch(mcs::on_p{});
    CHECK(config(m) == "MCS On Setup");
}

TEST_CASE("mcs: buttons without a transition in the current state are ignored and change nothing") {
    SUBCASE("Off: all but ON_P and ESTOP_P") {
        mcs::machine m{mcs::chart};
        check_ignored(m, mcs::button_list<mcs::off_p, mcs::reset_p>{});
        check_ignored(m, mode_buttons{});
    }
    SUBCASE("Estop before the reset: ON_P, OFF_P (cond) and the mode buttons") {
        auto m = in_mode<mcs::rpd_p>();
        m.dispatch(mcs::estop_p{});
        check_ignored(m, mcs::button_list<mcs::on_p, mcs::off_p>{});
        check_ignored(m, mode_buttons{});
    }
    SUBCASE("Estop after the reset: ON_P and the mode buttons") {
        auto m = in_mode<mcs::rpd_p>();
        m.dispatch(mcs::estop_p{});
        m.dispatch(mcs::reset_p{});
        check_ignored(m, mcs::button_list<mcs::on_p>{});
        check_ignored(m, mode_buttons{});
    }
    SUBCASE("On, in every mode: ON_P and RESET_P") {
        for_each_mode([](auto md) {
            check_ignored(in_mode<typename decltype(md)::button>(), mcs::button_list<mcs::on_p, mcs::reset_p>{});
        });
    }
}

TEST_CASE("mcs: the display keeps the most recent Show lines") {
    mcs::display d;
    for (std::size_t i = 0; i < mcs::display::capacity + 2; ++i) d.show(i % 2 ? "On" : "Off", i % 2 == 1);
    CHECK(d.size() == mcs::display::capacity);
    CHECK(d[0].state == "Off");  // lines 0 and 1 scrolled away
    CHECK(d[d.size() - 1].state == "On");
    CHECK(d[d.size() - 1].entered);
    d.clear();
    CHECK(d.empty());
    CHECK(d.text().empty());
}
