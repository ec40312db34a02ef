// The Mode Control Supervisor at work.
//   mcs                 runs a scripted operator run and checks every step of it
//   mcs --interactive   the paper's virtual HMI: reads button names from standard input
//   mcs --inspect PORT  the same, watched in the browser (bsc::inspector, docs/inspector.md) at
//                       http://127.0.0.1:PORT/; with --commands the page's buttons push too
//   --log               (with any) also writes bsc::logger's record of every exit,
//                       transition and entry to standard error
//   --trace FILE        (with any) records the run in FILE as a trace stream (docs/trace.md)
// Each push prints the button, the resulting active configuration, the error code and what
// Show put on the display, e.g.
//   JOG_P     -> MCS On Manual Jog        error 0  show -Setup +Manual +Jog
// A button is pushed by name: bsc::event_set names the chart's events (each button's `name`),
// and dispatch_by_number dispatches the one found.

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include <bsc/inspector.hpp>
#include <bsc/logger.hpp>
#include <bsc/observers.hpp>
#include <bsc/trace.hpp>

#include "mcs.hpp"

namespace {

// The example's machine: the MCS chart with a logger, which writes only when given a stream,
// and a tracer, whose frames are read only when the run is recorded or inspected.
using tracer = bsc::tracer<decltype(mcs::chart)>;
using machine = bsc::machine<bsc::chart_ref<mcs::chart>, bsc::default_policy, bsc::observers<bsc::logger, tracer>>;
using events = bsc::event_set<decltype(mcs::chart)>;

struct options {
    bool interactive = false;
    bool log = false;
    std::string trace;  // the file to record the trace in, if any
    int inspect = -1;   // the inspector's port, if any
    bool commands = false;
    std::string web_root = BSC_MCS_WEB_ROOT;
};

// The transitions the logger has recorded, which the scripted run checks against its pushes.
long logged_transitions = 0;

// The trace's ring, drained after every push (to the file) or poll (to the page): 64 KiB
// holds the dictionary and far more than one push writes. Without a reader it stays unused.
std::array<std::byte, 1 << 16> trace_storage;
bsc::trace_buffer trace_buffer{trace_storage};
bsc::trace_buffer unread_trace{std::span<std::byte>{}};  // drops every frame: nothing reads it

machine make_machine(options const& o) {
    bool const traced = !o.trace.empty() || o.inspect >= 0;
    tracer t{mcs::chart, traced ? trace_buffer : unread_trace};
    if (!o.log) return machine{mcs::chart, mcs::panel{}, bsc::observers{bsc::logger{bsc::logger::sink_type{}}, t}};
    return machine{mcs::chart, mcs::panel{},
                   bsc::observers{bsc::logger{[](bsc::log_record const& r) {
                                      std::clog << bsc::to_string(r) << '\n';
                                      logged_transitions += r.what == bsc::log_record::kind::transition;
                                  }},
                                  t}};
}

// Writes what the trace's ring holds to `file` (if open).
void drain_trace(std::ofstream& file) {
    std::array<std::byte, 4096> chunk;
    while (std::size_t const n = trace_buffer.read(chunk))
        if (file) file.write(reinterpret_cast<char const*>(chunk.data()), static_cast<std::streamsize>(n));
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

bool open_trace(std::ofstream& file, std::string const& path) {
    file.open(path, std::ios::binary);
    if (!file) std::cerr << "mcs: cannot write " << path << '\n';
    return static_cast<bool>(file);
}

char const* to_string(bsc::outcome o) { return o == consumed ? "consumed" : o == ignored ? "ignored" : "other"; }

int run_script(options const& o) {
    bool const log = o.log;
    std::cout << "MCS scripted operator run\n";
    std::ofstream trace_file;
    if (!o.trace.empty() && !open_trace(trace_file, o.trace)) return 2;
    machine m = make_machine(o);
    m.observer().get<1>().sample(m);
    drain_trace(trace_file);
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
        m.observer().get<1>().sample(m);
        drain_trace(trace_file);
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

// One line of the operator's: a button, help or quit. Returns false for quit.
bool take_line(machine& m, std::string_view line) {
    std::string_view const name = trim(line);
    if (name.empty()) return true;
    if (same_name(name, "quit")) return false;
    if (same_name(name, "help")) {
        print_help();
    } else if (auto const pushed = press(m, name)) {
        print(pushed->button, m, pushed->outcome, pushed->shown_before);
        m.observer().get<1>().sample(m);
    } else {
        std::cerr << "mcs: " << events::unknown(name) << " (any case; 'help' lists the buttons)\n";
    }
    return true;
}

int run_interactive(options const& o) {
    std::cout << "MCS virtual HMI: one button per line, 'help' lists them, 'quit' leaves\n";
    std::ofstream trace_file;
    if (!o.trace.empty() && !open_trace(trace_file, o.trace)) return 2;
    machine m = make_machine(o);
    m.observer().get<1>().sample(m);
    print("(start)", m, consumed, 0);
    for (std::string line; std::getline(std::cin, line);) {
        bool const more = take_line(m, line);
        drain_trace(trace_file);
        if (!more) break;
    }
    return 0;
}

// The virtual HMI watched, and with --commands driven, from the browser: the inspector serves
// the page between the lines read from standard input, which stay open until quit or its end.
int run_inspected(options const& o) {
    machine m = make_machine(o);
    m.observer().get<1>().sample(m);
    bsc::inspector_options view_options;
    view_options.port = static_cast<std::uint16_t>(o.inspect);
    view_options.commands = o.commands;
    view_options.web_root = o.web_root;
    view_options.on_command = [&m](std::string_view command, std::string_view answer) {
        std::cout << "  page: " << std::left << std::setw(16) << command << " -> " << std::setw(22)
                  << m.active_states().joined() << "  error " << m.context().error << "  (" << answer << ")"
                  << std::endl;
    };
    bsc::inspector view{m, trace_buffer, std::move(view_options)};
    std::cout << "MCS virtual HMI, inspected: one button per line, 'help' lists them, 'quit' leaves\n"
              << "inspect: " << view.url() << (o.commands ? "" : " (read-only: --commands lets the page push)")
              << std::endl;
    print("(start)", m, consumed, 0);
    std::cout << std::flush;
    std::string pending;
    for (;;) {
        view.poll(std::chrono::milliseconds{50});
        pollfd input{0, POLLIN, 0};
        if (::poll(&input, 1, 0) <= 0 || (input.revents & (POLLIN | POLLHUP)) == 0) continue;
        char chunk[256];
        ssize_t const n = ::read(0, chunk, sizeof chunk);
        if (n <= 0) break;  // end of input: leave
        pending.append(chunk, static_cast<std::size_t>(n));
        bool more = true;
        for (std::size_t end; more && (end = pending.find('\n')) != std::string::npos;) {
            more = take_line(m, std::string_view{pending}.substr(0, end));
            pending.erase(0, end + 1);
        }
        std::cout << std::flush;
        if (!more) break;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    options o;
    bool bad = false;
    for (int i = 1; i < argc && !bad; ++i) {
        std::string_view const a = argv[i];
        if (a == "--interactive" && !o.interactive) {
            o.interactive = true;
        } else if (a == "--log" && !o.log) {
            o.log = true;
        } else if (a == "--trace" && i + 1 < argc && o.trace.empty()) {
            o.trace = argv[++i];
        } else if (a == "--inspect" && i + 1 < argc && o.inspect < 0) {
            std::string_view const port = argv[++i];
            int value = 0;
            auto const r = std::from_chars(port.data(), port.data() + port.size(), value);
            bad = r.ec != std::errc{} || r.ptr != port.data() + port.size() || value < 0 || value > 65535;
            o.inspect = value;
        } else if (a == "--commands" && !o.commands) {
            o.commands = true;
        } else if (a == "--web-root" && i + 1 < argc) {
            o.web_root = argv[++i];
        } else {
            bad = true;
        }
    }
    bool const asked = argc == 2 && (std::string_view{argv[1]} == "--help" || std::string_view{argv[1]} == "-h");
    if (bad || asked || (o.commands && o.inspect < 0)) {
        (asked ? std::cout : std::cerr)
            << "usage: mcs [--interactive | --inspect PORT [--commands] [--web-root DIR]] [--log] [--trace FILE]\n"
               "  without flags:   run the scripted operator run and check it\n"
               "  --interactive    push buttons by name, one per line on standard input (default: off, the script)\n"
               "  --inspect PORT   as --interactive, and serve the live view at http://127.0.0.1:PORT/ (0: any free\n"
               "                   port; the address is printed) until quit or the end of standard input\n"
               "  --commands       (with --inspect) let the page push buttons (default: the view is read-only)\n"
               "  --web-root DIR   the inspector page's folder (default: the build's, " BSC_MCS_WEB_ROOT
               ")\n"
               "  --log            write every exit, transition and entry to standard error (default: off)\n"
               "  --trace FILE     record the run in FILE as a trace stream (default: none)\n"
               "  -h, --help       print this text and exit\n";
        return asked ? 0 : 2;
    }
    if (o.inspect >= 0) return run_inspected(o);
    return o.interactive ? run_interactive(o) : run_script(o);
}
