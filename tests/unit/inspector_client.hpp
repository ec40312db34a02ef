#pragma once
// A client of an inspector (bsc::inspector, bsc::system_inspector) in the same thread: it sends
// one request over a real loopback socket and polls the inspector until the answer is whole.

#include <doctest/doctest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace inspector_client {

using namespace std::chrono_literals;

struct answer {
    int status = 0;
    std::string headers;
    std::string body;
};

// Sends one request to the inspector on 127.0.0.1:port and polls it until the answer is whole
// (it closes the connection after each).
// A request as the page's script sends it: to the inspector's own host, a command with the
// X-Bsc-Command header; `origin`, `host` and `as_page` change that.
struct sent_as {
    std::string_view origin;
    std::string_view host;  // empty: 127.0.0.1:<port>
    bool as_page = true;
};

template <class Inspector>
inline answer ask(Inspector& view, std::string_view method, std::string_view target, std::string_view body = {},
                  sent_as how = {}) {
    int const fd = ::socket(AF_INET, SOCK_STREAM, 0);
    REQUIRE(fd >= 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(view.port());
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    REQUIRE(::connect(fd, reinterpret_cast<sockaddr const*>(&address), sizeof address) == 0);
    std::string const host = how.host.empty() ? "127.0.0.1:" + std::to_string(view.port()) : std::string{how.host};
    std::string request = std::string{method} + " " + std::string{target} + " HTTP/1.1\r\nHost: " + host + "\r\n";
    if (!how.origin.empty()) request += "Origin: " + std::string{how.origin} + "\r\n";
    if (how.as_page && method == "POST") request += "X-Bsc-Command: 1\r\n";
    request += "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + std::string{body};
    REQUIRE(::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size()));
    std::string reply;
    for (int round = 0; round < 200; ++round) {
        view.poll(5ms);
        char chunk[4096];
        ssize_t const n = ::recv(fd, chunk, sizeof chunk, MSG_DONTWAIT);
        if (n == 0) break;
        if (n > 0) reply.append(chunk, static_cast<std::size_t>(n));
    }
    ::close(fd);
    answer a;
    auto const end = reply.find("\r\n\r\n");
    REQUIRE(end != std::string::npos);
    a.status = std::stoi(reply.substr(9, 3));
    a.headers = reply.substr(0, end);
    a.body = reply.substr(end + 4);
    return a;
}

inline std::string header(answer const& a, std::string_view name) {
    auto const at = a.headers.find(std::string{name} + ": ");
    if (at == std::string::npos) return {};
    auto const end = a.headers.find("\r\n", at);
    return a.headers.substr(at + name.size() + 2,
                            end == std::string::npos ? std::string::npos : end - at - name.size() - 2);
}

}  // namespace inspector_client
