#pragma once
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

#include <bsc/net/transport.hpp>

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
