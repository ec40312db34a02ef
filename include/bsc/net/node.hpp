#pragma once
// A system deployed across processes: each process runs a bsc::net::node that steps the actors
// it hosts, and the links between actors on different nodes travel over a transport (MQTT, or
// memory inside one program). Which actor runs where is configuration (node_options::actors);
// the system's declaration, its charts and its links are the same code everywhere.
//
// Stepping follows the system's order exactly, so that a deployed system computes what
// bsc::system::step computes in one process, step by step: actor X runs its step n when
//   - every link into X has its value: the publisher's step n if the publisher comes before X
//     in the order, step n - 1 otherwise (the same rule as bsc::system);
//   - every consumer of X's outputs has read the value X is about to replace (it completed step
//     n - 1 if it comes after X, step n if before).
// A remote publisher or consumer that is silent longer than node_options::deadline, or whose
// node's last will arrived, is stale: X goes on without it, reading what the link's policy says
// (bsc::hold_last, bsc::fail_safe<V>), except on bsc::lossless links, which always wait. An
// actor without lossless links that finds its peers ahead (it was stale, or restarted) jumps to
// their step instead of replaying the ones it missed. Messages carry their step: a value older
// than one applied is never applied.
//
// After each step a node publishes, for every output channel that feeds an actor on another
// node, the value (topic <prefix>/value/<actor>/<channel>) and the actor's progress (topic
// <prefix>/progress/<actor>), and saves the actor (bsc::save) when node_options::state_dir is
// set; a node started again resumes every actor from there. Between steps it sends its last
// messages again every node_options::heartbeat, which both proves it alive and repairs losses.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <bsc/detail/member_names.hpp>
#include <bsc/detail/system_plan.hpp>
#include <bsc/net/transport.hpp>
#include <bsc/net/wire.hpp>
#include <bsc/retain.hpp>
#include <bsc/system.hpp>

namespace bsc::net {

/// How a node runs. Every node of a system must agree on `prefix` and `period`.
struct node_options {
    std::string prefix = "bsc";                        ///< the system's topics start with it
    std::string name = "node";                         ///< the node's name, unique in the system (its will's topic)
    std::vector<std::string> actors{};                 ///< names of the actors this node runs; empty: all of them
    duration period = std::chrono::milliseconds{100};  ///< step n runs at time n * period
    std::int64_t last_step = std::numeric_limits<std::int64_t>::max();  ///< the actors stop after it
    std::chrono::milliseconds deadline{300};                            ///< silence after which a peer is stale
    std::chrono::milliseconds startup{10000};  ///< how long a peer never heard of is waited for
    std::chrono::milliseconds heartbeat{50};   ///< the last messages are sent again this often
    std::chrono::microseconds pace{0};         ///< at least this much wall time per step (0: as fast as inputs allow)
    std::filesystem::path state_dir{};         ///< where each actor is saved after each step; empty: nowhere
    std::function<std::chrono::steady_clock::time_point()> clock = [] { return std::chrono::steady_clock::now(); };
};

/// What a node has done so far.
struct node_stats {
    std::uint64_t steps = 0;        ///< actor steps taken
    std::uint64_t jumps = 0;        ///< steps that skipped ahead to rejoin the peers
    std::uint64_t stale_steps = 0;  ///< actor steps taken with at least one stale input
    std::uint64_t published = 0;    ///< messages sent, heartbeats included
    std::uint64_t received = 0;     ///< messages applied
    std::uint64_t old = 0;          ///< messages not newer than what was applied (repeats, late ones)
    std::uint64_t refused = 0;      ///< messages with a wrong header, fingerprint or body
    std::uint64_t restored = 0;     ///< actors resumed from saved state
};

namespace detail {

// What a node knows of its system: the actors' places and names, the links' ends.
template <class System>
using deployment = bsc::detail::system_plan<System>;

}  // namespace detail

/// One node of a distributed `System` (a bsc::system): runs the actors it hosts on the system it
/// is given (the other actors of that system are unused) and talks over `transport`.
/// Requirements: every actor is a bsc::machine whose context bsc::save can store; the value type
/// of every link crossing nodes can be saved too. Not thread-safe: one thread runs a node.
template <class System>
class node {
    using plan = detail::deployment<System>;
    static constexpr std::size_t N = plan::actor_count;
    static constexpr std::size_t L = plan::link_count;
    using links = typename System::links_type;
    using time_point = std::chrono::steady_clock::time_point;
    static constexpr std::int64_t unknown = std::numeric_limits<std::int64_t>::min();
    // The largest step a message or a saved state may name: far from overflow in n + 1 and in
    // n * period, and more than 29,000 years of 100 ms steps.
    static constexpr std::int64_t max_step = std::int64_t{1} << 43;
    static_assert(N <= 255, "bsc::net::node: a will names the node's actors in one byte each");

public:
    /// Called after each actor step, with the actor's place in the system's order and the step.
    std::function<void(std::size_t actor, std::int64_t step)> on_step;

    node(System& sys, transport& t, node_options options) : system_(sys), net_(t), options_(std::move(options)) {
        if (!valid_topic_part(options_.prefix, true) || !valid_topic_part(options_.name, false))
            throw std::invalid_argument(
                "bsc::net::node: the prefix and the node's name must not be empty nor hold "
                "'+', '#' or NUL, and the name no '/'");
        if (options_.period <= duration::zero())
            throw std::invalid_argument("bsc::net::node: the period must be positive");
        // Far beyond any use, and far from the clock's overflow.
        constexpr std::chrono::milliseconds day{24 * 3600 * 1000};
        options_.deadline = std::clamp(options_.deadline, std::chrono::milliseconds{0}, day);
        options_.startup = std::clamp(options_.startup, options_.deadline, day);
        options_.heartbeat = std::clamp(options_.heartbeat, std::chrono::milliseconds{1}, day);
        options_.last_step = std::clamp<std::int64_t>(options_.last_step, -1, max_step);
        if (!options_.state_dir.empty()) std::filesystem::create_directories(options_.state_dir);
        for (std::size_t a = 0; a < N; ++a) {
            local_[a] = options_.actors.empty() || std::find(options_.actors.begin(), options_.actors.end(),
                                                             plan::names[a]) != options_.actors.end();
        }
        for (auto const& name : options_.actors)
            if (std::find(plan::names.begin(), plan::names.end(), name) == plan::names.end())
                throw std::invalid_argument("bsc::net::node: the system has no actor named \"" + name + "\"");
        start_ = options_.clock();
        for (std::size_t a = 0; a < N; ++a) {
            peers_[a].completed = local_[a] ? -1 : unknown;
            // Never heard of: stale once `startup` has passed.
            peers_[a].heard = start_ + options_.startup - options_.deadline;
            progress_topic_[a] = options_.prefix + "/progress/" + std::string(plan::names[a]);
        }
        link_topics();
        for (std::size_t a = 0; a < N; ++a)
            if (local_[a]) restore_actor(a);
        subscribe();
        std::vector<std::uint8_t> mine;
        for (std::size_t a = 0; a < N; ++a)
            if (local_[a]) mine.push_back(static_cast<std::uint8_t>(a));
        auto const will = wire::encode(wire::kind::will, 0, system_fingerprint(), mine);
        net_.set_will(options_.prefix + "/node/" + options_.name, will);
        for (std::size_t a = 0; a < N; ++a)
            if (local_[a]) publish_actor(a);
        last_heartbeat_ = start_;
    }

    node(node const&) = delete;
    node& operator=(node const&) = delete;

    /// Applies what has arrived and steps each hosted actor at most once, if it can; when none
    /// can, waits at most `wait` for a message. Returns the number of actor steps taken. Call it
    /// in a loop: between calls nothing happens, and no call blocks longer than `wait` (or the
    /// heartbeat) beyond the transport's poll.
    std::size_t run_once(std::chrono::milliseconds wait) {
        receive(std::chrono::milliseconds{0});
        std::size_t taken = step_ready();
        if (taken == 0) {
            auto timeout = std::min(wait, options_.heartbeat);
            if (paced_until_) {  // an actor waits for its pace, not for a message
                auto const left = std::chrono::ceil<std::chrono::milliseconds>(*paced_until_ - options_.clock());
                timeout = std::clamp(left, std::chrono::milliseconds{0}, timeout);
            }
            receive(timeout);
            taken = step_ready();
        }
        auto const now = options_.clock();
        if (now - last_heartbeat_ >= options_.heartbeat) {
            last_heartbeat_ = now;
            for (std::size_t a = 0; a < N; ++a)
                if (local_[a]) resend(a);
        }
        return taken;
    }

    /// Every hosted actor has completed node_options::last_step, and every peer on another node
    /// linked to them, reader or publisher, has completed it too (or is stale, on a link that is
    /// not lossless), and has been so for two heartbeats, in which run_once sent the last messages
    /// again: the node may stop without leaving anyone waiting for its messages.
    bool finished() const {
        auto const now = options_.clock();
        if (!all_done(now)) {
            done_since_.reset();
            return false;
        }
        if (!done_since_) done_since_ = now;
        return now - *done_since_ >= 2 * options_.heartbeat;
    }

    /// Lets the hosted actors run up to `step` (node_options::last_step), e.g. to extend a run.
    void stop_after(std::int64_t step) { options_.last_step = std::clamp<std::int64_t>(step, -1, max_step); }

    /// The actors' names, in the system's order.
    static constexpr std::span<std::string_view const, N> actor_names() { return plan::names; }
    /// Whether this node runs the actor at `place` in the system's order.
    bool hosts(std::size_t place) const { return local_[place]; }
    /// The last step the actor is known to have completed (-1: none yet; lowest value: never heard of).
    std::int64_t completed(std::size_t place) const { return peers_[place].completed; }
    /// Whether the actor at `place` (on another node) is stale now.
    bool is_stale(std::size_t place) const { return !local_[place] && stale(place, options_.clock()); }
    /// What each hosted actor that has not finished waits for, e.g. "table waits for the value of
    /// step 12 of robot (has 11)", after "cannot reach <the transport's peer>; " while the
    /// transport is not connected; empty when none waits. For diagnostics.
    std::string waiting() const {
        std::string out;
        auto const now = options_.clock();
        for (std::size_t a = 0; a < N; ++a) {
            if (!local_[a] || peers_[a].completed >= options_.last_step) continue;
            std::string why;
            bool stale_input = false;
            if (ready(a, peers_[a].completed + 1, now, stale_input, &why)) continue;
            if (!out.empty()) out += "; ";
            out += std::string(plan::names[a]) + " waits for " + why;
        }
        if (!out.empty() && !net_.connected()) out = "cannot reach " + net_.peer() + "; " + out;
        return out;
    }
    /// Whether the last step of the hosted actor at `place` read a stale value.
    bool stepped_stale(std::size_t place) const { return stepped_stale_[place]; }
    node_stats const& stats() const { return stats_; }
    System& system() { return system_; }
    System const& system() const { return system_; }

private:
    struct peer {
        std::int64_t completed = unknown;
        time_point heard{};
        bool will = false;  // the node's will arrived after its last message
    };
    template <class T>
    struct slot {
        T value{};
        std::int64_t step = unknown;
    };
    template <class Link>
    using slot_of = slot<typename plan::template value_of<Link>>;
    template <class... Ls>
    static auto slots_of(std::tuple<Ls...>*) -> std::tuple<slot_of<Ls>...>;

    bool all_done(time_point now) const {
        for (std::size_t a = 0; a < N; ++a)
            if (local_[a] && peers_[a].completed < options_.last_step) return false;
        for (std::size_t i = 0; i < L; ++i) {
            auto const p = plan::from[i], c = plan::to[i];
            if (local_[p] == local_[c]) continue;
            auto const remote = local_[p] ? c : p;
            if (peers_[remote].completed < options_.last_step && (plan::lossless[i] || !stale(remote, now)))
                return false;
        }
        return true;
    }

    // ---- set-up ---------------------------------------------------------------------------------

    static bool valid_topic_part(std::string const& s, bool slashes) {
        return !s.empty() && s.find_first_of(std::string("+#\0", 3)) == std::string::npos &&
               (slashes || s.find('/') == std::string::npos);
    }

    static constexpr std::uint64_t system_fingerprint() {
        bsc::detail::fingerprint f;
        // clang-format off
        [&]<std::size_t... A>(std::index_sequence<A...>) {
            ((f.add(plan::names[A]),
              f.add(bsc::detail::chart_fingerprint<typename plan::template machine_at<A>>())),
             ...);
        }(std::make_index_sequence<N>{});
        // clang-format on
        // The wiring too: the same charts linked otherwise are another system.
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((f.add(plan::from[I]), f.add(plan::to[I]), f.add(plan::lossless[I] ? 1u : 0u),
              f.add(bsc::detail::member_name<std::tuple_element_t<I, links>::from_channel>()),
              f.add(bsc::detail::member_name<std::tuple_element_t<I, links>::to_channel>())),
             ...);
        }(std::make_index_sequence<L>{});
        // clang-format on
        return f.value;
    }

    template <std::size_t A>
    static constexpr std::uint64_t actor_fingerprint() {
        return bsc::detail::chart_fingerprint<typename plan::template machine_at<A>>();
    }
    // clang-format off
    static constexpr std::array<std::uint64_t, N> actor_fingerprints = []<std::size_t... A>(std::index_sequence<A...>) {
        return std::array<std::uint64_t, N>{actor_fingerprint<A>()...};
    }(std::make_index_sequence<N>{});
    // clang-format on

    template <std::size_t I>
    static constexpr std::uint64_t link_fingerprint() {
        using link = std::tuple_element_t<I, links>;
        return wire::value_fingerprint<typename plan::template machine_at<plan::from[I]>, link::from_channel>();
    }

    void link_topics() {
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((value_topic_[I] = options_.prefix + "/value/" + std::string(plan::names[plan::from[I]]) + "/" +
                                std::string(bsc::detail::member_name<std::tuple_element_t<I, links>::from_channel>())),
             ...);
        }(std::make_index_sequence<L>{});
        // clang-format on
        // One message per channel, whatever the number of links that read it.
        for (std::size_t i = 0; i < L; ++i) {
            first_reader_[i] = i;
            for (std::size_t j = 0; j < i; ++j)
                if (value_topic_[j] == value_topic_[i]) {
                    first_reader_[i] = first_reader_[j];
                    break;
                }
        }
    }

    void subscribe() {
        std::vector<std::string> done;
        auto once = [&](std::string const& filter) {
            if (std::find(done.begin(), done.end(), filter) != done.end()) return;
            done.push_back(filter);
            net_.subscribe(filter);
        };
        for (std::size_t i = 0; i < L; ++i) {
            auto const p = plan::from[i], c = plan::to[i];
            if (local_[c] && !local_[p]) {
                once(value_topic_[i]);
                once(progress_topic_[p]);
                topic_links_[value_topic_[i]].push_back(i);
            }
            if (local_[p] && !local_[c]) once(progress_topic_[c]);
        }
        for (std::size_t a = 0; a < N; ++a) topic_actor_[progress_topic_[a]] = a;
        once(options_.prefix + "/node/+");
    }

    // ---- retained state -------------------------------------------------------------------------

    std::filesystem::path state_file(std::size_t a) const {
        return options_.state_dir / (std::string(plan::names[a]) + ".bsc");
    }

    void restore_actor(std::size_t a) {
        if (options_.state_dir.empty()) return;
        auto const file = state_file(a);
        if (!std::filesystem::exists(file)) return;
        std::ifstream in(file, std::ios::binary);
        std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        auto const* bytes = reinterpret_cast<std::byte const*>(raw.data());
        // "bscN", the step, a CRC-32 of the step: bsc::save's own checksum covers the rest.
        bool const whole = raw.size() >= state_header && std::equal(raw.begin(), raw.begin() + 4, "bscN") &&
                           bsc::detail::read_le(bytes + 12, 4) == bsc::detail::crc32(bytes + 4, 8);
        auto const step = whole ? static_cast<std::int64_t>(bsc::detail::read_le(bytes + 4, 8)) : 0;
        if (!whole || step < -1 || step > max_step)
            throw std::runtime_error("bsc::net::node: " + file.string() + " is not a saved state of a node's actor");
        std::span<std::byte const> const saved{bytes + state_header, raw.size() - state_header};
        restore_result result{};
        for_actor(a, [&](auto A) { result = bsc::restore(system_.actors.*plan::template step_at<A>, saved); });
        if (result.error != restore_error::none)
            throw std::runtime_error("bsc::net::node: cannot resume " + std::string(plan::names[a]) + " from " +
                                     file.string() + ": " + to_string(result));
        peers_[a].completed = step;
        ++stats_.restored;
    }

    static constexpr std::size_t state_header = 16;

    void save_actor(std::size_t a) {
        if (options_.state_dir.empty()) return;
        std::vector<std::byte> bytes(state_header);
        bsc::detail::byte_writer w{bytes.data()};
        for (char c : {'b', 's', 'c', 'N'}) w.put(static_cast<unsigned char>(c), 1);
        w.put(static_cast<std::uint64_t>(peers_[a].completed), 8);
        w.put(bsc::detail::crc32(bytes.data() + 4, 8), 4);
        for_actor(a, [&](auto A) {
            auto const saved = bsc::save(system_.actors.*plan::template step_at<A>);
            bytes.insert(bytes.end(), saved.begin(), saved.end());
        });
        // Written aside, then renamed: a node killed while writing leaves the previous state whole.
        auto const file = state_file(a);
        auto const tmp = std::filesystem::path(file.string() + ".tmp");
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            out.write(reinterpret_cast<char const*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
            if (!out) throw std::runtime_error("bsc::net::node: cannot write " + tmp.string());
        }
        std::filesystem::rename(tmp, file);
    }

    // ---- receiving ------------------------------------------------------------------------------

    void receive(std::chrono::milliseconds wait) {
        net_.poll(wait, [&](message const& m) { apply(m); });
    }

    void apply(message const& m) {
        auto const h = wire::read_header(m.payload);
        if (!h) {
            ++stats_.refused;
            return;
        }
        auto const now = options_.clock();
        if (h->step < -1 || h->step > max_step) {
            ++stats_.refused;
            return;
        }
        if (h->what == wire::kind::will) {
            if (h->fingerprint != system_fingerprint()) {
                ++stats_.refused;
                return;
            }
            for (std::size_t i = wire::header_size; i < m.payload.size(); ++i) {
                auto const a = static_cast<std::size_t>(m.payload[i]);
                if (a < N && !local_[a]) peers_[a].will = true;
            }
            ++stats_.received;
            return;
        }
        if (h->what == wire::kind::progress) {
            auto const it = topic_actor_.find(m.topic);
            if (it == topic_actor_.end() || local_[it->second] || h->fingerprint != actor_fingerprints[it->second] ||
                m.payload.size() != wire::header_size) {
                ++stats_.refused;
                return;
            }
            heard(it->second, h->step, now);
            return;
        }
        auto const it = topic_links_.find(m.topic);
        if (it == topic_links_.end()) {
            ++stats_.refused;
            return;
        }
        bool fresh = false, refused = false;
        for (std::size_t const i : it->second) {
            for_link(i, [&](auto I) {
                if (h->fingerprint != link_fingerprint<I>()) {
                    refused = true;
                    return;
                }
                auto& s = std::get<I>(slots_);
                if (h->step <= s.step) return;
                if (!wire::decode_value(m.payload, s.value)) {
                    refused = true;
                    return;
                }
                s.step = h->step;
                fresh = true;
            });
        }
        if (refused) {
            ++stats_.refused;
            return;
        }
        if (!fresh) {
            ++stats_.old;
            heard(plan::from[it->second.front()], unknown, now);
            return;
        }
        heard(plan::from[it->second.front()], h->step, now);
    }

    void heard(std::size_t a, std::int64_t step, time_point now) {
        auto& p = peers_[a];
        p.heard = now;
        p.will = false;
        if (step > p.completed) {
            p.completed = step;
            ++stats_.received;
        } else if (step != unknown) {
            ++stats_.old;
        }
    }

    bool stale(std::size_t a, time_point now) const {
        return peers_[a].will || now - peers_[a].heard > options_.deadline;
    }

    // ---- stepping -------------------------------------------------------------------------------

    // Each hosted actor, in the system's order, steps at most once: the network is read again
    // before anyone goes further, whatever the staleness of the peers.
    std::size_t step_ready() {
        std::size_t taken = 0;
        paced_until_.reset();
        for (std::size_t a = 0; a < N; ++a) {
            if (!local_[a] || peers_[a].completed >= options_.last_step) continue;
            auto const now = options_.clock();
            rejoin(a, now);
            auto const n = peers_[a].completed + 1;
            bool stale_input = false;
            if (!ready(a, n, now, stale_input) || !paced(a, n, stale_input, now)) continue;
            run_step(a, n, now);
            ++taken;
        }
        return taken;
    }

    // The actors with a lossless link: they never jump.
    static constexpr std::array<bool, N> has_lossless = [] {
        std::array<bool, N> any{};
        for (std::size_t i = 0; i < L; ++i)
            if (plan::lossless[i]) any[plan::from[i]] = any[plan::to[i]] = true;
        return any;
    }();

    // An actor without lossless links that finds every peer it hears from on other nodes further
    // on (it was stale to them, or its node restarted) skips to the furthest step at which those
    // peers' values are all there, instead of replaying the ones it missed: its completed step
    // moves forward without stepping, as if it had held its outputs. Never past a remote peer that
    // is not there yet (that peer may be waiting for it); peers on its own node are in the same
    // situation and skip alike.
    void rejoin(std::size_t a, time_point now) {
        if (has_lossless[a]) return;
        std::int64_t reach = std::numeric_limits<std::int64_t>::max();
        bool remote = false;
        for (std::size_t i = 0; i < L; ++i) {
            std::size_t const other = plan::from[i] == a ? plan::to[i] : plan::to[i] == a ? plan::from[i] : a;
            if (other == a || local_[other] || stale(other, now)) continue;
            if (peers_[other].completed == unknown) return;
            remote = true;
            reach = std::min(reach, peers_[other].completed + (other > a ? 1 : 0));
        }
        reach = std::min(reach, options_.last_step);
        if (!remote || reach - 1 <= peers_[a].completed) return;
        peers_[a].completed = reach - 1;
        ++stats_.jumps;
        // Its outputs are held at the skipped steps: say so, or the peers would wait for them.
        save_actor(a);
        publish_actor(a);
    }

    // What a diagnostic says of the last step known of an actor or a value.
    static std::string known_step(std::int64_t step) {
        if (step == unknown) return "not heard from yet";
        if (step < 0) return "has completed no step";
        return "has " + std::to_string(step);
    }

    // Whether actor `a` can run step `n`; `stale_input` tells whether it would read a stale value,
    // and `why`, if given, what it waits for when it cannot.
    bool ready(std::size_t a, std::int64_t n, time_point now, bool& stale_input, std::string* why = nullptr) const {
        for (std::size_t i = 0; i < L; ++i) {
            auto const p = plan::from[i], c = plan::to[i];
            if (c == a && p != a) {  // an input: the publisher's step n if it comes first, else n - 1
                auto const needed = p < a ? n : n - 1;
                auto const has = local_[p] ? peers_[p].completed : slot_step(i);
                if (has < needed || (!local_[p] && !same_step_from(p, a, i))) {
                    if (local_[p] || plan::lossless[i] || !stale(p, now)) {
                        if (why)
                            *why = "the value of step " + std::to_string(needed) + " of " +
                                   std::string(plan::names[p]) + " (" + known_step(has) + ")";
                        return false;
                    }
                    stale_input = true;
                }
            }
            if (p == a && c != a) {  // an output: its reader has read the value about to change
                auto const needed = c > a ? n - 1 : n;
                if (peers_[c].completed < needed && (local_[c] || plan::lossless[i] || !stale(c, now))) {
                    if (why)
                        *why = std::string(plan::names[c]) +
                               (needed < 0 ? std::string(" to start") : " to complete step " + std::to_string(needed)) +
                               " (" + known_step(peers_[c].completed) + ")";
                    return false;
                }
            }
        }
        return true;
    }

    // The values from one publisher are read at one step: a reader does not mix a channel of step
    // 12 with another of step 11 (each travels in its own message).
    bool same_step_from(std::size_t p, std::size_t a, std::size_t i) const {
        auto const step = slot_step(i);
        for (std::size_t j = 0; j < L; ++j)
            if (plan::from[j] == p && plan::to[j] == a && slot_step(j) != step) return false;
        return true;
    }

    // The wall clock's say: at least `pace` between two steps of an actor, and, for a step that
    // reads a stale value, at least the pace or else the period: an actor that goes on without a
    // peer runs on its own clock, not as fast as the processor allows.
    bool paced(std::size_t a, std::int64_t n, bool stale_input, time_point now) {
        auto const gap = stale_input
                             ? (options_.pace.count() > 0
                                    ? std::chrono::duration_cast<std::chrono::steady_clock::duration>(options_.pace)
                                    : std::chrono::duration_cast<std::chrono::steady_clock::duration>(options_.period))
                             : std::chrono::duration_cast<std::chrono::steady_clock::duration>(options_.pace);
        (void)n;
        if (gap.count() == 0 || !last_step_at_[a]) return true;
        auto const due = *last_step_at_[a] + gap;
        if (now >= due) return true;
        paced_until_ = paced_until_ ? std::min(*paced_until_, due) : due;
        return false;
    }

    std::int64_t slot_step(std::size_t i) const {
        std::int64_t s = unknown;
        for_link(i, [&](auto I) { s = std::get<I>(slots_).step; });
        return s;
    }

    void run_step(std::size_t a, std::int64_t n, time_point now) {
        bool stale_input = false;
        for (std::size_t i = 0; i < L; ++i) {
            if (plan::to[i] != a) continue;
            for_link(i, [&](auto I) { stale_input = feed<I>(n, now) || stale_input; });
        }
        if (stale_input) ++stats_.stale_steps;
        stepped_stale_[a] = stale_input;
        for_actor(a, [&](auto A) { (system_.actors.*plan::template step_at<A>).step(n * options_.period); });
        peers_[a].completed = n;
        last_step_at_[a] = now;
        ++stats_.steps;
        save_actor(a);
        publish_actor(a);
        if (on_step) on_step(a, n);
    }

    // Writes link I's value into its consumer's input (converted by the link's bsc::convert, as
    // bsc::system does); true if the value is a stale one. The input is set through the
    // machine's const context, as the environment sets it.
    template <std::size_t I>
    bool feed(std::int64_t n, time_point now) {
        using link = std::tuple_element_t<I, links>;
        constexpr auto p = plan::from[I];
        constexpr auto c = plan::to[I];
        auto const& target = (system_.actors.*link::to_actor).context().*link::to_channel;
        if (local_[p]) {
            target.set(link::converted(((system_.actors.*link::from_actor).context().*link::from_channel).get()));
            return false;
        }
        auto const& s = std::get<I>(slots_);
        auto const needed = p < c ? n : n - 1;
        if (s.step >= needed && same_step_from(p, c, I)) {
            target.set(link::converted(s.value));
            return false;
        }
        (void)now;
        if constexpr (requires { link::when_stale::value; }) {
            // A fail-safe value is what the consumer reads: of the target's type, not converted.
            typename plan::template target_value_of<link> const safe = link::when_stale::value;
            target.set(safe);
        } else if (s.step != unknown) {
            target.set(link::converted(s.value));
        }
        return true;
    }

    // ---- publishing -----------------------------------------------------------------------------

    void publish_actor(std::size_t a) {
        auto& out = last_sent_[a];
        out.clear();
        for (std::size_t i = 0; i < L; ++i) {
            if (plan::from[i] != a || first_reader_[i] != i) continue;
            bool remote = false;
            for (std::size_t j = i; j < L; ++j) remote = remote || (first_reader_[j] == i && !local_[plan::to[j]]);
            if (!remote) continue;
            for_link(i, [&](auto I) {
                using link = std::tuple_element_t<I, links>;
                auto const& channel = (system_.actors.*link::from_actor).context().*link::from_channel;
                out.emplace_back(value_topic_[I],
                                 wire::encode_value(peers_[a].completed, link_fingerprint<I>(), channel.get()));
            });
        }
        bool remote_peer = false;
        for (std::size_t i = 0; i < L; ++i)
            remote_peer = remote_peer || (plan::from[i] == a && !local_[plan::to[i]]) ||
                          (plan::to[i] == a && !local_[plan::from[i]]);
        if (remote_peer)
            out.emplace_back(progress_topic_[a],
                             wire::encode(wire::kind::progress, peers_[a].completed, actor_fingerprints[a]));
        resend(a);
    }

    void resend(std::size_t a) {
        for (auto const& [topic, bytes] : last_sent_[a]) {
            net_.publish(topic, bytes);
            ++stats_.published;
        }
    }

    // ---- dispatch from a runtime index to a compile-time one --------------------------------------

    template <class F>
    static void for_actor(std::size_t a, F&& f) {
        // clang-format off
        [&]<std::size_t... A>(std::index_sequence<A...>) {
            ((a == A ? (f(std::integral_constant<std::size_t, A>{}), 0) : 0), ...);
        }(std::make_index_sequence<N>{});
        // clang-format on
    }
    template <class F>
    static void for_link(std::size_t i, F&& f) {
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((i == I ? (f(std::integral_constant<std::size_t, I>{}), 0) : 0), ...);
        }(std::make_index_sequence<L>{});
        // clang-format on
    }

    System& system_;
    transport& net_;
    node_options options_;
    node_stats stats_{};
    std::array<bool, N> local_{};
    std::array<peer, N> peers_{};
    std::array<std::string, N> progress_topic_{};
    std::array<std::string, L> value_topic_{};
    std::array<std::size_t, L> first_reader_{};
    std::unordered_map<std::string, std::vector<std::size_t>> topic_links_;
    std::unordered_map<std::string, std::size_t> topic_actor_;
    decltype(slots_of(static_cast<links*>(nullptr))) slots_{};
    std::array<std::vector<std::pair<std::string, std::vector<std::byte>>>, N> last_sent_{};
    time_point start_{};
    time_point last_heartbeat_{};
    std::array<std::optional<time_point>, N> last_step_at_{};
    std::array<bool, N> stepped_stale_{};
    std::optional<time_point> paced_until_;
    mutable std::optional<time_point> done_since_;
};

}  // namespace bsc::net
