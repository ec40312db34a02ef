#pragma once
// bsc::net - a system deployed across nodes, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/net.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/net.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_NET_HPP
#define BSC_SINGLE_INCLUDE_BSC_NET_HPP
// Distributed systems (opt-in): a bsc::system's actors deployed on several nodes, linked over a
// publish/subscribe transport. This header has no dependency beyond the standard library; the
// MQTT transport is <bsc/mqtt.hpp> (CMake target bsc::mqtt, needs libmosquitto).

// begin include/bsc/net/memory_transport.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_NET_MEMORY_TRANSPORT_HPP
#define BSC_SINGLE_INCLUDE_BSC_NET_MEMORY_TRANSPORT_HPP
// A transport inside one process: every memory_transport on the same memory_bus receives what
// the others publish, at once and in order. For tests and for running the nodes of a system in
// one program; it can also lose its connection on demand, so that staleness can be tested
// without a network.

#include <algorithm>
#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

// begin include/bsc/net/transport.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_NET_TRANSPORT_HPP
#define BSC_SINGLE_INCLUDE_BSC_NET_TRANSPORT_HPP
// What a node of a distributed system (<bsc/net/node.hpp>) needs from a network: publish and
// subscribe by topic, and a last will. MQTT gives all of it (<bsc/net/mosquitto_transport.hpp>);
// memory_transport (<bsc/net/memory_transport.hpp>) gives it inside one process, for tests. Another
// transport (DDS, ZeroMQ) implements this class and nothing else changes.

#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bsc::net {

/// A message as a transport delivers it.
struct message {
    std::string topic;
    std::vector<std::byte> payload;
};

/// A publish/subscribe connection. Delivery is best effort: a message may be lost (a node sends
/// its latest messages again with every heartbeat), but the messages of one topic from one
/// publisher never overtake each other, and none arrives corrupted.
class transport {
public:
    virtual ~transport() = default;

    /// The message the network publishes for this client when the connection is lost without a
    /// goodbye (MQTT's last will). Set before the first poll; kept across reconnections.
    virtual void set_will(std::string_view topic, std::span<std::byte const> payload) = 0;
    /// Receive the messages whose topic matches `filter` (MQTT syntax: `+` one level, `#` the rest).
    virtual void subscribe(std::string_view filter) = 0;
    /// Sends a message; dropped while disconnected.
    virtual void publish(std::string_view topic, std::span<std::byte const> payload) = 0;
    /// Waits at most `timeout` for messages and hands each to `deliver`, in arrival order; keeps
    /// the connection (and reconnects after a loss). Returns the number of messages handed.
    virtual std::size_t poll(std::chrono::milliseconds timeout, std::function<void(message const&)> const& deliver) = 0;
    /// Whether the connection is up now.
    virtual bool connected() const = 0;
    /// What the transport connects to, for diagnostics, e.g. "the MQTT broker at 127.0.0.1:1883".
    virtual std::string peer() const { return "the network"; }
};

/// Hands every message of `inbox` to `deliver`, oldest first, and empties it; returns how many.
/// Takes each message out before delivering it: `deliver` may publish, and so add to an inbox.
inline std::size_t deliver_all(std::deque<message>& inbox, std::function<void(message const&)> const& deliver) {
    std::size_t n = 0;
    while (!inbox.empty()) {
        message m = std::move(inbox.front());
        inbox.pop_front();
        deliver(m);
        ++n;
    }
    return n;
}

/// Whether `topic` matches the MQTT topic filter `filter`.
constexpr bool topic_matches(std::string_view filter, std::string_view topic) {
    while (true) {
        auto const f_end = filter.find('/');
        auto const t_end = topic.find('/');
        auto const f_level = filter.substr(0, f_end);
        auto const t_level = topic.substr(0, t_end);
        if (f_level == "#") return true;
        if (f_level != "+" && f_level != t_level) return false;
        bool const f_last = f_end == std::string_view::npos;
        bool const t_last = t_end == std::string_view::npos;
        if (f_last || t_last) {
            if (f_last && t_last) return true;
            // "a/#" also matches "a".
            return t_last && filter.substr(f_end + 1) == "#";
        }
        filter.remove_prefix(f_end + 1);
        topic.remove_prefix(t_end + 1);
    }
}

}  // namespace bsc::net
#endif  // BSC_SINGLE_INCLUDE_BSC_NET_TRANSPORT_HPP
// end include/bsc/net/transport.hpp

namespace bsc::net {

class memory_transport;

/// The medium the memory transports of one system share. Outlives them.
class memory_bus {
    friend class memory_transport;
    std::vector<memory_transport*> clients_;
};

/// A transport on a memory_bus. Single-threaded: poll never blocks.
class memory_transport final : public transport {
public:
    explicit memory_transport(memory_bus& bus) : bus_(&bus) { bus_->clients_.push_back(this); }
    ~memory_transport() override { std::erase(bus_->clients_, this); }
    memory_transport(memory_transport const&) = delete;
    memory_transport& operator=(memory_transport const&) = delete;

    void set_will(std::string_view topic, std::span<std::byte const> payload) override {
        will_ = message{std::string(topic), {payload.begin(), payload.end()}};
    }
    void subscribe(std::string_view filter) override { filters_.emplace_back(filter); }
    void publish(std::string_view topic, std::span<std::byte const> payload) override {
        if (!connected_) return;
        broadcast(message{std::string(topic), {payload.begin(), payload.end()}});
    }
    std::size_t poll(std::chrono::milliseconds, std::function<void(message const&)> const& deliver) override {
        return connected_ ? deliver_all(inbox_, deliver) : 0;
    }
    bool connected() const override { return connected_; }
    std::string peer() const override { return "the memory bus"; }

    /// The connection breaks: what was not yet delivered is lost, the others receive the will.
    void disconnect() {
        if (!connected_) return;
        connected_ = false;
        inbox_.clear();
        if (will_) broadcast(*will_);
    }
    /// The node hangs, or its link holds everything: nothing goes out or comes in, and the
    /// others get no will; only their deadline tells them.
    void fall_silent() {
        connected_ = false;
        inbox_.clear();
    }
    /// The connection is back, with the same subscriptions and will.
    void reconnect() { connected_ = true; }

private:
    void broadcast(message const& m) {
        for (memory_transport* c : bus_->clients_) {
            if (c == this || !c->connected_) continue;
            if (std::any_of(c->filters_.begin(), c->filters_.end(),
                            [&](std::string const& f) { return topic_matches(f, m.topic); }))
                c->inbox_.push_back(m);
        }
    }

    memory_bus* bus_;
    std::vector<std::string> filters_;
    std::deque<message> inbox_;
    std::optional<message> will_;
    bool connected_ = true;
};

}  // namespace bsc::net
#endif  // BSC_SINGLE_INCLUDE_BSC_NET_MEMORY_TRANSPORT_HPP
// end include/bsc/net/memory_transport.hpp
// begin include/bsc/net/node.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_NET_NODE_HPP
#define BSC_SINGLE_INCLUDE_BSC_NET_NODE_HPP
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

// begin include/bsc/detail/system_plan.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
// What a program that runs or shows a bsc::system knows of it at compile time: the actors in
// their order, with their names; the links with their ends' places and channel names. Used by
// bsc::net::node and bsc::system_inspector.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>


namespace bsc::detail {

template <std::size_t I, auto... Members>
struct nth_member;
template <auto First, auto... Rest>
struct nth_member<0, First, Rest...> {
    static constexpr auto value = First;
};
template <std::size_t I, auto First, auto... Rest>
struct nth_member<I, First, Rest...> : nth_member<I - 1, Rest...> {};

template <class System>
struct system_plan {
    static_assert(sizeof(System) == 0, "System must be a bsc::system<Actors, bsc::order<...>, links...>");
};

template <class Actors, auto... Steps, class... Entries>
struct system_plan<system<Actors, order<Steps...>, Entries...>> {
    // The links only: a system's bsc::from_outside entries are the environment's business.
    using links = typename system<Actors, order<Steps...>, Entries...>::links_type;
    static constexpr std::size_t actor_count = sizeof...(Steps);
    static constexpr std::size_t link_count = std::tuple_size_v<links>;
    static constexpr std::array<std::string_view, actor_count> names{member_name<Steps>()...};

    template <auto Actor>
    static constexpr std::size_t place() {
        std::size_t i = 0, found = actor_count;
        ((same_member_pointer<Actor, Steps>() ? (found = i, ++i) : ++i), ...);
        return found;
    }
    template <std::size_t I>
    static constexpr auto step_at = nth_member<I, Steps...>::value;
    template <std::size_t I>
    using machine_at = std::remove_cvref_t<decltype(std::declval<Actors&>().*nth_member<I, Steps...>::value)>;

    // What link L carries over the network: the source's value, as its publisher published it
    // (the consumer's side applies the link's bsc::convert).
    template <class L>
    using value_of = channel_value<
        std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::from_actor).context()).*L::from_channel)>>;
    // What the consumer of link L reads: its input's value type.
    template <class L>
    using target_value_of =
        channel_value<std::remove_cvref_t<decltype(((std::declval<Actors&>().*L::to_actor).context()).*L::to_channel)>>;

    // (Every actor a link names is in the order: bsc::system checks it.)
    // clang-format off
    static constexpr std::array<std::size_t, link_count> from = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::from_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<std::size_t, link_count> to = []<class... L>(std::tuple<L...>*) {
        return std::array<std::size_t, link_count>{place<L::to_actor>()...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // clang-format off
    static constexpr std::array<bool, link_count> lossless = []<class... L>(std::tuple<L...>*) {
        return std::array<bool, link_count>{std::is_same_v<typename L::when_stale, bsc::lossless>...};
    }(static_cast<links*>(nullptr));
    // clang-format on
    // The name of a channel in its actor's context; empty where the context is not an aggregate
    // (one described by bsc::fields: its members' names are not known here).
    template <auto Channel>
    static constexpr std::string_view channel_name() {
        if constexpr (std::is_aggregate_v<decltype(class_of_member(Channel))>)
            return member_name<Channel>();
        else
            return {};
    }
    // The channels each link joins, by their names.
    static constexpr std::array<std::string_view, link_count> from_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::from_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
    static constexpr std::array<std::string_view, link_count> to_channels() {
        // clang-format off
        return []<class... L>(std::tuple<L...>*) {
            return std::array<std::string_view, link_count>{channel_name<L::to_channel>()...};
        }(static_cast<links*>(nullptr));
        // clang-format on
    }
};

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_SYSTEM_PLAN_HPP
// end include/bsc/detail/system_plan.hpp
// begin include/bsc/net/wire.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_NET_WIRE_HPP
#define BSC_SINGLE_INCLUDE_BSC_NET_WIRE_HPP
// The messages that the nodes of a distributed system exchange, byte by byte. Each starts with
// the same header:
//
//   offset  size     field
//        0  3 bytes  "bsc"
//        3  1 byte   kind: 'V' a channel's value, 'P' an actor's progress, 'W' a node's will
//        4  1 byte   format version (2: the fingerprints of version 1 described types otherwise)
//        5  8 bytes  the step the message is about (two's complement, little-endian)
//       13  8 bytes  fingerprint: of the publishing actor's chart, and for a value also of the
//                    channel's name and value type (detail/state_bytes.hpp's fingerprints)
//       21           body: a value as bsc::save writes it (fixed size per type); for a will, one
//                    byte per actor of the node (its place in the system's order)
//
// A message whose header, fingerprint or size does not match what the receiver expects is
// refused and counted, never applied: two nodes built from different charts do not talk.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

// begin include/bsc/detail/bytes.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
// Bytes that leave the program: little-endian numbers written and read at a position, the FNV-1a
// fingerprint of what they mean, and the CRC-32 that guards them. Shared by retentive state
// (bsc/retain.hpp) and the messages of bsc::net (net/wire.hpp).

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace bsc::detail {

// FNV-1a, 64 bits: fingerprints of a chart and a layout, computed at compile time.
struct fingerprint {
    std::uint64_t value = 14695981039346656037ull;
    constexpr void add(std::uint64_t v) {
        for (int i = 0; i < 8; ++i, v >>= 8) value = (value ^ (v & 0xffu)) * 1099511628211ull;
    }
    constexpr void add(std::string_view s) {
        add(s.size());
        for (char c : s) value = (value ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
};

// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), bit by bit: states are small.
constexpr std::uint32_t crc32(std::byte const* data, std::size_t n) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < n; ++i) {
        crc ^= static_cast<std::uint32_t>(data[i]);
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// A little-endian number of `bytes` (at most 8) bytes.
inline std::uint64_t read_le(std::byte const* p, std::size_t bytes) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

class byte_writer {
public:
    explicit byte_writer(std::byte* out) : out_(out) {}
    void put(std::uint64_t v, std::size_t bytes) {
        for (std::size_t i = 0; i < bytes; ++i, v >>= 8) out_[pos_++] = static_cast<std::byte>(v & 0xffu);
    }
    std::size_t position() const { return pos_; }

private:
    std::byte* out_;
    std::size_t pos_ = 0;
};

// Reads what byte_writer wrote, within [begin, end); the first value out of range (or past the
// end) is remembered with its position, and reading goes on with zeros.
class byte_reader {
public:
    enum class fault : std::uint8_t { none, truncated, invalid_value, machine_running };

    byte_reader(std::byte const* in, std::size_t begin, std::size_t end) : in_(in), pos_(begin), end_(end) {}
    std::uint64_t get(std::size_t bytes) {
        if (pos_ + bytes > end_) {
            refuse(fault::truncated, end_);
            return 0;
        }
        std::uint64_t const v = read_le(in_ + pos_, bytes);
        pos_ += bytes;
        return v;
    }
    // A value that must be below `limit`.
    std::uint64_t get_below(std::size_t bytes, std::uint64_t limit) {
        std::size_t const at = pos_;
        std::uint64_t const v = get(bytes);
        if (v >= limit) refuse(fault::invalid_value, at);
        return v < limit ? v : 0;
    }
    // Passes over what is left up to `to` (padding), or to the end.
    void skip_to(std::size_t to) {
        if (to > end_) refuse(fault::truncated, end_);
        if (to > pos_) pos_ = to < end_ ? to : end_;
    }
    void refuse(fault f, std::size_t at) {
        if (fault_ == fault::none) {
            fault_ = f;
            at_ = at;
        }
    }
    fault failure() const { return fault_; }
    std::size_t failed_at() const { return at_; }
    std::size_t position() const { return pos_; }

private:
    std::byte const* in_;
    std::size_t pos_;
    std::size_t end_;
    fault fault_ = fault::none;
    std::size_t at_ = 0;
};

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
// end include/bsc/detail/bytes.hpp
// begin include/bsc/detail/state_bytes.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
// A machine's state as bytes, and the values of its context: what bsc::save writes and
// bsc::restore reads (bsc/retain.hpp), and the values bsc::net sends (net/wire.hpp). Walked by
// the member layer (detail/members.hpp), so that every kind of member is encoded in one place:
//
//   a machine   one byte per composite, two in a chart with a composite of more than 255
//               children (its active or remembered child: the configuration and
//               the history), the clock (8), whether a cycle has run (1), each timeout's start
//               (8 each), the last outcome (1); for a chart that defers: whether the deferred
//               events wait for a retry (1), their number (2) and each of them (an event slot);
//               for a chart that sends delayed events: the queue's clock (8), the number pending
//               (2) and each of them in the order sent: due time (8), id (4), event slot; then
//               the context
//   an event    slot: the event's place among the chart's events plus one (0: none) in 1 byte
//               (2 above 255 events), then its members, padded to the largest event's size
//   a channel   its pending and its current value
//   a timer     limit, start, elapsed time (8 each), phase (1), expired (1)
//   a scalar    bool 1 byte; integers, enums, float, double, durations in their size
//   std::array, aggregate, bsc::fields type: the elements or members in order
// All numbers little-endian. Transient members (bsc::transient) take no bytes.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>


namespace bsc::detail {

inline constexpr std::size_t outcome_count = static_cast<std::size_t>(outcome::unknown_event) + 1;

template <class Machine>
using machine_model = chart_model<typename Machine::chart_type>;

// ---- what a member is to the bytes -----------------------------------------------------------------

// Whether a leaf has a fixed encoding (else the retentive state refuses it).
template <class T>
constexpr bool encodable_leaf() {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (is_transient<U>)
        return true;
    else if constexpr (std::is_const_v<T>)
        return false;  // cannot be restored
    else if constexpr (k == member_kind::enumeration)
        return has_fixed_underlying_type<U>;
    else if constexpr (k == member_kind::time)
        return kind_of<typename U::rep>() != member_kind::opaque;
    else if constexpr (k == member_kind::opaque)
        return std::is_empty_v<U>;  // a tag with constructors holds nothing
    else
        return k != member_kind::unwalkable;
}

// Whether every leaf of T has one, and none is a reference (what lies behind one is not the
// machine's); no error is reported (the pending events' check names the event).
struct encodable_folder {
    using result = bool;
    template <class T>
    constexpr bool leaf() const {
        if constexpr (kind_of<std::remove_cv_t<T>>() == member_kind::channel)
            return encodable_leaf<T>() && fold_type<encodable_folder, channel_value<std::remove_cv_t<T>>>(*this);
        else
            return encodable_leaf<T>();
    }
    template <class T>
    constexpr bool array(bool element) const {
        return element;
    }
    template <class T, std::size_t N>
    constexpr bool record(std::array<bool, N> const& members) const {
        if constexpr (!described_by_fields<T>)
            if (has_reference_field<T>) return false;
        return std::all_of(members.begin(), members.end(), [](bool b) { return b; });
    }
};
template <class T>
inline constexpr bool encodable = fold_type<encodable_folder, T>(encodable_folder{});

template <class Machine>
constexpr std::size_t machine_size();

// The bytes of a value of T; a member that has none is reported (member_not_retainable).
struct size_folder : summing_fold<size_folder> {
    template <class T, member_kind k>
    constexpr std::size_t share() const {
        using U = std::remove_cv_t<T>;
        if constexpr (!encodable_leaf<T>()) {
            detail::report<error::member_not_retainable<T>>();
            return 0;
        } else if constexpr (k == member_kind::machine) {
            return machine_size<U>();
        } else if constexpr (k == member_kind::channel) {
            return 2 * fold<size_folder, channel_value<U>>(*this);
        } else if constexpr (k == member_kind::timer) {
            return 3 * 8 + 2;
        } else if constexpr (k == member_kind::boolean) {
            return 1;
        } else if constexpr (k == member_kind::time) {
            return sizeof(typename U::rep);
        } else if constexpr (k == member_kind::opaque) {
            return 0;  // empty (encodable_leaf)
        } else {
            return sizeof(U);
        }
    }
    template <class T, std::size_t N>
    constexpr std::size_t record(std::array<std::size_t, N> const& members) const {
        if constexpr (!described_by_fields<T>)
            if constexpr (has_reference_field<T>) detail::report<error::member_not_retainable<T>>();
        return summing_fold<size_folder>::record<T>(members);
    }
};
template <class T>
constexpr std::size_t size_of() {
    return fold<size_folder, T>(size_folder{});
}

// ---- the pending events of a machine -----------------------------------------------------------------

// The events that can wait in a machine between calls: every event of the chart but
// bsc::action_failed (which carries an exception, and which no row defers or delays).
// Whether an event that waits in a machine is encoded with its members (retain's bytes, the
// explorer's bits): bsc::action_failed never waits; an event that cannot be encoded is reported
// (pending_events_encodable), and takes no room.
template <class E>
inline constexpr bool encoded_while_pending = !std::is_same_v<E, action_failed> && encodable<E> &&
                                              std::is_default_constructible_v<E>;

template <class Chart, class E>
constexpr bool pending_event_encodable() {
    if constexpr (std::is_same_v<E, action_failed> || encoded_while_pending<E>)
        return true;
    else
        return detail::report<error::pending_events_not_encoded<Chart, E>>();
}
template <class Chart, class... Es>
constexpr bool pending_events_encodable(type_list<Es...>) {
    return ((pending_event_encodable<Chart, Es>() ? 0 : 1) + ... + 0) == 0;
}

template <class Events>
struct event_slot;
template <class... Es>
struct event_slot<type_list<Es...>> {
    static constexpr std::size_t index_bytes = sizeof...(Es) + 1 <= 256 ? 1 : 2;
    template <class E>
    static constexpr std::size_t payload_of() {
        if constexpr (encoded_while_pending<E>)
            return size_of<E>();
        else
            return 0;
    }
    static constexpr std::size_t payload = std::max({std::size_t{0}, payload_of<Es>()...});
    static constexpr std::size_t size = index_bytes + payload;
};

template <class Machine>
struct pending_layout {
    using model = machine_model<Machine>;
    using slot = event_slot<typename model::events>;
    static constexpr bool defers = model::has_deferral;
    static constexpr bool delays = chart_sends_delayed<model>();
    static constexpr bool check() {
        if constexpr (defers || delays)
            return pending_events_encodable<typename Machine::chart_type>(typename model::events{});
        else
            return true;
    }
    static constexpr bool checked = check();
    static constexpr std::size_t deferred_capacity = [] {
        if constexpr (defers)
            return std::remove_cvref_t<decltype(access::deferred(std::declval<Machine&>()))>::capacity();
        else
            return std::size_t{0};
    }();
    static constexpr std::size_t delayed_capacity = [] {
        if constexpr (delays)
            return std::remove_cvref_t<decltype(access::queue(std::declval<Machine&>()))>::slot_count();
        else
            return std::size_t{0};
    }();
    static constexpr std::size_t size = [] {
        if constexpr (defers || delays)
            return (defers ? 1 + 2 + deferred_capacity * slot::size : 0) +
                   (delays ? 8 + 2 + delayed_capacity * (8 + 4 + slot::size) : 0);
        else
            return std::size_t{0};
    }();
};

template <class Machine>
constexpr std::size_t machine_size() {
    using layout = chart_layout<machine_model<Machine>>;
    static_assert(pending_layout<Machine>::checked || true);
    return static_cast<std::size_t>(machine_model<Machine>::tree.slots) *
               sizeof(typename machine_model<Machine>::ordinal_type) +
           8 + 1 + 8 * static_cast<std::size_t>(layout::timeout_slots) + 1 + pending_layout<Machine>::size +
           size_of<typename Machine::context_type>();
}

// ---- fingerprints --------------------------------------------------------------------------------

// What the saved bytes of a machine mean: its states and where its timeouts are.
template <class Machine>
constexpr std::uint64_t chart_fingerprint() {
    using model = machine_model<Machine>;
    using layout = chart_layout<model>;
    constexpr auto const& names = state_names_of<model>;
    fingerprint f;
    f.add(static_cast<std::uint64_t>(model::N));
    for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s) {
        f.add(names[s]);
        f.add(static_cast<std::uint64_t>(model::tree.kinds[s]));
        f.add(static_cast<std::uint64_t>(model::tree.hist[s]));
        f.add(static_cast<std::uint64_t>(model::tree.parent[s] + 1));
    }
    f.add(static_cast<std::uint64_t>(layout::timeout_slots));
    if constexpr (layout::timeout_slots > 0)
        for (int s : layout::timeout_slot_state) f.add(static_cast<std::uint64_t>(s));
    return f.value;
}

// The same, with each timeout row's place among the rows, its target and its delay (a value of
// the chart, not of its type): a timeout row added, removed, moved or given another delay changes
// the meaning of the start times the bytes hold.
template <class Machine>
std::uint64_t chart_fingerprint(Machine const& m) {
    using model = machine_model<Machine>;
    using layout = chart_layout<model>;
    fingerprint f{chart_fingerprint<Machine>()};
    auto const delays = access::row_delays(m);
    for (std::size_t row = 0; row < delays.size(); ++row) {
        if (!layout::is_timeout_row(static_cast<int>(row))) continue;
        f.add(row);
        f.add(static_cast<std::uint64_t>(model::rows.target[row] + 2));
        f.add(static_cast<std::uint64_t>(delays[row].count()));
    }
    return f.value;
}

template <class Machine>
constexpr std::uint64_t layout_fingerprint();

// A type's description: its kind, size and, for composites, their parts (members by name).
struct describe_folder {
    using result = std::uint64_t;
    template <class T>
    constexpr std::uint64_t leaf() const {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        fingerprint f;
        if constexpr (is_transient<U>) {
            f.add("transient");
        } else {
            f.add(static_cast<std::uint64_t>(k));
            if constexpr (k == member_kind::machine) {
                f.add(chart_fingerprint<U>());
                f.add(layout_fingerprint<U>());
            } else if constexpr (k == member_kind::channel) {
                using V = channel_value<U>;
                f.add(std::is_same_v<U, input<V>> ? 1u : std::is_same_v<U, output<V>> ? 2u : 3u);
                f.add(fold<describe_folder, V>(*this));
            } else if constexpr (k == member_kind::enumeration) {
                f.add(name_of<U>);
                f.add(sizeof(U));
                f.add(std::is_signed_v<std::underlying_type_t<U>> ? 1 : 0);
            } else if constexpr (k == member_kind::time) {
                f.add(static_cast<std::uint64_t>(U::period::num));
                f.add(static_cast<std::uint64_t>(U::period::den));
                f.add(fold<describe_folder, typename U::rep>(*this));
            } else if constexpr (k != member_kind::timer) {
                f.add(sizeof(U));
            }
        }
        return f.value;
    }
    template <class T>
    constexpr std::uint64_t array(std::uint64_t element) const {
        fingerprint f;
        f.add(static_cast<std::uint64_t>(member_kind::array));
        f.add(std::tuple_size_v<T>);
        f.add(element);
        return f.value;
    }
    template <class T, std::size_t N>
    constexpr std::uint64_t record(std::array<std::uint64_t, N> const& members) const {
        fingerprint f;
        f.add(static_cast<std::uint64_t>(member_kind::record));
        f.add(N);
        for (std::size_t i = 0; i < N; ++i) {
            // (A struct with a reference member is refused by size_of: its names are not constants.)
            if constexpr (described_by_fields<T> || !has_reference_field<T>) f.add(names_of<T>()[i]);
            f.add(members[i]);
        }
        return f.value;
    }
};

template <class T>
constexpr std::uint64_t describe() {
    return fold<describe_folder, T>(describe_folder{});
}

template <class Machine>
constexpr std::uint64_t layout_fingerprint() {
    fingerprint f;
    f.add(describe<typename Machine::context_type>());
    using pending = pending_layout<Machine>;
    if constexpr (pending::defers || pending::delays) {
        f.add(pending::deferred_capacity);
        f.add(pending::delayed_capacity);
        // clang-format off
        [&]<class... Es>(type_list<Es...>) {
            // (In order, as a list: a chart may have more events than a fold takes, detail::max_fold.)
            [[maybe_unused]] int const added[] = {
                (f.add(name_of<Es>), f.add(std::is_same_v<Es, action_failed> ? 0 : describe<Es>()), 0)..., 0};
        }(typename machine_model<Machine>::events{});
        // clang-format on
    }
    return f.value;
}

// ---- writing -----------------------------------------------------------------------------------------

template <class Machine>
void put_machine(byte_writer& w, Machine const& m);

struct put_visitor {
    byte_writer& w;
    template <class T>
    void leaf(T const& value, no_name) {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        if constexpr (k == member_kind::machine) {
            put_machine(w, value);
        } else if constexpr (k == member_kind::channel) {
            walk(value.pending(), *this);
            walk(value.get(), *this);
        } else if constexpr (k == member_kind::timer) {
            w.put(static_cast<std::uint64_t>(value.limit().count()), 8);
            w.put(static_cast<std::uint64_t>(access::timer_started(value).count()), 8);
            w.put(static_cast<std::uint64_t>(value.elapsed().count()), 8);
            w.put(access::timer_phase(value), 1);
            w.put(value.expired() ? 1 : 0, 1);
        } else if constexpr (k == member_kind::boolean) {
            w.put(value ? 1 : 0, 1);
        } else if constexpr (k == member_kind::enumeration) {
            using R = std::underlying_type_t<U>;
            w.put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<R>>(static_cast<R>(value))), sizeof(U));
        } else if constexpr (k == member_kind::signed_integer || k == member_kind::unsigned_integer) {
            w.put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<U>>(value)), sizeof(U));
        } else if constexpr (std::is_same_v<U, float>) {
            w.put(std::bit_cast<std::uint32_t>(value), 4);
        } else if constexpr (std::is_same_v<U, double>) {
            w.put(std::bit_cast<std::uint64_t>(value), 8);
        } else if constexpr (k == member_kind::time) {
            leaf(value.count(), no_name{});
        }
        // (opaque and unwalkable members are refused by size_of before anything is written)
    }
};

template <class T>
void put(byte_writer& w, T const& value) {
    put_visitor v{w};
    walk(value, v);
}

// An event slot: the event's place plus one, its members, zeros up to the slot's size.
template <class Events, class Item>
void put_event(byte_writer& w, Item const& item) {
    using slot = event_slot<Events>;
    std::size_t const end = w.position() + slot::size;
    w.put(item.index(), slot::index_bytes);
    std::visit(
        [&]<class E>(E const& e) {
            if constexpr (!std::is_same_v<E, std::monostate> && !std::is_same_v<E, action_failed>) put(w, e);
        },
        item);
    while (w.position() < end) w.put(0, 1);
}

template <class Machine>
void put_pending(byte_writer& w, Machine const& m) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    auto& machine = const_cast<Machine&>(m);  // access reads through non-const references too
    if constexpr (pending::defers) {
        auto const& deferred = access::deferred(machine);
        w.put(access::deferral_pending_retry(m) && deferred.size() > 0 ? 1 : 0, 1);
        w.put(deferred.size(), 2);
        deferred.for_each_held([&](auto const& item) { put_event<events>(w, item); });
        for (std::size_t i = deferred.size(); i < pending::deferred_capacity; ++i)
            for (std::size_t b = 0; b < pending::slot::size; ++b) w.put(0, 1);
    }
    if constexpr (pending::delays) {
        auto const& queue = access::queue(machine);
        w.put(static_cast<std::uint64_t>(queue.clock().count()), 8);
        std::size_t const count = queue.scheduled();
        w.put(count, 2);
        queue.for_each_scheduled([&](duration due, int id, auto const& item) {
            w.put(static_cast<std::uint64_t>(due.count()), 8);
            w.put(static_cast<std::uint32_t>(id), 4);
            put_event<events>(w, item);
        });
        for (std::size_t i = count; i < pending::delayed_capacity; ++i)
            for (std::size_t b = 0; b < 8 + 4 + pending::slot::size; ++b) w.put(0, 1);
    }
}

template <class Machine>
void put_machine(byte_writer& w, Machine const& m) {
    auto& machine = const_cast<Machine&>(m);  // access reads through non-const references too
    for (auto ordinal : access::configuration(machine).active) w.put(ordinal, sizeof(ordinal));
    w.put(static_cast<std::uint64_t>(access::clock(m).count()), 8);
    w.put(access::clock_started(m) ? 1 : 0, 1);
    for (duration armed : access::armed(machine)) w.put(static_cast<std::uint64_t>(armed.count()), 8);
    w.put(static_cast<std::uint64_t>(access::last_outcome(m)), 1);
    put_pending(w, m);
    put(w, m.context());
}

// ---- reading -------------------------------------------------------------------------------------------

// What a reading pass does with the values: only check them, or also store them, each machine's
// clock continuing at `resume` if given.
struct pass {
    bool apply = false;
    std::optional<duration> resume{};
    duration shift{};  // added to every time the enclosing machine keeps
};

template <class Machine>
void get_machine(byte_reader& r, Machine& m, pass const& p);

struct get_visitor {
    byte_reader& r;
    pass const& p;
    template <class T>
    void leaf(T& target, no_name) {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        if constexpr (k == member_kind::machine) {
            get_machine(r, target, p);
        } else if constexpr (k == member_kind::channel) {
            using V = channel_value<U>;
            // Read into copies, then store both at once.
            V pending = target.pending();
            V current = target.get();
            pass const into_copies{true, p.resume, p.shift};
            get_visitor copies{r, into_copies};
            walk(pending, copies);
            walk(current, copies);
            if (!p.apply) return;
            access::set_channel(target, current, pending);
        } else if constexpr (k == member_kind::timer) {
            std::size_t const at = r.position();
            auto const limit = duration{static_cast<duration::rep>(r.get(8))};
            auto const started = duration{static_cast<duration::rep>(r.get(8))};
            auto const elapsed = duration{static_cast<duration::rep>(r.get(8))};
            auto const phase = static_cast<std::uint8_t>(r.get_below(1, 3));
            bool const expired = r.get_below(1, 2) != 0;
            // Only what a timer can come to: a limit and an elapsed time not below zero, the flag
            // only while timing (phase 2), no elapsed time while idle or pending.
            constexpr std::uint8_t timing = 2;
            if (limit < duration::zero() || elapsed < duration::zero() || (expired && phase != timing) ||
                (phase != timing && elapsed != duration::zero()))
                r.refuse(byte_reader::fault::invalid_value, at);
            if (!p.apply) return;
            access::set_timer_limit(target, limit);
            access::set_timer(target, phase, expired, shifted(started, p.shift), elapsed);
        } else if constexpr (k == member_kind::boolean) {
            bool const v = r.get_below(1, 2) != 0;
            if (p.apply) target = v;
        } else if constexpr (k == member_kind::enumeration) {
            using R = std::underlying_type_t<U>;
            auto const v = static_cast<R>(static_cast<std::make_unsigned_t<R>>(r.get(sizeof(U))));
            if (p.apply) target = static_cast<U>(v);
        } else if constexpr (k == member_kind::signed_integer || k == member_kind::unsigned_integer) {
            // Unsigned to signed is modular (C++20): every saved value comes back exactly.
            auto const v = static_cast<U>(static_cast<std::make_unsigned_t<U>>(r.get(sizeof(U))));
            if (p.apply) target = v;
        } else if constexpr (std::is_same_v<U, float>) {
            auto const v = std::bit_cast<float>(static_cast<std::uint32_t>(r.get(4)));
            if (p.apply) target = v;
        } else if constexpr (std::is_same_v<U, double>) {
            auto const v = std::bit_cast<double>(r.get(8));
            if (p.apply) target = v;
        } else if constexpr (k == member_kind::time) {
            typename U::rep v{};
            pass const into_copy{true, {}, {}};
            get_visitor copy{r, into_copy};
            copy.leaf(v, no_name{});
            if (p.apply) target = U{v};
        }
    }
};

template <class T>
void get(byte_reader& r, T& target, pass const& p) {
    get_visitor v{r, p};
    walk(target, v);
}

// Reads an event slot; the event, or std::monostate for an empty slot. A place past the chart's
// events, or one of an event that never waits (bsc::action_failed), is refused.
template <class Events, class Item>
Item get_event(byte_reader& r) {
    using slot = event_slot<Events>;
    std::size_t const end = r.position() + slot::size;
    std::size_t const at = r.position();
    auto const index = static_cast<std::size_t>(r.get_below(slot::index_bytes, std::variant_size_v<Item>));
    Item item{};
    visit_index<static_cast<int>(std::variant_size_v<Item>)>(static_cast<int>(index), [&](auto i) {
        using E = std::variant_alternative_t<decltype(i)::value, Item>;
        if constexpr (std::is_same_v<E, action_failed>) {
            r.refuse(byte_reader::fault::invalid_value, at);
        } else if constexpr (!std::is_same_v<E, std::monostate>) {
            if constexpr (std::is_default_constructible_v<E>) {
                E e{};
                get(r, e, pass{true, {}, {}});
                item.template emplace<decltype(i)::value>(e);
            } else {
                r.refuse(byte_reader::fault::invalid_value, at);
            }
        }
    });
    r.skip_to(end);
    return item;
}

template <class Machine>
void get_pending(byte_reader& r, Machine& m, pass const& p, duration shift) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    if constexpr (pending::defers) {
        auto& deferred = access::deferred(m);
        using item_type = typename std::remove_cvref_t<decltype(deferred)>::value_type;
        bool const retry = r.get_below(1, 2) != 0;
        std::size_t const at = r.position();
        auto const count = static_cast<std::size_t>(r.get_below(2, pending::deferred_capacity + 1));
        std::array<item_type, pending::deferred_capacity> items{};
        for (std::size_t i = 0; i < pending::deferred_capacity; ++i) {
            items[i] = get_event<events, item_type>(r);
            if ((i < count) == (items[i].index() == 0)) r.refuse(byte_reader::fault::invalid_value, at);
        }
        if (p.apply) {
            deferred.clear();
            deferred.clear_overflow();
            for (std::size_t i = 0; i < count; ++i) (void)deferred.push_item(items[i]);
            access::set_deferral_pending_retry(m, retry);
        }
    }
    if constexpr (pending::delays) {
        auto& queue = access::queue(m);
        using item_type = typename std::remove_cvref_t<decltype(queue)>::value_type;
        auto const clock = duration{static_cast<duration::rep>(r.get(8))};
        std::size_t const at = r.position();
        auto const count = static_cast<std::size_t>(r.get_below(2, pending::delayed_capacity + 1));
        struct scheduled {
            duration due;
            int id;
            item_type item;
        };
        std::array<scheduled, pending::delayed_capacity> items{};
        for (std::size_t i = 0; i < pending::delayed_capacity; ++i) {
            items[i].due = duration{static_cast<duration::rep>(r.get(8))};
            items[i].id = static_cast<int>(static_cast<std::uint32_t>(r.get(4)));
            items[i].item = get_event<events, item_type>(r);
            if ((i < count) == (items[i].item.index() == 0)) r.refuse(byte_reader::fault::invalid_value, at);
        }
        if (p.apply) {
            queue.clear_scheduled();
            queue.set_clock(shifted(clock, shift));
            // (Moved past duration::max() by resume_at, an event never comes due: not kept, as
            // detail/runtime/delayed_events.hpp keeps none such.)
            for (std::size_t i = 0; i < count; ++i)
                if (!shifted_past_max(items[i].due, shift))
                    (void)queue.put_scheduled(shifted(items[i].due, shift), items[i].id, items[i].item);
        }
    }
}

template <class Machine>
void get_machine(byte_reader& r, Machine& m, pass const& p) {
    using model = machine_model<Machine>;
    constexpr auto& tree = model::tree;
    // The children of the composite that owns each configuration byte.
    constexpr auto children_by_slot = [] {
        std::array<int, static_cast<std::size_t>(tree.slots)> children{};
        for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s)
            if (tree.slot[s] >= 0) children[static_cast<std::size_t>(tree.slot[s])] = tree.child_count[s];
        return children;
    }();
    if (access::running(m)) r.refuse(byte_reader::fault::machine_running, r.position());  // one held in the context
    auto config = access::configuration(m);
    for (std::size_t k = 0; k < children_by_slot.size(); ++k)
        config.active[k] = static_cast<typename decltype(config)::ordinal_type>(
            r.get_below(sizeof(config.active[k]), static_cast<std::uint64_t>(children_by_slot[k])));
    auto const clock = duration{static_cast<duration::rep>(r.get(8))};
    bool const started = r.get_below(1, 2) != 0;
    auto armed = access::armed(m);
    for (auto& a : armed) a = duration{static_cast<duration::rep>(r.get(8))};
    auto const last = static_cast<outcome>(r.get_below(1, outcome_count));
    // resume_at: this machine's clock continues at the given time, and what it keeps moves with
    // it. A machine whose clock has not started keeps no time of the caller's: nothing moves.
    pass const own{p.apply, p.resume, started && p.resume ? difference(*p.resume, clock) : duration{}};
    get_pending(r, m, p, own.shift);
    get(r, access::context(m), own);
    if (!p.apply) return;
    access::configuration(m) = config;
    access::set_clock(m, shifted(clock, own.shift), started);
    for (std::size_t i = 0; i < armed.size(); ++i) access::armed(m)[i] = shifted(armed[i], own.shift);
    access::set_last_outcome(m, last);
    access::forget_failure(m);  // the exception of a last outcome `failed` is not saved
    access::queue(m).clear();   // raised events: none between runs
    access::queue(m).clear_overflow();
}

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
// end include/bsc/detail/state_bytes.hpp

namespace bsc::net::wire {

inline constexpr std::uint8_t format_version = 2;
inline constexpr std::size_t header_size = 21;

enum class kind : std::uint8_t { value = 'V', progress = 'P', will = 'W' };

struct header {
    kind what{};
    std::int64_t step = 0;
    std::uint64_t fingerprint = 0;
};

inline void put_header(detail::byte_writer& w, kind what, std::int64_t step, std::uint64_t fingerprint) {
    w.put('b', 1);
    w.put('s', 1);
    w.put('c', 1);
    w.put(static_cast<std::uint8_t>(what), 1);
    w.put(format_version, 1);
    w.put(static_cast<std::uint64_t>(step), 8);
    w.put(fingerprint, 8);
}

/// The header of `bytes`, if they start with one of this format's version.
inline std::optional<header> read_header(std::span<std::byte const> bytes) {
    if (bytes.size() < header_size) return std::nullopt;
    auto const* p = bytes.data();
    if (p[0] != std::byte{'b'} || p[1] != std::byte{'s'} || p[2] != std::byte{'c'}) return std::nullopt;
    auto const what = static_cast<kind>(p[3]);
    if (what != kind::value && what != kind::progress && what != kind::will) return std::nullopt;
    if (static_cast<std::uint8_t>(p[4]) != format_version) return std::nullopt;
    return header{what, static_cast<std::int64_t>(detail::read_le(p + 5, 8)), detail::read_le(p + 13, 8)};
}

/// The fingerprint of actor `Machine`'s output channel `Channel`: its chart, its name, its value's type.
template <class Machine, auto Channel>
constexpr std::uint64_t value_fingerprint() {
    using channel = std::remove_cvref_t<decltype(std::declval<typename Machine::context_type&>().*Channel)>;
    detail::fingerprint f{detail::chart_fingerprint<Machine>()};
    f.add(detail::member_name<Channel>());
    f.add(detail::describe<detail::channel_value<channel>>());
    return f.value;
}

/// A progress message (an actor completed `step`), or a will (`actors` are the node's).
inline std::vector<std::byte> encode(kind what, std::int64_t step, std::uint64_t fingerprint,
                                     std::span<std::uint8_t const> actors = {}) {
    std::vector<std::byte> out(header_size + actors.size());
    detail::byte_writer w{out.data()};
    put_header(w, what, step, fingerprint);
    for (auto a : actors) w.put(a, 1);
    return out;
}

/// A value message.
template <class T>
std::vector<std::byte> encode_value(std::int64_t step, std::uint64_t fingerprint, T const& value) {
    std::vector<std::byte> out(header_size + detail::size_of<T>());
    detail::byte_writer w{out.data()};
    put_header(w, kind::value, step, fingerprint);
    detail::put(w, value);
    return out;
}

/// Reads a value message's body into `out`; false (and `out` unchanged) if its size or any of
/// its values is wrong.
template <class T>
bool decode_value(std::span<std::byte const> bytes, T& out) {
    if (bytes.size() != header_size + detail::size_of<T>()) return false;
    detail::byte_reader check{bytes.data(), header_size, bytes.size()};
    T value = out;
    detail::get(check, value, detail::pass{true, std::nullopt, {}});
    if (check.failure() != detail::byte_reader::fault::none) return false;
    out = value;
    return true;
}

}  // namespace bsc::net::wire
#endif  // BSC_SINGLE_INCLUDE_BSC_NET_WIRE_HPP
// end include/bsc/net/wire.hpp
#include "retain.hpp"

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
#endif  // BSC_SINGLE_INCLUDE_BSC_NET_NODE_HPP
// end include/bsc/net/node.hpp
#endif  // BSC_SINGLE_INCLUDE_BSC_NET_HPP
// end include/bsc/net.hpp
