// The production cell in closed loop: five controller actors and five plant models, stepped
// every 100 ms. The operator offers five bricks at fixed times; the run prints one line per step
// in which a controller's state or a brick's place changes, then a summary, and fails (exit
// status 1) if a plant model reaches Damage, a brick is lost, or a brick leaves unforged or not
// at all within the time limit.
//
//   production_cell --trace DIR
//     the same run, recorded into the folder DIR for the inspector's page to replay.
//   production_cell --inspect PORT [--commands] [--web-root DIR] [--period-ms MS]
//     runs the cell in real time, a brick offered every 15 s, watched in the browser: one panel
//     per actor and the links between them (bsc::system_inspector, docs/inspector.md). With
//     --commands the page may pause and step the cell and set the operator's inputs. It stops
//     at the end of standard input or at a line "quit".

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <bsc/system_inspector.hpp>

#include "inspected.hpp"
#include "operation.hpp"

#ifndef BSC_CELL_WEB_ROOT
#define BSC_CELL_WEB_ROOT ""
#endif

namespace {

using namespace std::chrono_literals;

/// A controller's active states without the root and the states that only contain others.
template <class Machine>
std::string states(Machine const& m) {
    constexpr std::string_view containers[] = {"On", "RobotWork", "Turret", "Arm1Job", "Arm2Job"};
    std::string out;
    auto const names = m.active_states();
    for (std::size_t i = 1; i < names.size(); ++i) {
        bool skip = false;
        for (auto c : containers) skip = skip || names[i] == c;
        if (skip) continue;
        if (!out.empty()) out += ' ';
        out += names[i];
    }
    return out;
}

template <class System>
std::string line(System const& s) {
    auto const& a = s.actors;
    return "feed " + states(a.feed_belt) + " | table " + states(a.table) + " | robot " + states(a.robot) + " | press " +
           states(a.press) + " | deposit " + states(a.deposit_belt) + " || " + pcell::picture(s);
}

double seconds(bsc::duration d) { return std::chrono::duration<double>(d).count(); }

/// The checked run: five bricks, as fast as the machine goes; `stepped(cell)` after each step.
template <class System, class Stepped>
int run_checked(Stepped stepped) {
    // Two bricks at once, one shortly after, then two more later.
    std::vector<bsc::duration> const offers{0s, 0s, 2s, 15s, 16s};
    constexpr auto time_limit = 90s;

    pcell::run<System> r{offers};
    std::string previous;
    bool conserved = true;
    while (!r.done() && r.now() <= time_limit && pcell::no_damage(r.cell)) {
        auto const t = r.now();
        r.step();
        stepped(r.cell);
        conserved = conserved && r.bricks_conserved();
        auto const now = line(r.cell);
        if (now != previous) std::printf("%6.1f s  %s\n", seconds(t), now.c_str());
        previous = now;
    }

    bsc::duration longest{};
    for (std::size_t k = 0; k < r.offered(); ++k)
        if (r.left_at(k) != r.never) longest = std::max(longest, r.left_at(k) - r.put_at(k));
    auto const damage = pcell::damaged(r.cell);
    auto const unforged = r.cell.actors.env_deposit_belt.context().unforged;

    std::printf("\nbricks offered %zu, fed %zu, forged %zu, deposited %zu (unforged %d)\n", r.offered(), r.fed(),
                r.forged(), r.delivered(), unforged);
    std::printf("steps %zu, time %.1f s, longest stay in the cell %.1f s\n", r.steps(), seconds(r.now()),
                seconds(longest));
    bool ok = true;
    if (!damage.empty()) {
        std::printf("FAILED: Damage in %s\n", damage.c_str());
        ok = false;
    }
    if (!conserved) {
        std::printf("FAILED: a brick was lost or seen twice\n");
        ok = false;
    }
    if (!r.done() || unforged != 0) {
        std::printf("FAILED: not every brick left the cell forged\n");
        ok = false;
    }
    if (ok) std::printf("ok: every brick forged and deposited, no Damage\n");
    return ok ? 0 : 1;
}

// The checked run recorded into `folder`: system.json (the system's description) and one
// <actor>.bsctrace per actor, which the inspector's page replays from disk.
int run_recorded(std::string const& folder) {
    using view = bsc::system_inspector<pcell::traced_cell>;
    std::ofstream description{folder + "/system.json"};
    description << view::description() << "\n";
    // (The rings are in the system's order: inspected.hpp declares them so.)
    std::array<std::ofstream, view::actor_names().size()> files;
    for (std::size_t i = 0; i < files.size(); ++i)
        files[i].open(folder + "/" + std::string{view::actor_names()[i]} + ".bsctrace", std::ios::binary);
    auto const drain = [&files] {
        std::array<std::byte, 4096> chunk;
        for (std::size_t i = 0; i < files.size(); ++i)
            while (std::size_t const n = pcell::trace_rings[i].read(chunk))
                files[i].write(reinterpret_cast<char const*>(chunk.data()), static_cast<std::streamsize>(n));
    };
    drain();  // the dictionaries and the construction, written before the first step
    int const status = run_checked<pcell::traced_cell>([&drain](pcell::traced_cell& cell) {
        pcell::sample_all(cell);
        drain();
    });
    bool written = static_cast<bool>(description.flush());
    for (auto& f : files) written = written && static_cast<bool>(f.flush());
    for (auto const& ring : pcell::trace_rings) written = written && ring.dropped() == 0;
    if (!written) {
        std::fprintf(stderr, "production_cell: could not record the run into %s\n", folder.c_str());
        return 2;
    }
    std::printf("recorded into %s: system.json and %zu traces\n", folder.c_str(), files.size());
    return status;
}

struct options {
    std::string trace;  // the folder to record into, if any
    int inspect = -1;   // the inspector's port, if any
    bool commands = false;
    std::string web_root = BSC_CELL_WEB_ROOT;
    int period_ms = 100;  // wall time per step
};

// The cell in real time, watched from the browser: the inspector serves the page between steps;
// standard input, read without blocking, ends the run at its end or at "quit".
int run_inspected(options const& o) {
    std::vector<bsc::duration> offers;
    for (int k = 0; k < 250; ++k) offers.push_back(std::chrono::seconds{15 * k});  // a brick id is one byte
    pcell::run<pcell::traced_cell> r{offers};
    bsc::inspector_options view_options;
    view_options.port = static_cast<std::uint16_t>(o.inspect);
    view_options.commands = o.commands;
    view_options.stepping = true;
    view_options.web_root = o.web_root;
    view_options.on_command = [&r](std::string_view command, std::string_view answer) {
        std::cout << "  page: " << command << " -> " << answer << " (at " << seconds(r.now()) << " s)" << std::endl;
    };
    bsc::system_inspector view{r.cell, std::move(view_options)};
    view.sample();
    std::cout << "production cell, inspected: 'quit' or the end of input leaves\n"
              << "inspect: " << view.url() << (o.commands ? "" : " (read-only: --commands lets the page drive it)")
              << std::endl;
    auto const period = std::chrono::milliseconds{o.period_ms};
    auto next = std::chrono::steady_clock::now();
    std::string previous, pending;
    for (;;) {
        auto const now = std::chrono::steady_clock::now();
        auto const wait = std::chrono::ceil<std::chrono::milliseconds>(next - now);
        view.poll(std::clamp(wait, std::chrono::milliseconds{0}, std::chrono::milliseconds{50}));
        if (std::chrono::steady_clock::now() >= next || view.paused()) {
            if (view.may_step()) {
                auto const t = r.now();
                r.step();
                view.sample();
                auto const changed = line(r.cell);
                if (changed != previous) std::printf("%6.1f s  %s\n", seconds(t), changed.c_str());
                previous = changed;
                std::fflush(stdout);
                // Late (a slow poll, a pause just ended): start the pace again from now.
                next = std::max(next + period, std::chrono::steady_clock::now());
            }
        }
        pollfd input{0, POLLIN, 0};
        if (::poll(&input, 1, 0) <= 0 || (input.revents & (POLLIN | POLLHUP)) == 0) continue;
        char chunk[256];
        ssize_t const n = ::read(0, chunk, sizeof chunk);
        if (n <= 0) break;
        pending.append(chunk, static_cast<std::size_t>(n));
        bool quit = false;
        for (std::size_t end; !quit && (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1))
            quit = std::string_view{pending}.substr(0, end) == "quit";
        if (quit) break;
    }
    if (!pcell::no_damage(r.cell)) {
        std::printf("FAILED: Damage in %s\n", pcell::damaged(r.cell).c_str());
        return 1;
    }
    return 0;
}

bool read_number(std::string_view text, int low, int high, int& value) {
    auto const r = std::from_chars(text.data(), text.data() + text.size(), value);
    return r.ec == std::errc{} && r.ptr == text.data() + text.size() && value >= low && value <= high;
}

}  // namespace

int main(int argc, char** argv) {
    options o;
    bool bad = false, asked = false;
    for (int i = 1; i < argc && !bad; ++i) {
        std::string_view const a = argv[i];
        if (a == "--inspect" && i + 1 < argc && o.inspect < 0) {
            bad = !read_number(argv[++i], 0, 65535, o.inspect);
        } else if (a == "--commands" && !o.commands) {
            o.commands = true;
        } else if (a == "--web-root" && i + 1 < argc) {
            o.web_root = argv[++i];
        } else if (a == "--period-ms" && i + 1 < argc) {
            bad = !read_number(argv[++i], 1, 10000, o.period_ms);
        } else if (a == "--trace" && i + 1 < argc && o.trace.empty()) {
            o.trace = argv[++i];
        } else if (a == "--help") {
            asked = true;
        } else {
            bad = true;
        }
    }
    bool const inspect_flags = o.commands || o.period_ms != 100 || o.web_root != BSC_CELL_WEB_ROOT;
    if (bad || asked || (o.inspect < 0 && inspect_flags) || (o.inspect >= 0 && !o.trace.empty())) {
        (asked ? std::cout : std::cerr)
            << "usage: production_cell [--trace DIR | --inspect PORT [--commands] [--web-root DIR] [--period-ms MS]]\n"
               "  (no flag)        the checked run: five bricks, a summary, exit status 1 on a failure\n"
               "  --trace DIR      the checked run, recorded into the folder DIR (which must exist): system.json\n"
               "                   and one <actor>.bsctrace per actor, for the inspector's page to replay\n"
               "  --inspect PORT   the cell in real time, a brick every 15 s, served to the browser at\n"
               "                   http://127.0.0.1:PORT/ (0: any free port); ends at 'quit' or the end of input\n"
               "  --commands       let the page pause, step and set the operator's inputs (default: read-only)\n"
               "  --web-root DIR   the inspector page's folder (default: the build's, " BSC_CELL_WEB_ROOT
               ")\n"
               "  --period-ms MS   wall time per step of 100 ms of the cell's time (default: 100)\n";
        return asked ? 0 : 2;
    }
    if (o.inspect >= 0) return run_inspected(o);
    if (!o.trace.empty()) return run_recorded(o.trace);
    return run_checked<pcell::cell>([](pcell::cell const&) {});
}
