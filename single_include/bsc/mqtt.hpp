#pragma once
// bsc::net over MQTT, single-header distribution (needs bsc.hpp beside it, and libmosquitto).
// Generated from include/bsc/mqtt.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/mqtt.hpp
// Distributed systems over MQTT: <bsc/net.hpp> and bsc::net::mosquitto_transport. Link with the
// CMake target bsc::mqtt (Eclipse Mosquitto's client library, Debian package libmosquitto-dev).

#include "net.hpp"
// begin include/bsc/net/mosquitto_transport.hpp
// The MQTT transport of a distributed system, through Eclipse Mosquitto's client library
// (Debian: libmosquitto-dev; CMake target bsc::mqtt). The only part of bsc with a dependency:
// the rest of <bsc/net/...> and the whole core compile without it.
//
// Single-threaded: poll runs the client's network loop, reconnects after a loss (every
// `retry`), and subscribes again on every connection. Messages go at QoS 0 with TCP_NODELAY:
// the node repairs losses itself (heartbeats), and a lock-stepped system lives on latency.

#include <mosquitto.h>

#include <chrono>
#include <cstddef>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>


namespace bsc::net {

/// Where a mosquitto_transport connects.
struct mqtt_endpoint {
    std::string host = "127.0.0.1";
    int port = 1883;
    std::string client_id;                 ///< unique per node; the node's name will do
    int keepalive_seconds = 5;             ///< the broker publishes the will after 1.5 times this without traffic
    std::chrono::milliseconds retry{100};  ///< pause between connection attempts
};

/// A transport over an MQTT broker.
class mosquitto_transport final : public transport {
public:
    explicit mosquitto_transport(mqtt_endpoint endpoint) : endpoint_(std::move(endpoint)) {
        static int const initialised = mosquitto_lib_init();
        (void)initialised;
        client_ = mosquitto_new(endpoint_.client_id.empty() ? nullptr : endpoint_.client_id.c_str(), true, this);
        if (client_ == nullptr) throw std::runtime_error("bsc::net::mosquitto_transport: cannot create a client");
        mosquitto_int_option(client_, MOSQ_OPT_TCP_NODELAY, 1);
        mosquitto_connect_callback_set(
            client_, [](mosquitto*, void* self, int rc) { static_cast<mosquitto_transport*>(self)->on_connect(rc); });
        mosquitto_disconnect_callback_set(
            client_, [](mosquitto*, void* self, int) { static_cast<mosquitto_transport*>(self)->connected_ = false; });
        mosquitto_message_callback_set(client_, [](mosquitto*, void* self, mosquitto_message const* m) {
            // No exception may cross the C library's frames: a message that cannot be stored is lost,
            // as the network may lose one, and the heartbeat sends it again.
            try {
                auto const* bytes = static_cast<std::byte const*>(m->payload);
                static_cast<mosquitto_transport*>(self)->inbox_.push_back(
                    message{m->topic, std::vector<std::byte>(bytes, bytes + m->payloadlen)});
            } catch (...) {
            }
        });
    }
    ~mosquitto_transport() override {
        if (connected_) {
            // What is still queued goes out before the goodbye (at most 200 ms).
            auto const until = std::chrono::steady_clock::now() + std::chrono::milliseconds{200};
            while (mosquitto_want_write(client_) && std::chrono::steady_clock::now() < until)
                if (mosquitto_loop_write(client_, 1) != MOSQ_ERR_SUCCESS) break;
            mosquitto_disconnect(client_);
            mosquitto_loop_write(client_, 1);
        }
        mosquitto_destroy(client_);
    }
    mosquitto_transport(mosquitto_transport const&) = delete;
    mosquitto_transport& operator=(mosquitto_transport const&) = delete;

    void set_will(std::string_view topic, std::span<std::byte const> payload) override {
        std::string const t(topic);
        mosquitto_will_set(client_, t.c_str(), static_cast<int>(payload.size()), payload.data(), 0, false);
    }
    void subscribe(std::string_view filter) override {
        filters_.emplace_back(filter);
        if (connected_) mosquitto_subscribe(client_, nullptr, filters_.back().c_str(), 0);
    }
    void publish(std::string_view topic, std::span<std::byte const> payload) override {
        if (!socket_open_) return;  // libmosquitto answers MOSQ_ERR_NO_CONN itself until the connection is up
        std::string const t(topic);
        int const rc = mosquitto_publish(client_, nullptr, t.c_str(), static_cast<int>(payload.size()), payload.data(),
                                         0, false);
        // Before CONNACK the library refuses too: that is no loss of a connection.
        if ((rc == MOSQ_ERR_NO_CONN || rc == MOSQ_ERR_CONN_LOST) && connected_) drop_connection();
    }
    std::size_t poll(std::chrono::milliseconds timeout, std::function<void(message const&)> const& deliver) override {
        auto const until = std::chrono::steady_clock::now() + timeout;
        do {
            if (!socket_open_ && !try_connect()) {
                auto const left = until - std::chrono::steady_clock::now();
                if (left > std::chrono::milliseconds{0})
                    std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(left, endpoint_.retry));
                continue;
            }
            auto const left = std::chrono::duration_cast<std::chrono::milliseconds>(until -
                                                                                    std::chrono::steady_clock::now());
            if (mosquitto_loop(client_, static_cast<int>(std::max<long long>(left.count(), 0)), 1) !=
                MOSQ_ERR_SUCCESS) {
                drop_connection();
                continue;
            }
            // The loop reads one packet per call: take what else has arrived, without waiting.
            for (std::size_t before = 0; before != inbox_.size() && inbox_.size() < 4096;) {
                before = inbox_.size();
                if (mosquitto_loop(client_, 0, 1) != MOSQ_ERR_SUCCESS) {
                    drop_connection();
                    break;
                }
            }
        } while (inbox_.empty() && std::chrono::steady_clock::now() < until);
        return deliver_all(inbox_, deliver);
    }
    bool connected() const override { return connected_; }
    std::string peer() const override {
        return "the MQTT broker at " + endpoint_.host + ":" + std::to_string(endpoint_.port);
    }

private:
    bool try_connect() {
        auto const now = std::chrono::steady_clock::now();
        if (last_attempt_ && now - *last_attempt_ < endpoint_.retry) return false;
        last_attempt_ = now;
        // Asynchronous: an unreachable broker must not hold the node longer than its poll's timeout.
        int const rc = ever_connected_ ? mosquitto_reconnect_async(client_)
                                       : mosquitto_connect_async(client_, endpoint_.host.c_str(), endpoint_.port,
                                                                 endpoint_.keepalive_seconds);
        if (rc != MOSQ_ERR_SUCCESS) return false;
        ever_connected_ = true;
        socket_open_ = true;  // CONNACK arrives through the loop, then on_connect subscribes
        return true;
    }
    void drop_connection() {
        connected_ = false;
        socket_open_ = false;
    }
    void on_connect(int rc) {
        if (rc != 0) return;
        connected_ = true;
        for (auto const& f : filters_) mosquitto_subscribe(client_, nullptr, f.c_str(), 0);
    }

    mqtt_endpoint endpoint_;
    mosquitto* client_ = nullptr;
    std::vector<std::string> filters_;
    std::deque<message> inbox_;
    std::optional<std::chrono::steady_clock::time_point> last_attempt_;
    bool ever_connected_ = false;
    bool socket_open_ = false;
    bool connected_ = false;
};

}  // namespace bsc::net
// end include/bsc/net/mosquitto_transport.hpp
// end include/bsc/mqtt.hpp
