#pragma once
// What every inspector's server does alike: it answers only for its own host name, serves the
// page's files, keeps the trace's history for pages that open later, checks that a command
// comes from its own page and is allowed, and runs pause, resume and step. The machine's or the
// system's own answers (/info, /trace, the other commands) come from the inspector's handler.

#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <bsc/detail/inspector/http.hpp>
#include <bsc/inspector_options.hpp>
#include <bsc/outcome.hpp>
#include <bsc/trace.hpp>  // (trace_buffer.hpp through it: the single headers then share one copy)

namespace bsc::detail::inspector {

inline response text(int status, std::string body) {
    return response{status, "text/plain; charset=utf-8", std::move(body), {}};
}

// The number after `key=` in a query such as "actor=2&from=100"; `otherwise` when absent.
inline std::size_t query_number(std::string_view query, std::string_view key, std::size_t otherwise = 0) {
    while (!query.empty()) {
        auto const amp = query.find('&');
        std::string_view const part = query.substr(0, amp);
        if (part.size() > key.size() && part.starts_with(key) && part[key.size()] == '=') {
            std::size_t n = otherwise;
            auto const digits = part.substr(key.size() + 1);
            auto const r = std::from_chars(digits.data(), digits.data() + digits.size(), n);
            return r.ec == std::errc{} && r.ptr == digits.data() + digits.size() ? n : otherwise;
        }
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    }
    return otherwise;
}

// The first word of `s`, and the rest after one space.
inline std::pair<std::string_view, std::string_view> split_word(std::string_view s) {
    auto const space = s.find(' ');
    if (space == std::string_view::npos) return {s, {}};
    return {s.substr(0, space), s.substr(space + 1)};
}

inline std::string outcome_text(outcome o) {
    switch (o) {
        case outcome::consumed: return "consumed";
        case outcome::ignored: return "ignored";
        case outcome::queue_overflow: return "queue overflow";
        case outcome::livelock: return "livelock";
        case outcome::halted: return "halted";
        case outcome::reentrant: return "reentrant";
        case outcome::failed: return "failed";
        case outcome::unknown_event: return "unknown event";
    }
    return "?";
}

// A name as a JSON string's content: quotes, backslashes and control characters left out (the
// names are identifiers; this only keeps a strange one from breaking the document).
inline std::string json_name(std::string_view name) {
    std::string out;
    for (char c : name)
        if (c != '"' && c != '\\' && static_cast<unsigned char>(c) >= ' ') out += c;
    return out;
}

// The trace bytes one tracer wrote, drained from its ring and kept for pages that read them
// later, up to a limit past which they start again at a dictionary written anew.
class trace_history {
public:
    trace_history() = default;
    explicit trace_history(trace_buffer* buffer) : buffer_(buffer) {}

    bool traced() const { return buffer_ != nullptr; }
    // The trace bytes the page can read (from its start, less what the history let go).
    std::size_t end() const { return base_ + bytes_.size(); }

    // Moves what the ring holds into the history; past `limit`, lets it all go and keeps what
    // `rewrite()` writes (the dictionary and the configuration) instead.
    template <class Rewrite>
    void collect(std::size_t limit, Rewrite&& rewrite) {
        drain();
        if (bytes_.size() > limit) {
            base_ += bytes_.size();
            bytes_.clear();
            rewrite();
            drain();
        }
    }

    // The answer to GET /trace?from=N: at most `max_answer` bytes from N (or from the oldest
    // kept, if the history let N go), with the range in X-Trace-Start and X-Trace-End.
    response answer(std::size_t from) const {
        // Past the end (a page that read an earlier run of the program): an empty answer at the
        // end, which tells the page to read again from the start.
        std::size_t const start = from < base_ ? base_ : from > end() ? end() : from;
        std::size_t const stop = end() - start > max_answer ? start + max_answer : end();
        response r{200, "application/octet-stream", {}, {}};
        if (start < stop) r.body.assign(reinterpret_cast<char const*>(bytes_.data()) + (start - base_), stop - start);
        r.headers = {{"X-Trace-Start", std::to_string(start)}, {"X-Trace-End", std::to_string(stop)}};
        return r;
    }

    // The most trace bytes one answer carries: the page asks again from where it ends.
    static constexpr std::size_t max_answer = std::size_t{4} << 20;

private:
    void drain() {
        if (buffer_ == nullptr) return;
        std::byte chunk[4096];
        while (std::size_t const n = buffer_->read(chunk)) bytes_.insert(bytes_.end(), chunk, chunk + n);
    }

    trace_buffer* buffer_ = nullptr;
    std::vector<std::byte> bytes_;
    std::size_t base_ = 0;  // the offset in the whole trace of bytes_'s first byte
};

// The server and the commands every inspector shares. The handler answers the rest:
//   response info(std::string const& run_fields)   GET /info, given the fields all share
//   response trace(std::string_view query)         GET /trace?...
//   response command(std::string_view verb, std::string_view rest)   a command but pause,
//       resume and step (400 with the list of commands for one it does not know)
class site {
public:
    explicit site(inspector_options options) : options_(std::move(options)), server_(options_.port) {}

    std::uint16_t port() const { return server_.port(); }
    std::string url() const { return "http://127.0.0.1:" + std::to_string(port()) + "/"; }
    inspector_options const& options() const { return options_; }

    bool may_step() {
        if (!paused_) return true;
        if (steps_ == 0) return false;
        --steps_;
        return true;
    }
    bool paused() const { return paused_; }
    std::uint64_t commands_run() const { return commands_; }

    template <class Handler>
    void serve(std::chrono::milliseconds wait, Handler& handler) {
        server_.serve(wait, [this, &handler](request const& r) { return answer(r, handler); });
    }

private:
    template <class Handler>
    response answer(request const& r, Handler& handler) {
        // A page of another site that a rebinding of its name sends here reads nothing either.
        std::string const port_text = ":" + std::to_string(port());
        if (r.host != "127.0.0.1" + port_text && r.host != "localhost" + port_text)
            return text(421, "this server answers for 127.0.0.1" + port_text + " only");
        std::string_view target = r.target;
        std::string_view query;
        if (auto const q = target.find('?'); q != std::string_view::npos) {
            query = target.substr(q + 1);
            target = target.substr(0, q);
        }
        if (target == "/command") {
            response done = command(r, handler);
            if (options_.on_command) options_.on_command(r.body, done.body);
            return done;
        }
        if (r.method != "GET") return text(405, "GET or POST /command only");
        if (target == "/info") {
            std::string run = "\"commands\": " + std::string(options_.commands ? "true" : "false");
            run += ", \"paused\": " + std::string(paused_ ? "true" : "false");
            run += ", \"scan\": " + std::string(options_.stepping ? "true" : "false");
            return handler.info(run);
        }
        if (target == "/trace") return handler.trace(query);
        return file(target == "/" ? std::string_view{"index.html"} : target.substr(1));
    }

    response file(std::string_view name) const {
        bool const plain = !name.empty() && name.front() != '.' &&
                           name.find_first_not_of(
                               "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") ==
                               std::string_view::npos;
        if (!plain || options_.web_root.empty()) return text(404, "not found");
        std::ifstream in{options_.web_root + "/" + std::string{name}, std::ios::binary};
        if (!in) return text(404, "not found");
        std::string body{std::istreambuf_iterator<char>(in), {}};
        std::string type = "application/octet-stream";
        if (name.ends_with(".html")) type = "text/html; charset=utf-8";
        if (name.ends_with(".js") || name.ends_with(".mjs")) type = "text/javascript; charset=utf-8";
        if (name.ends_with(".css")) type = "text/css; charset=utf-8";
        if (name.ends_with(".svg")) type = "image/svg+xml";
        if (name.ends_with(".png")) type = "image/png";
        if (name.ends_with(".json")) type = "application/json";
        return {200, type, std::move(body), {}};
    }

    template <class Handler>
    response command(request const& r, Handler& handler) {
        if (r.method != "POST") return text(405, "POST a command");
        if (!options_.commands) return text(403, "this program does not accept commands: the view is read-only");
        // Only the page's own script sends the custom header: a browser asks this server before
        // another site's page may send it, and this server never says yes.
        std::string const own = "http://127.0.0.1:" + std::to_string(port());
        std::string const own_name = "http://localhost:" + std::to_string(port());
        if ((!r.origin.empty() && r.origin != own && r.origin != own_name) || !r.command)
            return text(403, "a command from another origin is refused");
        std::string_view body = r.body;
        while (!body.empty() && (body.back() == '\n' || body.back() == '\r' || body.back() == ' '))
            body.remove_suffix(1);
        auto const [verb, rest] = split_word(body);
        bool const run_control = verb == "pause" || verb == "resume" || verb == "step";
        ++commands_;
        if (run_control && !options_.stepping)
            return text(409, "pause, resume and step are for a program that runs in steps");
        if (verb == "pause") return paused_ = true, text(200, "ok paused");
        if (verb == "resume") return paused_ = false, steps_ = 0, text(200, "ok running");
        if (verb == "step") {
            if (!paused_) return text(409, "step while paused");
            ++steps_;
            return text(200, "ok one step");
        }
        response answer = handler.command(verb, rest);
        if (answer.status == 400 && answer.body.starts_with("commands:")) --commands_;
        return answer;
    }

    inspector_options options_;
    server server_;
    bool paused_ = false;
    std::uint64_t steps_ = 0;
    std::uint64_t commands_ = 0;
};

}  // namespace bsc::detail::inspector
