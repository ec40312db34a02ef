#pragma once
// bsc::inspector - a live view in the browser, single-header distribution (needs bsc.hpp beside it; POSIX).
// Generated from include/bsc/inspector.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/inspector.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_INSPECTOR_HPP
#define BSC_SINGLE_INCLUDE_BSC_INSPECTOR_HPP
// bsc::inspector: a live view of a running machine in the browser. It serves the inspector's
// page (web/inspector, docs/inspector.md) on 127.0.0.1 and the machine's trace stream to it,
// and, when the program allows it, runs the page's commands on the machine:
//
//   std::array<std::byte, 1 << 16> storage;
//   bsc::trace_buffer buffer{storage};
//   bsc::machine m{chart, ctx{}, bsc::tracer{chart, buffer}};
//   bsc::inspector view{m, buffer, {.port = 8080, .commands = true, .web_root = "web/inspector"}};
//   for (;;) {
//       view.poll(10ms);                  // serve the page, run its commands
//       if (view.may_step()) m.step(now);  // a scan machine: paused and stepped from the page
//   }
//
// Nothing runs behind the program's back: there is no thread; the page's commands run in
// poll(), through the machine's own interface (dispatch_by_name; an input's set, latched at the
// next step), so that the checks and the reentrancy rules hold. The server binds to the
// loopback address only, refuses commands unless `commands` is set, and refuses a command from a
// page of another origin.
//
// Opt-in and POSIX only: <bsc/bsc.hpp> does not include it.

#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <type_traits>

// begin include/bsc/detail/inspector/site.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_SITE_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_SITE_HPP
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

// begin include/bsc/detail/inspector/http.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_HTTP_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_HTTP_HPP
// The inspector's HTTP server: a listening socket on 127.0.0.1 and its clients, served one
// request per connection, without threads: poll() is called from the program's own loop, so
// that every command runs between two of the machine's steps (POSIX sockets; Linux).

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace bsc::detail::inspector {

struct request {
    std::string method;
    std::string target;    // the path and the query
    std::string host;      // the Host header
    std::string origin;    // the Origin header, if any
    bool command = false;  // the X-Bsc-Command header: only the page's own script sends it
    std::string body;
};

struct response {
    int status = 200;
    std::string content_type = "text/plain; charset=utf-8";
    std::string body;
    std::vector<std::pair<std::string, std::string>> headers;
};

inline std::string_view reason(int status) {
    switch (status) {
        case 200: return "OK";
        case 400: return "Bad Request";
        case 403: return "Forbidden";
        case 404: return "Not Found";
        case 405: return "Method Not Allowed";
        case 409: return "Conflict";
        case 413: return "Payload Too Large";
        case 421: return "Misdirected Request";
        default: return "Error";
    }
}

inline std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

// The request in `data` if it is whole: 1 (parsed into `r`), 0 (more bytes needed), -1 (not a
// request this server reads), -2 (larger than `limit`).
inline int parse(std::string const& data, request& r, std::size_t limit) {
    auto const end_of_headers = data.find("\r\n\r\n");
    if (end_of_headers == std::string::npos) return data.size() > limit ? -2 : 0;
    std::string_view const head{data.data(), end_of_headers};
    auto const line_end = head.find("\r\n");
    std::string_view const line = head.substr(0, line_end);
    auto const first = line.find(' ');
    auto const second = first == std::string_view::npos ? first : line.find(' ', first + 1);
    if (second == std::string_view::npos) return -1;
    r.method = std::string(line.substr(0, first));
    r.target = std::string(line.substr(first + 1, second - first - 1));
    std::size_t length = 0;
    for (std::size_t at = line_end; at != std::string_view::npos && at < head.size();) {
        auto const next = head.find("\r\n", at + 2);
        std::string_view const header = head.substr(at + 2, next == std::string_view::npos ? next : next - at - 2);
        auto const colon = header.find(':');
        if (colon != std::string_view::npos) {
            std::string const name = lowercase(header.substr(0, colon));
            std::string_view value = header.substr(colon + 1);
            while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
            while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
            if (name == "content-length") {
                char* stop = nullptr;
                std::string const digits(value);
                auto const n = std::strtoull(digits.c_str(), &stop, 10);
                if (digits.empty() || *stop != '\0') return -1;
                if (n > limit) return -2;
                length = static_cast<std::size_t>(n);
            } else if (name == "host") {
                r.host = std::string(value);
            } else if (name == "origin") {
                r.origin = std::string(value);
            } else if (name == "x-bsc-command") {
                r.command = true;
            }
        }
        at = next;
    }
    std::size_t const body_start = end_of_headers + 4;
    if (data.size() - body_start < length) return 0;
    r.body = data.substr(body_start, length);
    return 1;
}

inline std::string serialize(response const& r) {
    std::string out = "HTTP/1.1 " + std::to_string(r.status) + " " + std::string(reason(r.status)) + "\r\n";
    out += "Content-Type: " + r.content_type + "\r\n";
    out += "Content-Length: " + std::to_string(r.body.size()) + "\r\n";
    out += "Cache-Control: no-store\r\nConnection: close\r\n";
    for (auto const& [name, value] : r.headers) out += name + ": " + value + "\r\n";
    out += "\r\n";
    out += r.body;
    return out;
}

// A listening socket on 127.0.0.1 and the connections it accepted.
class server {
public:
    static constexpr std::size_t request_limit = 64 * 1024;
    static constexpr std::size_t max_clients = 32;
    // A connection that has not sent its request and read the answer by then is closed, so
    // that idle ones cannot keep others out.
    static constexpr std::chrono::seconds client_deadline{10};

    // Listens on 127.0.0.1:port (0: a port the system picks); throws std::system_error.
    explicit server(std::uint16_t port) {
        listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        if (listener_ < 0) fail("socket");
        int const yes = 1;
        ::setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(port);
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // loopback only, never another interface
        if (::bind(listener_, reinterpret_cast<sockaddr const*>(&address), sizeof address) != 0) fail("bind");
        if (::listen(listener_, 16) != 0) fail("listen");
        socklen_t size = sizeof address;
        if (::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &size) != 0) fail("getsockname");
        port_ = ntohs(address.sin_port);
    }
    ~server() {
        for (auto const& c : clients_) ::close(c.fd);
        if (listener_ >= 0) ::close(listener_);
    }
    server(server const&) = delete;
    server& operator=(server const&) = delete;

    std::uint16_t port() const { return port_; }

    // Waits at most `wait` for something to do, then accepts, reads and writes what is ready:
    // each whole request is answered by handle(request) -> response.
    template <class Handler>
    void serve(std::chrono::milliseconds wait, Handler&& handle) {
        std::vector<pollfd> fds;
        fds.push_back({listener_, POLLIN, 0});
        for (auto const& c : clients_) fds.push_back({c.fd, static_cast<short>(c.out.empty() ? POLLIN : POLLOUT), 0});
        int const ready = ::poll(fds.data(), fds.size(), static_cast<int>(wait.count()));
        if (ready > 0) {
            std::size_t const waiting = clients_.size();  // accept_all adds after them
            if (fds[0].revents & POLLIN) accept_all();
            for (std::size_t i = 1; i < fds.size() && i - 1 < waiting; ++i) {
                if (fds[i].revents == 0) continue;
                client& c = clients_[i - 1];
                if (c.out.empty())
                    receive(c, handle);
                else
                    transmit(c);
            }
        }
        auto const now = std::chrono::steady_clock::now();
        std::erase_if(clients_, [&](client const& c) {
            bool const done = c.closed || now - c.since > client_deadline;
            if (done) ::close(c.fd);
            return done;
        });
    }

private:
    struct client {
        int fd = -1;
        std::chrono::steady_clock::time_point since;
        std::string in;
        std::string out;
        std::size_t sent = 0;
        bool closed = false;
    };

    [[noreturn]] void fail(char const* what) {
        int const error = errno;
        if (listener_ >= 0) ::close(listener_);
        listener_ = -1;
        throw std::system_error(error, std::generic_category(), std::string("bsc::inspector: ") + what);
    }

    void accept_all() {
        for (;;) {
            int const fd = ::accept4(listener_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
            if (fd < 0) return;
            if (clients_.size() >= max_clients) {
                ::close(fd);
                continue;
            }
            clients_.push_back({fd, std::chrono::steady_clock::now(), {}, {}, 0, false});
        }
    }

    template <class Handler>
    void receive(client& c, Handler& handle) {
        char buffer[4096];
        ssize_t const n = ::recv(c.fd, buffer, sizeof buffer, 0);
        if (n <= 0) {
            if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) c.closed = true;
            return;
        }
        c.in.append(buffer, static_cast<std::size_t>(n));
        request r;
        int const parsed = parse(c.in, r, request_limit);
        if (parsed == 0) return;
        response const answer = parsed == -2 ? response{413, "text/plain; charset=utf-8", "request too large", {}}
                                : parsed == -1
                                    ? response{400, "text/plain; charset=utf-8", "request not understood", {}}
                                    : handle(r);
        c.out = serialize(answer);
        transmit(c);
    }

    void transmit(client& c) {
        while (c.sent < c.out.size()) {
            ssize_t const n = ::send(c.fd, c.out.data() + c.sent, c.out.size() - c.sent, MSG_NOSIGNAL);
            if (n < 0) {
                if (errno != EAGAIN && errno != EWOULDBLOCK) c.closed = true;
                return;
            }
            c.sent += static_cast<std::size_t>(n);
        }
        c.closed = true;  // one request per connection
    }

    int listener_ = -1;
    std::uint16_t port_ = 0;
    std::vector<client> clients_;
};

}  // namespace bsc::detail::inspector
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_HTTP_HPP
// end include/bsc/detail/inspector/http.hpp
// begin include/bsc/inspector_options.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_INSPECTOR_OPTIONS_HPP
#define BSC_SINGLE_INCLUDE_BSC_INSPECTOR_OPTIONS_HPP
// bsc::inspector_options: how a bsc::inspector or a bsc::system_inspector serves its page.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace bsc {

/// How an inspector serves.
struct inspector_options {
    std::uint16_t port = 0;  ///< the port on 127.0.0.1; 0: one the system picks (port() tells)
    bool commands = false;   ///< run the page's commands: dispatch, set, pause, resume, step
    /// The program asks may_step() before each step, so that the page may pause it and step it
    /// one step at a time (a scan loop).
    bool stepping = false;
    std::string web_root;  ///< the folder of the page's files (index.html, inspector.js, ...)
    /// The trace bytes kept for a page that opens later (for each actor of a system); past it
    /// the history starts again with the dictionary and the configuration written anew.
    std::size_t history_limit = std::size_t{64} << 20;
    /// Called after each command the page sent, with the command and the answer it got (the
    /// program's own log of what was done to it).
    std::function<void(std::string_view command, std::string_view answer)> on_command;
};

}  // namespace bsc
#endif  // BSC_SINGLE_INCLUDE_BSC_INSPECTOR_OPTIONS_HPP
// end include/bsc/inspector_options.hpp
#include "trace.hpp"

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
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_INSPECTOR_SITE_HPP
// end include/bsc/detail/inspector/site.hpp
#include "observers.hpp"

namespace bsc {

namespace detail::inspector {

// The tracer among a machine's observers: the observer itself, or the first tracer part of a
// bsc::observers; a no_tracer when there is none (which the inspector refuses).
struct no_tracer {
    template <class Machine>
    void write_dictionary(Machine const&) {}
    template <class Machine>
    void sample(Machine const&) {}
};
template <class T>
inline constexpr bool is_tracer = false;
template <class C>
inline constexpr bool is_tracer<tracer<C>> = true;

template <class O>
auto* tracer_of(O& o) {
    if constexpr (is_tracer<O>) {
        return &o;
    } else {
        (void)o;
        return static_cast<no_tracer*>(nullptr);
    }
}
template <class... Parts>
auto* tracer_of(observers<Parts...>& o) {
    constexpr std::size_t first = [] {
        constexpr bool tracers[] = {is_tracer<Parts>...};
        std::size_t i = 0;
        while (i < sizeof...(Parts) && !tracers[i]) ++i;
        return i;
    }();
    if constexpr (first < sizeof...(Parts))
        return &o.template get<first>();
    else
        return static_cast<no_tracer*>(nullptr);
}

// Finds the context member named `path` (dotted, as the trace names members) in a walk
// (detail/members.hpp) and, if it is an input of a scalar type that `refuse` does not refuse
// (given its address, it says why not, or nothing), sets it to the value `text` reads as;
// `answer` is then empty, or says why not.
struct input_setter {
    static constexpr bool named = true;
    std::string_view path;
    std::string_view text;
    std::function<std::string(void const*)> refuse;
    member_path prefix;
    std::string answer;
    bool found = false;

    // As the trace names them (the page sets what the trace showed it).
    std::string element_name(std::string_view name, std::size_t i) const { return recorded::element_name(name, i); }
    void enter(std::string_view name) { prefix.enter(name); }
    void leave() { prefix.leave(); }
    template <class T>
    void leaf(T const& member, std::string_view name) {
        if (found || prefix.of(name) != path) return;
        found = true;
        std::string const what{path};
        if constexpr (is_channel<T>) {
            using V = channel_value<T>;
            if constexpr (is_output_channel<T>) {  // the chart's own: its const set() is an error
                answer = what + " is an output: only inputs can be set";
            } else if constexpr (!recorded::is_scalar_variable<V>) {
                answer = what + " is not of a scalar type";
            } else if (std::string why = refuse ? refuse(&member) : std::string{}; !why.empty()) {
                answer = std::move(why);
            } else {
                V value{};
                if (read(text, value)) {
                    member.set(value);
                    answer.clear();
                } else {
                    answer = "'" + std::string{text} + "' is not a value of " + what;
                }
            }
        } else {
            (void)member;
            answer = what + " is not an input channel: only inputs can be set";
        }
    }
    template <class V>
    static bool read(std::string_view t, V& value) {
        if constexpr (std::is_same_v<V, bool>) {
            bool const yes = t == "true" || t == "1";
            bool const no = t == "false" || t == "0";
            if (yes || no) value = yes;
            return yes || no;
        } else if constexpr (std::is_enum_v<V>) {
            // Only an enum with a fixed underlying type takes any of its values: list
            // initialisation from an integer compiles for exactly those.
            if constexpr (requires(std::underlying_type_t<V> u) { V{u}; }) {
                std::underlying_type_t<V> n{};
                if (!read(t, n)) return false;
                value = V{n};
                return true;
            } else {
                return false;
            }
        } else {
            auto const r = std::from_chars(t.data(), t.data() + t.size(), value);
            return r.ec == std::errc{} && r.ptr == t.data() + t.size();
        }
    }
};

// Sets the input named `path` of `context` to `text`'s value: "" (done), or why not (`refuse`'s
// answer for the input's address among them).
template <class Context>
std::string set_input(Context const& context, std::string_view path, std::string_view text,
                      std::function<std::string(void const*)> refuse = {}) {
    input_setter setter{path, text, std::move(refuse), {}, "no input is named '" + std::string{path} + "'", false};
    if constexpr (reaches<input_setter, Context>()) walk(context, setter, std::string_view{});
    return setter.answer;
}

}  // namespace detail::inspector

/// Serves a live view of `Machine` to the browser; see the top of this header.
/// Requirements: the machine's observer is a bsc::tracer writing into `buffer`, or a
/// bsc::observers holding one; the machine and the buffer outlive the inspector.
template <class Machine>
class inspector {
public:
    /// Listens on 127.0.0.1:options.port; throws std::system_error if it cannot.
    inspector(Machine& machine, trace_buffer& buffer, inspector_options options)
        : machine_(machine), history_(&buffer), site_(std::move(options)) {
        static_assert(!std::is_same_v<decltype(tracer()), detail::inspector::no_tracer*>,
                      "bsc::inspector: the machine's observer must be a bsc::tracer, or a bsc::observers holding one");
    }

    /// The port it listens on.
    std::uint16_t port() const { return site_.port(); }
    /// The page's address: "http://127.0.0.1:<port>/".
    std::string url() const { return site_.url(); }

    /// Moves the trace into the history, then serves the requests that arrive within `wait`
    /// (and runs their commands).
    void poll(std::chrono::milliseconds wait = {}) {
        collect();
        site_.serve(wait, *this);
        collect();
    }

    /// For a scan loop: whether to run the next step. Always true while not paused; while
    /// paused, true once for each "step" command.
    bool may_step() { return site_.may_step(); }
    /// Whether the page paused the machine.
    bool paused() const { return site_.paused(); }
    /// The commands run so far.
    std::uint64_t commands_run() const { return site_.commands_run(); }
    /// The trace bytes the page can read (from its start, less what the history let go).
    std::size_t trace_end() const { return history_.end(); }

private:
    // The site's handler (detail/inspector/site.hpp): the machine's own answers.
    friend class detail::inspector::site;
    detail::inspector::response info(std::string const& run) const {
        std::string body = "{\"chart\": \"" + detail::inspector::json_name(detail::state_names_of<model>[1]) + "\", ";
        return {200, "application/json", body + run + "}", {}};
    }
    detail::inspector::response trace(std::string_view query) const {
        return history_.answer(detail::inspector::query_number(query, "from"));
    }
    detail::inspector::response command(std::string_view verb, std::string_view rest) {
        using detail::inspector::text;
        if (verb == "dispatch" && !rest.empty()) {
            outcome const o = machine_.dispatch_by_name(rest);
            tracer()->sample(machine_);
            if (o == outcome::unknown_event)
                return text(400, "no event of this chart is named '" + std::string{rest} + "'");
            return text(200, "ok " + std::string{rest} + ": " + detail::inspector::outcome_text(o));
        }
        if (verb == "set" && !rest.empty()) {
            auto const [member, value] = detail::inspector::split_word(rest);
            if (value.empty()) return text(400, "set <input> <value>");
            std::string const why = detail::inspector::set_input(machine_.context(), member, value);
            if (!why.empty()) return text(400, why);
            return text(200, "ok " + std::string{member} + " = " + std::string{value} +
                                 (site_.options().stepping ? " (latched at the next step)" : ""));
        }
        return text(400, "commands: dispatch <event>, set <input> <value>, pause, resume, step");
    }

    void collect() {
        // The history starts again at a dictionary and the configuration written now, so that
        // a page that opens later begins with every name and where the machine stands.
        history_.collect(site_.options().history_limit, [this] { tracer()->write_dictionary(machine_); });
    }

    auto* tracer() { return detail::inspector::tracer_of(machine_.observer()); }

    using model = detail::chart_model<std::remove_cv_t<typename Machine::chart_type>>;

    Machine& machine_;
    detail::inspector::trace_history history_;
    detail::inspector::site site_;
};

template <class Machine>
inspector(Machine&, trace_buffer&, inspector_options) -> inspector<Machine>;

}  // namespace bsc
#endif  // BSC_SINGLE_INCLUDE_BSC_INSPECTOR_HPP
// end include/bsc/inspector.hpp
