// The ECA MFSM controller of the push button / robot / light cell at work, before and after
// the Pause extension (examples/eca_cell/modules.hpp and pause.hpp). Three scripted runs:
//
//   1. the controller of Figure 5 (Main, Button, Robot) on a run of presses, releases and
//      robot completions;
//   2. the extended controller of Figure 7b (Main, Button, Robot, Pause) on the same run: with
//      no pause event it answers as the controller of Figure 5;
//   3. the extended controller on a run with pause and continue.
//
// Each input is one scan. The program prints the input, the state of every module after the
// scan (Main's, then the Peripheral modules'), the output events the scan sent and the light,
// and compares them with what the script expects. It exits with status 1 if anything differs.

#include <cstdio>
#include <string>
#include <string_view>
#include <utility>

#include "pause.hpp"

namespace {

/// What a scan should leave: the Peripheral modules' states ("" for Pause: not checked), the
/// output events sent, and the light.
struct expect {
    std::string_view button;
    std::string_view robot;
    std::string_view pause;
    std::string_view outputs;
    bool light;
};

template <class Module>
std::string_view state_of(Module const& m) {
    auto const names = m.active_states();
    return names[names.size() - 1];  // the innermost active state: below the module's root
}

template <class Controller>
constexpr bool has_pause = requires(Controller const& c) {
    c.context().pause;
};

template <class Controller>
class script {
public:
    script(char const* title, Controller controller) : c_(std::move(controller)) {
        std::printf("%s\n  %-9s  %-5s %-9s %-5s %-8s %-16s %s\n", title, "input", "Main", "Button", "Robot",
                    has_pause<Controller> ? "Pause" : "", "outputs", "light");
        print("(start)");
        check("(start)", true, {"Released", "Idle", "Running", "", false});
    }

    /// One scan with the input event e, then the comparison with x.
    template <class E>
    void input(E const& e, expect x) {
        ++inputs_;
        bool const consumed = eca::scan(c_, e) == bsc::outcome::consumed;
        print(E::name);
        check(E::name, consumed, x);
    }

    int inputs() const { return inputs_; }
    int failures() const { return failures_; }
    Controller const& controller() const { return c_; }

private:
    void print(std::string_view input) {
        auto const& m = c_.context();
        std::string_view pause = "";  // never a null pointer for printf's %.*s
        if constexpr (has_pause<Controller>) pause = state_of(m.pause);
        std::printf("  %-9.*s  %-5.*s %-9.*s %-5.*s %-8.*s %-16s %s\n", static_cast<int>(input.size()), input.data(),
                    static_cast<int>(state_of(c_).size()), state_of(c_).data(),
                    static_cast<int>(state_of(m.button).size()), state_of(m.button).data(),
                    static_cast<int>(state_of(m.robot).size()), state_of(m.robot).data(),
                    static_cast<int>(pause.size()), pause.data(), m.env.sent.get().joined().c_str(),
                    m.env.light ? "on" : "off");
    }

    void check(std::string_view input, bool consumed, expect const& x) {
        auto const& m = c_.context();
        auto fail = [&](char const* what, std::string_view expected, std::string_view got) {
            ++failures_;
            std::printf("  ** after input %d (%.*s): %s: expected \"%.*s\", got \"%.*s\"\n", inputs_,
                        static_cast<int>(input.size()), input.data(), what, static_cast<int>(expected.size()),
                        expected.data(), static_cast<int>(got.size()), got.data());
        };
        // Definition 4: Idle is Main's only stable state; Definition 9: every input has a rule.
        if (!c_.template is<eca::Idle>()) fail("Main", "Idle", state_of(c_));
        if (!consumed) fail("outcome", "consumed", "ignored");
        if (state_of(m.button) != x.button) fail("Button", x.button, state_of(m.button));
        if (state_of(m.robot) != x.robot) fail("Robot", x.robot, state_of(m.robot));
        if constexpr (has_pause<Controller>)
            if (!x.pause.empty() && state_of(m.pause) != x.pause) fail("Pause", x.pause, state_of(m.pause));
        if (m.env.sent.get().joined() != x.outputs) fail("outputs", x.outputs, m.env.sent.get().joined());
        if (m.env.light != x.light) fail("light", x.light ? "on" : "off", m.env.light ? "on" : "off");
    }

    Controller c_;
    int inputs_ = 0;
    int failures_ = 0;
};

// The behaviour of section 2.1: a press lights the light and starts the robot; a release, or a
// press while the robot is busy, has no effect; the light goes out when the robot is done.
template <class Controller>
void figure_5_run(script<Controller>& s) {
    using namespace eca::in;
    s.input(press{}, {"Pressed", "Busy", "", "start light_on", true});  // rule 1, Robot? Idle
    s.input(release{}, {"Released", "Busy", "", "", true});             // rule 2
    s.input(press{}, {"Pressed", "Busy", "", "", true});                // rule 1, Robot? Busy: no effect
    s.input(release{}, {"Released", "Busy", "", "", true});
    s.input(done{}, {"Released", "Idle", "", "light_off", false});  // rule 3
    s.input(press{}, {"Pressed", "Busy", "", "start light_on", true});
    s.input(done{}, {"Pressed", "Idle", "", "light_off", false});  // done while the button is held
    s.input(release{}, {"Released", "Idle", "", "", false});
}

// Section 4: after pause, the light stays on once the robot has finished, and requests are
// ignored; continue brings the system back to normal mode.
void figure_7b_run(script<eca::extended_controller>& s) {
    using namespace eca::in;
    s.input(press{}, {"Pressed", "Busy", "Running", "start light_on", true});  // rules 4 and 1
    s.input(release{}, {"Released", "Busy", "Running", "", true});
    s.input(pause{}, {"Released", "Busy", "Paused", "", true});  // rule 6, Robot? Busy
    s.input(done{}, {"Released", "Idle", "Paused", "", true});   // rule 5, Pause? Paused: light stays on
    s.input(press{}, {"Pressed", "Idle", "Paused", "", true});   // rule 4, Pause? Paused: ignored
    s.input(release{}, {"Released", "Idle", "Paused", "", true});
    s.input(continue_{}, {"Released", "Idle", "Running", "light_off", false});  // rule 7, Robot? Idle
    s.input(press{}, {"Pressed", "Busy", "Running", "start light_on", true});   // normal mode again
    s.input(release{}, {"Released", "Busy", "Running", "", true});
    s.input(done{}, {"Released", "Idle", "Running", "light_off", false});  // rules 5 and 3
    s.input(pause{}, {"Released", "Idle", "Paused", "light_on", true});    // rule 6, Robot? Idle
    s.input(press{}, {"Pressed", "Idle", "Paused", "", true});             // ignored
    s.input(release{}, {"Released", "Idle", "Paused", "", true});
    s.input(continue_{}, {"Released", "Idle", "Running", "light_off", false});
    s.input(press{}, {"Pressed", "Busy", "Running", "start light_on", true});
    s.input(pause{}, {"Pressed", "Busy", "Paused", "", true});
    s.input(continue_{}, {"Pressed", "Busy", "Running", "", true});  // rule 7, Robot? Busy
    s.input(release{}, {"Released", "Busy", "Running", "", true});
    s.input(press{}, {"Pressed", "Busy", "Running", "", true});  // rules 4 and 1, Robot? Busy: no effect
    s.input(release{}, {"Released", "Busy", "Running", "", true});
    s.input(done{}, {"Released", "Idle", "Running", "light_off", false});
}

template <class Controller>
int report(script<Controller> const& s, int jobs) {
    int failures = s.failures();
    if (s.controller().context().env.jobs != jobs) {
        std::printf("  ** the robot was started %d times, expected %d\n", s.controller().context().env.jobs, jobs);
        ++failures;
    }
    std::printf(failures == 0 ? "  script ok: %d inputs, every state and output as expected\n\n"
                              : "  script FAILED: %d inputs\n\n",
                s.inputs());
    return failures;
}

}  // namespace

int main() {
    int failures = 0;

    script original{"Figure 5: Main, Button, Robot", eca::controller{eca::main_chart}};
    figure_5_run(original);
    failures += report(original, 2);

    script same_run{"Figure 7b: the extended controller on the same run",
                    eca::extended_controller{eca::extended_main_chart}};
    figure_5_run(same_run);
    failures += report(same_run, 2);

    script extended{"Figure 7b: Main, Button, Robot, Pause", eca::extended_controller{eca::extended_main_chart}};
    figure_7b_run(extended);
    failures += report(extended, 3);

    return failures == 0 ? 0 : 1;
}
