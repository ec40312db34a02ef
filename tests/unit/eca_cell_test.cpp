// The ECA MFSM example (examples/eca_cell): the controller of the paper's Figure 5 and its
// extension with a Pause module (section 4, Figure 7b), both built from the same module
// definitions. Every rule in the situation the paper gives, the light as the paper describes
// it, Main's single stable state, and the extension leaving the original behaviour alone.

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "../../examples/eca_cell/pause.hpp"

namespace {

using namespace eca::in;

template <class Module>
std::string_view state_of(Module const& m) {
    auto const names = m.active_states();
    return names[names.size() - 1];
}
template <class Controller>
std::string sent(Controller const& c) {
    return c.context().env.sent.get().joined();
}

eca::controller original() { return eca::controller{eca::main_chart}; }
eca::extended_controller extended() { return eca::extended_controller{eca::extended_main_chart}; }

/// Scans the inputs in order, checking that each one runs a whole transaction: a rule fires
/// and Main is back in its only stable state (Definitions 3, 4 and 9).
template <class Controller, class... E>
void scan_all(Controller& c, E const&... inputs) {
    (
        [&] {
            CHECK(eca::scan(c, inputs) == bsc::outcome::consumed);
            CHECK(c.template is<eca::Idle>());
        }(),
        ...);
}

}  // namespace

// ---- The modules ---------------------------------------------------------------------------

TEST_CASE("eca_cell: the Peripheral modules only keep state, following Main's updating events") {
    eca::button::module button{eca::button::chart};
    CHECK(button.is<eca::button::Released>());
    CHECK(button.dispatch(eca::button::set_pressed{}) == bsc::outcome::consumed);
    CHECK(button.is<eca::button::Pressed>());
    CHECK(button.dispatch(eca::button::set_pressed{}) == bsc::outcome::ignored);  // nothing to change
    CHECK(button.dispatch(eca::button::set_released{}) == bsc::outcome::consumed);
    CHECK(button.is<eca::button::Released>());

    eca::robot::module robot{eca::robot::chart};
    CHECK(robot.is<eca::robot::Idle>());
    robot.dispatch(eca::robot::set_busy{});
    CHECK(robot.is<eca::robot::Busy>());
    robot.dispatch(eca::robot::set_idle{});
    CHECK(robot.is<eca::robot::Idle>());

    eca::pause::module pause{eca::pause::chart};
    CHECK(pause.is<eca::pause::Running>());
    pause.dispatch(eca::pause::set_paused{});
    CHECK(pause.is<eca::pause::Paused>());
    pause.dispatch(eca::pause::set_running{});
    CHECK(pause.is<eca::pause::Running>());
}

TEST_CASE("eca_cell: both variants are built from the same module definitions") {
    // The same Peripheral modules: the same charts, so the same machine types.
    static_assert(std::is_same_v<decltype(eca::main_connections::button), decltype(eca::extended_connections::button)>);
    static_assert(std::is_same_v<decltype(eca::main_connections::robot), decltype(eca::extended_connections::robot)>);
    static_assert(std::is_same_v<decltype(eca::main_connections::env), decltype(eca::extended_connections::env)>);

    // Main's rules: 5 rows in Figure 5; the extension adds 10 and keeps those 5.
    static_assert(std::tuple_size_v<std::remove_cv_t<decltype(eca::main_rules)>> == 5);
    static_assert(std::tuple_size_v<std::remove_cv_t<decltype(eca::extended_rules)>> == 15);
    using old_rows = std::remove_cv_t<decltype(eca::main_rules)>;
    using new_rows = std::remove_cv_t<decltype(eca::extended_rules)>;
    // Rule 1's query and its responses, and rule 2, are the very same rows (guards and actions
    // included: they are part of a row's type).
    static_assert(std::is_same_v<std::tuple_element_t<1, old_rows>, std::tuple_element_t<11, new_rows>>);
    static_assert(std::is_same_v<std::tuple_element_t<2, old_rows>, std::tuple_element_t<12, new_rows>>);
    static_assert(std::is_same_v<std::tuple_element_t<3, old_rows>, std::tuple_element_t<13, new_rows>>);
    // Rules 1 and 3 changed their trigger only: rule 1 still leads to QueryRobotOnPress, rule 3
    // still does what it did.
    using old_press = std::tuple_element_t<0, old_rows>;
    using new_press = std::tuple_element_t<10, new_rows>;
    static_assert(std::is_same_v<typename old_press::target, typename new_press::target>);
    static_assert(std::is_same_v<typename old_press::source, eca::Idle>);
    static_assert(std::is_same_v<typename new_press::source, eca::QueryPauseOnPress>);
    using old_done = std::tuple_element_t<4, old_rows>;
    using new_done = std::tuple_element_t<14, new_rows>;
    static_assert(std::is_same_v<decltype(old_done::action), decltype(new_done::action)>);
    static_assert(std::is_same_v<typename old_done::target, typename new_done::target>);
    static_assert(std::is_same_v<typename new_done::source, eca::QueryPauseOnDone>);
}

// ---- Figure 5 ------------------------------------------------------------------------------

TEST_CASE("eca_cell, Figure 5: at rest, the button is released, the robot idle and the light off") {
    auto const c = original();
    CHECK(c.active_states().joined() == "Main Idle");
    CHECK(c.context().button.active_states().joined() == "Button Released");
    CHECK(c.context().robot.active_states().joined() == "Robot Idle");
    CHECK_FALSE(c.context().env.light);
}

TEST_CASE("eca_cell, Figure 5, rule 1: a press with the robot idle lights the light and starts the robot") {
    auto c = original();
    scan_all(c, press{});
    CHECK(sent(c) == "start light_on");
    CHECK(c.context().env.light);
    CHECK(c.context().env.jobs == 1);
    CHECK(state_of(c.context().robot) == "Busy");
    CHECK(state_of(c.context().button) == "Pressed");
}

TEST_CASE("eca_cell, Figure 5, rule 1: a press while the robot is busy has no effect") {
    auto c = original();
    scan_all(c, press{}, release{}, press{});
    CHECK(sent(c).empty());
    CHECK(c.context().env.jobs == 1);
    CHECK(c.context().env.light);
    CHECK(state_of(c.context().robot) == "Busy");
    CHECK(state_of(c.context().button) == "Pressed");  // the Button still tracks the button
}

TEST_CASE("eca_cell, Figure 5, rule 2: releasing the button at any time has no effect") {
    auto c = original();
    scan_all(c, press{}, release{});  // while the robot is busy
    CHECK(sent(c).empty());
    CHECK(c.context().env.light);
    CHECK(state_of(c.context().robot) == "Busy");
    CHECK(state_of(c.context().button) == "Released");
    scan_all(c, done{}, press{}, done{}, release{});  // while the robot is idle
    CHECK(sent(c).empty());
    CHECK_FALSE(c.context().env.light);
    CHECK(state_of(c.context().robot) == "Idle");
}

TEST_CASE("eca_cell, Figure 5, rule 3: the light goes out when the robot finishes its job") {
    auto c = original();
    scan_all(c, press{}, release{}, done{});
    CHECK(sent(c) == "light_off");
    CHECK_FALSE(c.context().env.light);
    CHECK(state_of(c.context().robot) == "Idle");
    scan_all(c, press{});  // and the next press is served
    CHECK(sent(c) == "start light_on");
    CHECK(c.context().env.jobs == 2);
}

namespace {
/// The plant as the environment sees it: the button's position, whether the robot is working
/// and, with the extension, the Pause button's position. Inputs follow from it: rise and fall
/// alternate, and only a working robot finishes.
struct plant {
    bool button_down = false;
    bool working = false;
    bool paused = false;
};

/// Scans `input` and checks the controller against the plant: Main back in Idle, the
/// Peripheral modules tracking the plant, and the light on exactly while the robot works (or,
/// extended, while the cell is paused). Then explores every next input, `depth` levels deep.
template <class Controller, class E>
void explore(Controller c, plant p, E const& input, int depth, long& scans);

template <class Controller>
void explore_next(Controller const& c, plant const& p, int depth, long& scans) {
    if (depth == 0) return;
    if (!p.button_down) explore(c, p, press{}, depth - 1, scans);
    if (p.button_down) explore(c, p, release{}, depth - 1, scans);
    if (p.working) explore(c, p, done{}, depth - 1, scans);
    if constexpr (std::is_same_v<Controller, eca::extended_controller>) {
        if (!p.paused) explore(c, p, pause{}, depth - 1, scans);
        if (p.paused) explore(c, p, continue_{}, depth - 1, scans);
    }
}

template <class Controller, class E>
void explore(Controller c, plant p, E const& input, int depth, long& scans) {
    constexpr bool extended = std::is_same_v<Controller, eca::extended_controller>;
    int const jobs = c.context().env.jobs;
    bool const ok = eca::scan(c, input) == bsc::outcome::consumed;
    ++scans;
    if constexpr (std::is_same_v<E, press>) p.button_down = true;
    if constexpr (std::is_same_v<E, release>) p.button_down = false;
    if constexpr (std::is_same_v<E, done>) p.working = false;
    if constexpr (std::is_same_v<E, pause>) p.paused = true;
    if constexpr (std::is_same_v<E, continue_>) p.paused = false;
    bool const started = c.context().env.jobs != jobs;
    bool const may_start = std::is_same_v<E, press> && !p.working && !(extended && p.paused);
    if (started) p.working = true;

    bool light_right = c.context().env.light == p.working;
    if constexpr (extended) light_right = c.context().env.light == (p.working || p.paused);
    bool pause_right = true;
    if constexpr (extended) pause_right = c.context().pause.template is<eca::pause::Paused>() == p.paused;
    bool const right = ok && c.template is<eca::Idle>() && started == may_start &&
                       c.context().robot.template is<eca::robot::Busy>() == p.working &&
                       c.context().button.template is<eca::button::Pressed>() == p.button_down && pause_right &&
                       light_right;
    if (!right) {
        FAIL_CHECK("after " << E::name << ": Main " << state_of(c) << ", Button " << state_of(c.context().button)
                            << ", Robot " << state_of(c.context().robot) << ", light " << c.context().env.light
                            << ", sent '" << sent(c) << "'");
        return;
    }
    explore_next(c, p, depth, scans);
}
}  // namespace

TEST_CASE("eca_cell, Figure 5: on every run of up to 10 inputs, the light is on exactly while the robot works") {
    long scans = 0;
    explore_next(original(), plant{}, 10, scans);
    CHECK(scans > 100);
}

// ---- Section 4: the Pause extension --------------------------------------------------------

TEST_CASE("eca_cell, section 4: at rest, the extended controller is running") {
    auto const c = extended();
    CHECK(c.active_states().joined() == "Main Idle");
    CHECK(c.context().pause.active_states().joined() == "Pause Running");
    CHECK_FALSE(c.context().env.light);
}

TEST_CASE("eca_cell, section 4, rules 6 and 5: after a pause the light stays on once the robot has finished") {
    auto c = extended();
    scan_all(c, press{}, release{}, pause{});  // rule 6, Robot? Busy
    CHECK(sent(c).empty());
    CHECK(state_of(c.context().pause) == "Paused");
    CHECK(c.context().env.light);
    scan_all(c, done{});  // rule 5, Pause? Paused
    CHECK(sent(c).empty());
    CHECK(state_of(c.context().robot) == "Idle");
    CHECK(c.context().env.light);  // the robot is effectively still busy: it is paused
}

TEST_CASE("eca_cell, section 4, rule 4: while paused, further requests are ignored: the robot stays stopped") {
    auto c = extended();
    scan_all(c, press{}, release{}, pause{}, done{});
    for (int i = 0; i < 3; ++i) {
        scan_all(c, press{});  // rule 4, Pause? Paused
        CHECK(sent(c).empty());
        CHECK(state_of(c.context().button) == "Pressed");
        scan_all(c, release{});
    }
    CHECK(c.context().env.jobs == 1);
    CHECK(state_of(c.context().robot) == "Idle");
    CHECK(c.context().env.light);
}

TEST_CASE("eca_cell, section 4, rule 7: continue brings the system back to normal mode") {
    auto c = extended();
    scan_all(c, press{}, release{}, pause{}, done{}, press{}, release{});
    scan_all(c, continue_{});  // rule 7, Robot? Idle
    CHECK(sent(c) == "light_off");
    CHECK_FALSE(c.context().env.light);
    CHECK(state_of(c.context().pause) == "Running");
    scan_all(c, press{});  // rules 4 and 1: Pause? Running, Robot? Idle
    CHECK(sent(c) == "start light_on");
    CHECK(c.context().env.jobs == 2);
    scan_all(c, release{}, done{});  // rules 5 and 3: Pause? Running
    CHECK(sent(c) == "light_off");
    CHECK_FALSE(c.context().env.light);
}

TEST_CASE("eca_cell, section 4, rule 7: continue while the robot still works leaves the light to done") {
    auto c = extended();
    scan_all(c, press{}, pause{}, continue_{});  // rule 7, Robot? Busy
    CHECK(sent(c).empty());
    CHECK(c.context().env.light);
    scan_all(c, release{}, done{});
    CHECK(sent(c) == "light_off");
    CHECK_FALSE(c.context().env.light);
}

TEST_CASE("eca_cell, section 4, rule 6: a pause while the robot is idle lights the light; continue puts it out") {
    auto c = extended();
    scan_all(c, pause{});  // rule 6, Robot? Idle
    CHECK(sent(c) == "light_on");
    CHECK(c.context().env.light);
    scan_all(c, press{}, release{});
    CHECK(c.context().env.jobs == 0);
    scan_all(c, continue_{});
    CHECK(sent(c) == "light_off");
    CHECK_FALSE(c.context().env.light);
}

TEST_CASE(
    "eca_cell, section 4: on every run of up to 9 inputs, the light is on while the robot works or the cell is paused") {
    long scans = 0;
    explore_next(extended(), plant{}, 9, scans);
    CHECK(scans > 1000);
}

namespace {
/// Feeds the same inputs to both controllers, every sequence of press, release and done up to
/// `depth` long (in any order, plausible or not), and checks that they answer alike.
void compare(eca::controller const& a, eca::extended_controller const& b, int depth, long& scans) {
    if (depth == 0) return;
    auto step = [&](auto const& input) {
        auto a2 = a;
        auto b2 = b;
        bool const same_outcome = eca::scan(a2, input) == eca::scan(b2, input);
        ++scans;
        bool const same = same_outcome && sent(a2) == sent(b2) && a2.context().env.light == b2.context().env.light &&
                          state_of(a2.context().button) == state_of(b2.context().button) &&
                          state_of(a2.context().robot) == state_of(b2.context().robot) && a2.template is<eca::Idle>() &&
                          b2.template is<eca::Idle>();
        if (!same) {
            FAIL_CHECK("the variants differ after " << std::remove_cvref_t<decltype(input)>::name);
            return;
        }
        compare(a2, b2, depth - 1, scans);
    };
    step(press{});
    step(release{});
    step(done{});
}
}  // namespace

TEST_CASE("eca_cell: without pause events, the extended controller answers every input as Figure 5's") {
    long scans = 0;
    compare(original(), extended(), 8, scans);
    CHECK(scans == 9840);  // 3 + 9 + ... + 3^8
}

namespace {
/// Records which of Main's rows fire (a row may be reported more than once per firing).
struct rows_fired {
    std::uint64_t mask = 0;
    void on_row(int row) { mask |= std::uint64_t{1} << row; }
};
template <class Rows>
constexpr std::uint64_t all_rows = (std::uint64_t{1} << std::tuple_size_v<std::remove_cv_t<Rows>>)-1;
}  // namespace

TEST_CASE("eca_cell: every row of both Mains fires in the situations the paper gives") {
    bsc::machine<decltype(eca::main_chart), bsc::default_policy, rows_fired> a{eca::main_chart, {}, {}};
    scan_all(a, press{}, release{}, press{}, release{}, done{});
    CHECK(a.observer().mask == all_rows<decltype(eca::main_rules)>);

    bsc::machine<decltype(eca::extended_main_chart), bsc::default_policy, rows_fired> b{
        eca::extended_main_chart, {}, {}};
    scan_all(b, press{}, release{}, press{}, release{}, pause{}, done{}, press{}, release{}, continue_{}, pause{},
             continue_{}, press{}, pause{}, continue_{}, done{});
    CHECK(b.observer().mask == all_rows<decltype(eca::extended_rules)>);
}
