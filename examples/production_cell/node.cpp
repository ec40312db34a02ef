// The production cell as a distributed system: the supervised cell (supervised.hpp) deployed as
// bsc::net nodes. Which actors a process runs is configuration:
//
//   production_cell_node --broker 127.0.0.1:1883 --name table --actors table
//   production_cell_node --broker 127.0.0.1:1883 --name all --actors all
//   production_cell_node --memory
//
// With --broker, the process runs the named actors as one node over MQTT until every actor of
// the node has completed the last step (--steps), writing one JSON line per actor step to
// --trace (what tests/distributed/cell.py merges and checks); with --state-dir, a node started
// again resumes its actors where they were saved. With --memory, the eleven actors run as eleven
// nodes over an in-process transport, and every actor's state after every step (bsc::save's
// bytes) is compared with the one-process bsc::system: the exit status says whether the
// distributed cell computed exactly what the cell computes in one process.

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <bsc/net/memory_transport.hpp>
#include <bsc/net/node.hpp>
#if defined(BSC_HAS_MOSQUITTO)
#include <bsc/net/mosquitto_transport.hpp>
#endif

#include "operation.hpp"
#include "supervised.hpp"

namespace {

using namespace std::chrono_literals;
using cell = pcell::supervised_cell;
using node = bsc::net::node<cell>;

struct arguments {
    std::string broker;
    std::string name = "cell";
    std::vector<std::string> actors;
    std::string prefix = "pcell";
    std::string state_dir;
    std::string trace;
    std::int64_t steps = 1200;  // 120 s of the cell
    long pace_ms = 0;
    long deadline_ms = 300;
    long timeout_s = 120;
    int bricks = static_cast<int>(pcell::supervisor_offers.size());
    bool memory = false;
};

static_assert(pcell::supervisor_offers.size() == 5, "the usage text names the default of --bricks");
constexpr char const* usage_text =
    "usage: production_cell_node (--broker HOST:PORT [node flags] | --memory) [--steps N] [--bricks N]\n"
    "       production_cell_node --help\n"
    "Runs actors of the supervised production cell as a node over MQTT (--broker), or all eleven\n"
    "actors as eleven nodes in one process (--memory), until they complete the last step.\n"
    "  --broker HOST:PORT  the MQTT broker to connect to (one of --broker, --memory is required)\n"
    "  --memory            eleven nodes on the in-process transport, checked against one process\n"
    "  --name NAME         the node's name, unique per broker (default: cell)\n"
    "  --actors A,B,...    the actors the node runs, or all (default: all)\n"
    "  --prefix P          the topics' prefix, one per system (default: pcell)\n"
    "  --state-dir DIR     save the actors' state there, and resume from it (default: none)\n"
    "  --trace FILE        append one JSON line per actor step (default: none)\n"
    "  --steps N           the last step, 100 ms each (default: 1200, 120 s of the cell)\n"
    "  --pace-ms MS        at least MS between two steps of an actor (default: 0, as fast as it can)\n"
    "  --deadline-ms MS    a silent peer is stale after MS (default: 300)\n"
    "  --timeout-s S       give up, exit 1, if not finished after S seconds (default: 120)\n"
    "  --bricks N          the bricks the supervisor puts on the feed belt, 0 to 255 (default: 5)\n"
    "  -h, --help          print this text and exit\n";

[[noreturn]] void usage(char const* message) {
    std::fprintf(stderr, "%s\n%s", message, usage_text);
    std::exit(2);
}

long number(char const* text) {
    long value = 0;
    auto const end = text + std::strlen(text);
    auto const [ptr, ec] = std::from_chars(text, end, value);
    if (ec != std::errc{} || ptr != end) usage("not a number");
    return value;
}

arguments parse(int argc, char** argv) {
    arguments a;
    for (int i = 1; i < argc; ++i) {
        std::string_view const flag = argv[i];
        auto value = [&]() -> char const* {
            if (i + 1 >= argc) usage("a flag lacks its value");
            return argv[++i];
        };
        if (flag == "--help" || flag == "-h") {
            std::fputs(usage_text, stdout);
            std::exit(0);
        }
        if (flag == "--broker")
            a.broker = value();
        else if (flag == "--name")
            a.name = value();
        else if (flag == "--actors") {
            std::string_view list = value();
            if (list == "all") continue;
            while (!list.empty()) {
                auto const comma = list.find(',');
                a.actors.emplace_back(list.substr(0, comma));
                list = comma == std::string_view::npos ? std::string_view{} : list.substr(comma + 1);
            }
        } else if (flag == "--prefix")
            a.prefix = value();
        else if (flag == "--state-dir")
            a.state_dir = value();
        else if (flag == "--trace")
            a.trace = value();
        else if (flag == "--steps")
            a.steps = number(value());
        else if (flag == "--pace-ms")
            a.pace_ms = number(value());
        else if (flag == "--deadline-ms")
            a.deadline_ms = number(value());
        else if (flag == "--timeout-s")
            a.timeout_s = number(value());
        else if (flag == "--bricks")
            a.bricks = static_cast<int>(number(value()));
        else if (flag == "--memory")
            a.memory = true;
        else
            usage("unknown flag");
    }
    if (a.memory == !a.broker.empty()) usage("give either --broker or --memory");
    if (a.bricks < 0 || a.bricks > 255) usage("--bricks is 0 to 255");
    return a;
}

#if defined(BSC_HAS_MOSQUITTO)
// ---- The trace: what each actor's step leaves for the checker ------------------------------------

char const* flag(bool b) { return b ? "true" : "false"; }

std::string json_bricks(std::vector<std::pair<pcell::brick, char const*>> const& bricks) {
    std::string out = "[";
    for (auto const& [b, where] : bricks) {
        if (out.size() > 1) out += ',';
        out += "[" + std::to_string(b.id) + "," + (b.forged ? "true" : "false") + ",\"" + where + "\"]";
    }
    return out + "]";
}

template <class Machine>
std::string json_states(Machine const& m) {
    std::string out = "[";
    for (auto const name : m.active_states()) {
        if (out.size() > 1) out += ',';
        out += "\"" + std::string(name) + "\"";
    }
    return out + "]";
}


/// One line: the step, the actor, when the step ended (the machine's monotonic clock, which all
/// processes of one machine share, in microseconds), whether it read a stale value, its active
/// states, and what the safety checks read of a plant (`driven`: some motor of the plant was
/// commanded to move in this step).
std::string trace_line(cell const& s, std::size_t actor, std::int64_t step, bool stale) {
    auto const& a = s.actors;
    auto const name = node::actor_names()[actor];
    auto const us = std::chrono::duration_cast<std::chrono::microseconds>(
                        std::chrono::steady_clock::now().time_since_epoch())
                        .count();
    std::string line = "{\"step\":" + std::to_string(step) + ",\"actor\":\"" + std::string(name) +
                       "\",\"us\":" + std::to_string(us) + ",\"stale\":" + flag(stale);
    std::vector<std::pair<pcell::brick, char const*>> bricks;
    auto add = [&](pcell::brick b, char const* where) {
        if (b) bricks.emplace_back(b, where);
    };
    if (name == "supervisor") {
        line += ",\"put\":" + std::to_string(a.supervisor.context().next);
        line += ",\"states\":" + json_states(a.supervisor);
    } else if (name == "feed_belt")
        line += ",\"states\":" + json_states(a.feed_belt);
    else if (name == "table")
        line += ",\"states\":" + json_states(a.table);
    else if (name == "robot")
        line += ",\"states\":" + json_states(a.robot);
    else if (name == "press")
        line += ",\"states\":" + json_states(a.press);
    else if (name == "deposit_belt")
        line += ",\"states\":" + json_states(a.deposit_belt);
    else if (name == "env_feed_belt") {
        for (auto const b : a.env_feed_belt.context().slots) add(b, "feed_belt");
        line += ",\"damage\":" + std::string(flag(a.env_feed_belt.is<pcell::Damage>()));
        line += ",\"driven\":" + std::string(flag(a.env_feed_belt.context().motor.get()));
    } else if (name == "env_table") {
        auto const& t = a.env_table.context();
        add(t.load, "table");
        line += ",\"damage\":" + std::string(flag(a.env_table.is<pcell::Damage>()));
        line += ",\"driven\":" + std::string(flag(t.lift.get() != pcell::stop || t.turn.get() != pcell::stop));
    } else if (name == "env_robot") {
        auto const& r = a.env_robot.context();
        add(r.held1, "arm1");
        add(r.held2, "arm2");
        line += ",\"damage\":" + std::string(flag(a.env_robot.is<pcell::Damage>()));
        line += ",\"driven\":" + std::string(flag(r.turn.get() != pcell::stop || r.arm1.get() != pcell::stop ||
                                                  r.arm2.get() != pcell::stop));
        line += ",\"arm1_in_press_area\":" + std::string(flag(r.angle == pcell::arm1_to_press && r.ext1 > 0));
        line += ",\"arm2_in_press_area\":" + std::string(flag(r.angle == pcell::arm2_to_press && r.ext2 > 0));
    } else if (name == "env_press") {
        auto const& p = a.env_press;
        add(p.context().load, "press");
        // Taken by arm2 this step; the robot's model holds it from the next (operation.hpp).
        add(p.context().to_arm2.get(), "arm2");
        line += ",\"damage\":" + std::string(flag(p.is<pcell::Damage>()));
        line += ",\"driven\":" + std::string(flag(p.context().plate.get() != pcell::stop));
        line += ",\"moving\":" + std::string(flag(p.is<pcell::PlateUp>() || p.is<pcell::PlateDown>()));
    } else if (name == "env_deposit_belt") {
        auto const& d = a.env_deposit_belt.context();
        for (auto const b : d.slots) add(b, "deposit_belt");
        line += ",\"damage\":" + std::string(flag(a.env_deposit_belt.is<pcell::Damage>()));
        line += ",\"driven\":" + std::string(flag(d.motor.get()));
        line += ",\"delivered\":" + std::to_string(d.delivered) + ",\"unforged\":" + std::to_string(d.unforged);
    }
    if (name.starts_with("env_")) line += ",\"bricks\":" + json_bricks(bricks);
    return line + "}";
}

#endif

bsc::net::node_options options_of(arguments const& args) {
    bsc::net::node_options o;
    o.prefix = args.prefix;
    o.name = args.name;
    o.actors = args.actors;
    o.period = pcell::period;
    o.last_step = args.steps;
    o.deadline = std::chrono::milliseconds{args.deadline_ms};
    o.pace = std::chrono::milliseconds{args.pace_ms};
    o.state_dir = args.state_dir;
    return o;
}

// The supervisor as the run configures it: `--bricks` bricks in all, given where it is built
// (its context is its own; the environment only sets its inputs).
pcell::supervisor_actor supervisor_of(arguments const& args) {
    pcell::supervisor_io io{};
    io.bricks = static_cast<std::uint8_t>(args.bricks);
    return pcell::supervisor_actor{pcell::supervisor_chart, io};
}

// ---- --memory: eleven nodes in one process, compared with the one-process system --------------------

int run_in_memory(arguments const& args) {
    constexpr std::size_t actors = node::actor_names().size();
    bsc::net::memory_bus bus;
    std::vector<std::unique_ptr<cell>> systems;
    std::vector<std::unique_ptr<bsc::net::memory_transport>> transports;
    std::vector<std::unique_ptr<node>> nodes;
    // What each actor saved after each step, deployed and in one process.
    std::map<std::pair<std::size_t, std::int64_t>, std::vector<std::byte>> deployed;
    auto saved = [](cell const& s, std::size_t actor) {
        std::vector<std::byte> bytes;
        // clang-format off
        [&]<std::size_t... A>(std::index_sequence<A...>) {
            ((A == actor ? (bytes = bsc::save(s.actors.*bsc::net::detail::deployment<cell>::step_at<A>), 0) : 0), ...);
        }(std::make_index_sequence<actors>{});
        // clang-format on
        return bytes;
    };
    auto supervised = [&args] {
        auto s = std::make_unique<cell>();
        s->actors.supervisor = supervisor_of(args);
        return s;
    };
    for (std::size_t a = 0; a < actors; ++a) {
        systems.push_back(supervised());
        transports.push_back(std::make_unique<bsc::net::memory_transport>(bus));
        auto o = options_of(args);
        // One thread runs every node: none is ever silent, whatever the machine's load does to the
        // wall clock, and a deadline could only make a slow run differ from the system's.
        o.deadline = std::chrono::hours{1};
        o.startup = std::chrono::hours{1};
        o.name = std::string(node::actor_names()[a]);
        o.actors = {o.name};
        nodes.push_back(std::make_unique<node>(*systems.back(), *transports.back(), o));
        cell const& s = *systems.back();
        nodes.back()->on_step = [&deployed, &s, saved](std::size_t actor, std::int64_t step) {
            deployed[{actor, step}] = saved(s, actor);
        };
    }
    auto const began = std::chrono::steady_clock::now();
    auto const deadline = began + std::chrono::seconds{args.timeout_s};
    bool all_done = false;
    while (!all_done && std::chrono::steady_clock::now() < deadline) {
        all_done = true;
        for (auto& n : nodes) {
            n->run_once(0ms);
            all_done = all_done && n->finished();
        }
    }
    if (!all_done) {
        std::printf("FAILED: the nodes did not reach step %lld in %ld s\n", static_cast<long long>(args.steps),
                    args.timeout_s);
        return 1;
    }
    auto const deployed_wall = std::chrono::steady_clock::now() - began;
    auto reference_ptr = supervised();
    cell& reference = *reference_ptr;
    std::size_t compared = 0;
    auto const reference_began = std::chrono::steady_clock::now();
    for (std::int64_t step = 0; step <= args.steps; ++step) {
        reference.step(step * pcell::period);
        for (std::size_t a = 0; a < actors; ++a) {
            auto const it = deployed.find({a, step});
            if (it == deployed.end() || it->second != saved(reference, a)) {
                std::printf("FAILED: %.*s differs from the one-process cell after step %lld\n",
                            static_cast<int>(node::actor_names()[a].size()), node::actor_names()[a].data(),
                            static_cast<long long>(step));
                return 1;
            }
            ++compared;
        }
    }
    auto const& d = reference.actors.env_deposit_belt.context();
    double const minutes = static_cast<double>(args.steps + 1) * std::chrono::duration<double>(pcell::period).count() /
                           60;
    auto const per_step = [&](auto wall) {
        return std::chrono::duration<double, std::micro>(wall).count() / static_cast<double>(args.steps + 1);
    };
    // The one-process time includes saving each actor for the comparison; timed again without.
    auto again = supervised();
    auto const plain_began = std::chrono::steady_clock::now();
    for (std::int64_t step = 0; step <= args.steps; ++step) again->step(step * pcell::period);
    auto const plain_wall = std::chrono::steady_clock::now() - plain_began;
    (void)reference_began;
    if (again->actors.env_deposit_belt.context().delivered != d.delivered) return 1;  // and the loop is not elided
    std::printf(
        "%zu actor steps deployed over 11 nodes equal the one-process cell's; bricks delivered %d of %d "
        "(%.2f per minute of the cell)\n",
        compared, d.delivered, args.bricks, d.delivered / minutes);
    std::printf("wall time per step: %.1f us deployed over 11 nodes in memory, %.1f us as one bsc::system\n",
                per_step(deployed_wall), per_step(plain_wall));
    // Every brick delivered forged, unless the run was too short for the supply (a throughput run).
    bool const supplying = reference.actors.supervisor.context().next < args.bricks;
    return (d.delivered == args.bricks || supplying) && d.unforged == 0 && pcell::no_damage(reference) ? 0 : 1;
}

// ---- --broker: one node over MQTT ---------------------------------------------------------------

#if defined(BSC_HAS_MOSQUITTO)
int run_over_mqtt(arguments const& args) {
    auto const colon = args.broker.rfind(':');
    if (colon == std::string::npos) usage("--broker wants HOST:PORT");
    bsc::net::mqtt_endpoint endpoint;
    endpoint.host = args.broker.substr(0, colon);
    endpoint.port = static_cast<int>(number(args.broker.c_str() + colon + 1));
    endpoint.client_id = args.prefix + "-" + args.name;
    bsc::net::mosquitto_transport transport{endpoint};
    cell system{};
    system.actors.supervisor = supervisor_of(args);
    node n{system, transport, options_of(args)};
    std::ofstream trace;
    if (!args.trace.empty()) trace.open(args.trace, std::ios::app);
    n.on_step = [&](std::size_t actor, std::int64_t step) {
        if (trace.is_open()) trace << trace_line(system, actor, step, n.stepped_stale(actor)) << '\n' << std::flush;
    };
    auto const deadline = std::chrono::steady_clock::now() + std::chrono::seconds{args.timeout_s};
    auto last_progress = std::chrono::steady_clock::now();
    while (!n.finished() && std::chrono::steady_clock::now() < deadline) {
        auto const now = std::chrono::steady_clock::now();
        if (n.run_once(20ms) > 0) {
            last_progress = now;
        } else if (now - last_progress > 5s) {  // a node that cannot go on says why
            std::printf("node %s: %s\n", args.name.c_str(), n.waiting().c_str());
            std::fflush(stdout);
            last_progress = now;
        }
    }
    auto const& st = n.stats();
    std::printf(
        "node %s: %llu steps (%llu jumps, %llu with stale inputs), %llu messages sent, %llu applied, "
        "%llu old, %llu refused, %llu actors resumed\n",
        args.name.c_str(), static_cast<unsigned long long>(st.steps), static_cast<unsigned long long>(st.jumps),
        static_cast<unsigned long long>(st.stale_steps), static_cast<unsigned long long>(st.published),
        static_cast<unsigned long long>(st.received), static_cast<unsigned long long>(st.old),
        static_cast<unsigned long long>(st.refused), static_cast<unsigned long long>(st.restored));
    if (!n.finished()) {
        std::printf("FAILED: node %s did not finish in %ld s\n", args.name.c_str(), args.timeout_s);
        return 1;
    }
    return st.refused == 0 ? 0 : 1;
}
#endif

}  // namespace

int main(int argc, char** argv) {
    auto const args = parse(argc, argv);
    if (args.memory) return run_in_memory(args);
#if defined(BSC_HAS_MOSQUITTO)
    return run_over_mqtt(args);
#else
    std::fprintf(stderr, "built without libmosquitto: only --memory is available\n");
    return 2;
#endif
}
