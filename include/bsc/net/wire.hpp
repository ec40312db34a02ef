#pragma once
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

#include <bsc/detail/bytes.hpp>
#include <bsc/detail/member_names.hpp>
#include <bsc/detail/state_bytes.hpp>

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
