// The Mode Control Supervisor at work.
//   mcs                 runs a scripted operator run and checks every step of it
//   mcs --interactive   the paper's virtual HMI: reads button names from standard input
//   --log               (with either) also writes bsc::logger's record of every exit,
//                       transition and entry to standard error
// Each push prints the button, the resulting active configuration, the error code and what
// Show put on the display, e.g.
//   JOG_P     -> MCS On Manual Jog        error 0  show -Setup +Manual +Jog
// A button is pushed by name: bsc::event_set names the chart's events (each button's `name`),
// and dispatch_by_number dispatches the one found.

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include <bsc/logger.hpp>

#include "mcs.hpp"

namespace {

// The example's machine: the MCS chart with a logger, which writes only when given a stream.
using machine = bsc::machine<bsc::chart_ref<mcs::chart>, bsc::default_policy, bsc::logger>;
using events = bsc::event_set<decltype(mcs::chart)>;

// The transitions the logger has recorded, which the scripted run checks against its pushes.
long logged_transitions = 0;

machine make_machine(bool log) {
    if (!log) return machine{mcs::chart, mcs::panel{}, bsc::logger{bsc::logger::sink_type{}}};
    return machine{mcs::chart, mcs::panel{}, bsc::logger{[](bsc::log_record const& r) {
                       std::clog << bsc::to_string(r) << '\n';
                       logged_transitions += r.what == bsc::log_record::kind::transition;
                   }}};
}

bool same_name(std::string_view a, std::string_view b) {
    return std::ranges::equal(a, b, [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    });
}

struct push {
    std::string_view button;  // the button's own name, e.g. "MDI_P"
    bsc::outcome outcome;
    std::size_t shown_before;  // the display's lines before the push (display::shown())
};

/// Pushes the button called `name` (in any case); nothing happens if no button is called so.
std::optional<push> press(machine& m, std::string_view name) {
    auto const found = std::ranges::find_if(events::names,
                                            [&](std::string_view event) { return same_name(name, event); });
    if (found == events::names.end()) return std::nullopt;
    std::size_t const shown_before = m.context().display.shown();
    auto const number = static_cast<std::size_t>(found - events::names.begin());
    return push{*found, m.dispatch_by_number(number), shown_before};
}

/// The push's line: the configuration, the error and what the push showed (the display's lines
/// after the first `shown_before`).
void print(std::string_view button, machine const& m, bsc::outcome outcome, std::size_t shown_before) {
    std::cout << "  " << std::left << std::setw(9) << button << " -> " << std::setw(22) << m.active_states().joined()
              << "  error " << m.context().error;
    if (outcome == bsc::outcome::ignored)
        std::cout << "  (ignored)";
    else
        std::cout << "  show " << m.context().display.text_since(shown_before);
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

int run_script(bool log) {
    std::cout << "MCS scripted operator run\n";
    machine m = make_machine(log);
    print("(start)", m, consumed, 0);
    if (m.active_states().joined() != "MCS Off" || m.context().error != 0) {
        std::cerr << "mcs: the machine does not start in 'MCS Off' with error 0\n";
        return 1;
    }
    int number = 0;
    for (step const& s : script) {
        ++number;
        long const logged_before = logged_transitions;
        auto const pushed = press(m, s.button);
        if (!pushed) {
            std::cerr << "mcs: step " << number << ": no button is called " << s.button << '\n';
            return 1;
        }
        print(pushed->button, m, pushed->outcome, pushed->shown_before);
        std::string const got = m.active_states().joined();
        if (got != s.expected || m.context().error != s.error || pushed->outcome != s.outcome) {
            std::cerr << "mcs: step " << number << " (" << s.button << "): expected '" << s.expected << "', error "
                      << s.error << ", " << to_string(s.outcome) << "; got '" << got << "', error " << m.context().error
                      << ", " << to_string(pushed->outcome) << '\n';
            return 1;
        }
        // With --log, the logger saw a transition for each push that was consumed, and none otherwise.
        if (log && (logged_transitions > logged_before) != (pushed->outcome == consumed)) {
            std::cerr << "mcs: step " << number << " (" << s.button << "): the log does not match the outcome\n";
            return 1;
        }
    }
    if (log && logged_transitions == 0) {
        std::cerr << "mcs: --log recorded no transition\n";
        return 1;
    }
    std::cout << "script ok: " << number << " pushes, every configuration as expected"
              << (log ? ", " + std::to_string(logged_transitions) + " transitions logged" : std::string{}) << '\n';
    return 0;
}

// ---- The virtual HMI ----------------------------------------------------------------------------

void print_help() {
    std::cout << "buttons (any case):\n";
    // clang-format off
    [&]<class... Button>(mcs::button_list<Button...>) {
        ((std::cout << "  " << std::left << std::setw(9) << Button::name << Button::label << '\n'), ...);
    }(mcs::buttons{});
    // clang-format on
    std::cout << "  help     this list\n  quit     leave (so does end of input)\n";
}

std::string_view trim(std::string_view s) {
    auto const space = [](unsigned char c) { return std::isspace(c) != 0; };
    while (!s.empty() && space(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && space(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

int run_interactive(bool log) {
    std::cout << "MCS virtual HMI: one button per line, 'help' lists them, 'quit' leaves\n";
    machine m = make_machine(log);
    print("(start)", m, consumed, 0);
    for (std::string line; std::getline(std::cin, line);) {
        std::string_view const name = trim(line);
        if (name.empty()) continue;
        if (same_name(name, "quit")) break;
        if (same_name(name, "help")) {
            print_help();
        } else if (auto const pushed = press(m, name)) {
            print(pushed->button, m, pushed->outcome, pushed->shown_before);
        } else {
            std::cerr << "mcs: " << events::unknown(name) << " (any case; 'help' lists the buttons)\n";
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    bool interactive = false;
    bool log = false;
    for (int i = 1; i < argc; ++i) {
        std::string_view const a = argv[i];
        if (a == "--interactive" && !interactive) {
            interactive = true;
        } else if (a == "--log" && !log) {
            log = true;
        } else {
            bool const asked = a == "--help" || a == "-h";
            (asked ? std::cout : std::cerr)
                << "usage: mcs [--interactive] [--log]\n"
                   "  without flags:  run the scripted operator run and check it\n"
                   "  --interactive   push buttons by name, one per line on standard input (default: off, the script)\n"
                   "  --log           write every exit, transition and entry to standard error (default: off)\n"
                   "  -h, --help      print this text and exit\n";
            return asked ? 0 : 2;
        }
    }
    return interactive ? run_interactive(log) : run_script(log);
}
