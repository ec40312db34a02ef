#pragma once
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
