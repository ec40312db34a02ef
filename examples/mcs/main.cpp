// The Mode Control Supervisor at work.
//   mcs                 runs a scripted operator run and checks every step of it
//   mcs --interactive   the paper's virtual HMI: reads button names from standard input
// Each push prints the button, the resulting active configuration, the error code and what
// Show put on the display, e.g.
//   JOG_P     -> MCS On Manual Jog        error 0  show -Setup +Manual +Jog

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include "mcs.hpp"

namespace {

bool same_name(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    });
}

struct push {
    std::string_view button;  // the button's own name, e.g. "MDI_P"
    bsc::outcome outcome;
};

/// Pushes the button called `name` (in any case); nothing happens if no button is called so.
std::optional<push> press(mcs::machine& m, std::string_view name) {
    return [&]<class... Button>(mcs::button_list<Button...>) {
        std::optional<push> result;
        auto try_button = [&]<class B>(B const& button) {
            if (!same_name(name, B::name)) return false;
            m.context().display.clear();
            result = push{B::name, m.dispatch(button)};
            return true;
        };
        (void)(try_button(Button{}) || ...);
        return result;
    }(mcs::buttons{});
}

void print(std::string_view button, mcs::machine const& m, bsc::outcome outcome) {
    std::cout << "  " << std::left << std::setw(9) << button << " -> " << std::setw(22)
              << m.active_states().joined() << "  error " << m.context().error;
    if (outcome == bsc::outcome::ignored)
        std::cout << "  (ignored)";
    else
        std::cout << "  show " << m.context().display.text();
    std::cout << '\n';
}

// ---- The scripted operator run ------------------------------------------------------------------

struct step {
    std::string_view button;
    std::string_view expected;  // the active configuration after the push
    int error;                  // panel::error after the push
    bsc::outcome outcome;
};

constexpr auto consumed = bsc::outcome::consumed;
constexpr auto ignored = bsc::outcome::ignored;

constexpr step script[] = {
    // Every mode, group by group.
    {"ON_P", "MCS On Auto Mem", 0, consumed},  // On's default group, Auto's default mode
    {"MDI_P", "MCS On Auto Mdi", 0, consumed},
    {"TAPE_P", "MCS On Auto Tape", 0, consumed},
    {"MEM_P", "MCS On Auto Mem", 0, consumed},
    {"MEM_P", "MCS On Auto Mem", 0, ignored},  // already in Mem
    {"HND_P", "MCS On Manual Handle", 0, consumed},
    {"RPD_P", "MCS On Manual Rpd", 0, consumed},
    {"ZRN_P", "MCS On Manual Zrn", 0, consumed},
    {"EDIT_P", "MCS On Edit", 0, consumed},
    {"SETUP_P", "MCS On Setup", 0, consumed},
    {"RESET_P", "MCS On Setup", 0, ignored},  // nothing to reset
    {"JOG_P", "MCS On Manual Jog", 0, consumed},
    // Emergency stop in Jog; reset, off and on again: back in Jog (On's history).
    {"ESTOP_P", "MCS Estop", 1, consumed},
    {"OFF_P", "MCS Estop", 1, ignored},  // cond: the stop is not reset yet
    {"MDI_P", "MCS Estop", 1, ignored},  // no mode changes in Estop
    {"RESET_P", "MCS Estop", 0, consumed},
    {"OFF_P", "MCS Off", 0, consumed},
    {"ON_P", "MCS On Manual Jog", 0, consumed},
    // History again, through OFF_P this time.
    {"TAPE_P", "MCS On Auto Tape", 0, consumed},
    {"OFF_P", "MCS Off", 0, consumed},
    {"JOG_P", "MCS Off", 0, ignored},  // no mode changes while Off
    {"ON_P", "MCS On Auto Tape", 0, consumed},
    // Emergency stop while Off, and pushed again after a reset.
    {"OFF_P", "MCS Off", 0, consumed},
    {"ESTOP_P", "MCS Estop", 1, consumed},
    {"ON_P", "MCS Estop", 1, ignored},
    {"RESET_P", "MCS Estop", 0, consumed},
    {"ESTOP_P", "MCS Estop", 1, consumed},
    {"RESET_P", "MCS Estop", 0, consumed},
    {"OFF_P", "MCS Off", 0, consumed},
};

char const* to_string(bsc::outcome o) { return o == consumed ? "consumed" : o == ignored ? "ignored" : "other"; }

int run_script() {
    std::cout << "MCS scripted operator run\n";
    mcs::machine m{mcs::chart};
    print("(start)", m, consumed);
    if (m.active_states().joined() != "MCS Off" || m.context().error != 0) {
        std::cerr << "mcs: the machine does not start in 'MCS Off' with error 0\n";
        return 1;
    }
    int number = 0;
    for (step const& s : script) {
        ++number;
        auto const pushed = press(m, s.button);
        if (!pushed) {
            std::cerr << "mcs: step " << number << ": no button is called " << s.button << '\n';
            return 1;
        }
        print(pushed->button, m, pushed->outcome);
        std::string const got = m.active_states().joined();
        if (got != s.expected || m.context().error != s.error || pushed->outcome != s.outcome) {
            std::cerr << "mcs: step " << number << " (" << s.button << "): expected '" << s.expected << "', error "
                      << s.error << ", " << to_string(s.outcome) << "; got '" << got << "', error "
                      << m.context().error << ", " << to_string(pushed->outcome) << '\n';
            return 1;
        }
    }
    std::cout << "script ok: " << number << " pushes, every configuration as expected\n";
    return 0;
}

// ---- The virtual HMI ----------------------------------------------------------------------------

void print_help() {
    std::cout << "buttons (any case):\n";
    [&]<class... Button>(mcs::button_list<Button...>) {
        ((std::cout << "  " << std::left << std::setw(9) << Button::name << Button::label << '\n'), ...);
    }(mcs::buttons{});
    std::cout << "  help     this list\n  quit     leave (so does end of input)\n";
}

std::string_view trim(std::string_view s) {
    auto const space = [](unsigned char c) { return std::isspace(c) != 0; };
    while (!s.empty() && space(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && space(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

int run_interactive() {
    std::cout << "MCS virtual HMI: one button per line, 'help' lists them, 'quit' leaves\n";
    mcs::machine m{mcs::chart};
    print("(start)", m, consumed);
    for (std::string line; std::getline(std::cin, line);) {
        std::string_view const name = trim(line);
        if (name.empty()) continue;
        if (same_name(name, "quit")) break;
        if (same_name(name, "help")) {
            print_help();
        } else if (auto const pushed = press(m, name)) {
            print(pushed->button, m, pushed->outcome);
        } else {
            std::cerr << "mcs: unknown button '" << name << "' ('help' lists the buttons)\n";
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string_view const mode = argc > 1 ? argv[1] : "";
    if (argc == 1) return run_script();
    if (argc == 2 && mode == "--interactive") return run_interactive();
    std::cerr << "usage: mcs [--interactive]\n"
                 "  without arguments: run the scripted operator run and check it\n"
                 "  --interactive:     push buttons by name, one per line on standard input\n";
    return 2;
}
