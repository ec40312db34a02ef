#pragma once
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
