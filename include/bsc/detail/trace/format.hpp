#pragma once
// The trace stream's frame (docs/trace.md): what bsc::trace_buffer writes and
// bsc::trace_reader reads, in one place.
//
//   offset  size  field
//   0       1     sync byte 0xB5
//   1       1     record type (record_type)
//   2       2     sequence number, little-endian, +1 per frame written or dropped (mod 2^16)
//   4       1     payload length n (0 to 255)
//   5       n     payload, its integers little-endian
//   5+n     2     CRC-16/CCITT-FALSE of bytes 1 to 4+n, little-endian
//
// A reader finds frames by the sync byte and keeps one only if its checksum holds, so that it
// resynchronises after damage; a gap in the sequence numbers shows a frame lost on the way.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace bsc::detail::trace {

inline constexpr std::byte sync{0xB5};
inline constexpr std::size_t header_size = 5;   // sync, type, sequence, length
inline constexpr std::size_t trailer_size = 2;  // the checksum
inline constexpr std::size_t max_payload = 255;
inline constexpr std::size_t max_frame = header_size + max_payload + trailer_size;
inline constexpr std::uint8_t format_version = 1;

// The records. A hello starts a dictionary: the chart's name and how many states, events and
// transition rows it has; the state, event, row and member records that follow name each number.
enum class record_type : std::uint8_t {
    hello = 0x01,          // version u8, states u16, events u16, rows u16, chart name
    state = 0x02,          // state u16, parent u16 (0xFFFF: none), kind u8 (dsl kind), name
    event = 0x03,          // event u16, name
    row = 0x05,            // row u16, source u16, target u16 (0xFFFF: internal), trigger u16, flags u8
                           // (1: defers, 2: local), label ("event [guard] / action")
    member = 0x04,         // member u16, kind u8 (var kind), width u8, name (dotted path)
    configuration = 0x06,  // begins u8 (1: a configuration begins, 0: the last one goes on), then
                           // the active states, u16 each (up to 127 a record)
    dispatch = 0x10,       // time i64 ns, event u16
    cycle = 0x11,          // time i64 ns
    cycle_end = 0x12,      // (empty)
    exit = 0x13,           // state u16
    entry = 0x14,          // state u16
    transition = 0x15,     // row u16, source u16, target u16 (0xFFFF: internal), trigger u16, [delay i64 ns]
    deferral = 0x16,       // state u16, event u16
    values = 0x20,         // time i64 ns, then (member u16, value u64) pairs: what changed
    overflow = 0x30,       // frames dropped so far u64: written when room returns after a drop
};

// Numbers a trigger takes besides the chart's events.
inline constexpr std::uint16_t no_number = 0xFFFF;  // no parent; internal target; an unnamed event
inline constexpr std::uint16_t eventless_trigger = 0xFFFE;
inline constexpr std::uint16_t timeout_trigger = 0xFFFD;  // the record carries the delay

// CRC-16/CCITT-FALSE (polynomial 0x1021, initial 0xFFFF): a table of 256 entries, one lookup a byte.
inline constexpr std::array<std::uint16_t, 256> crc_table = [] {
    std::array<std::uint16_t, 256> t{};
    for (unsigned i = 0; i < 256; ++i) {
        unsigned c = i << 8;
        for (int b = 0; b < 8; ++b) c = (c & 0x8000u) ? (c << 1) ^ 0x1021u : c << 1;
        t[i] = static_cast<std::uint16_t>(c & 0xFFFFu);
    }
    return t;
}();

constexpr std::uint16_t crc_update(std::uint16_t crc, std::byte b) {
    auto const index = static_cast<unsigned>((crc >> 8) ^ static_cast<unsigned>(b)) & 0xFFu;
    return static_cast<std::uint16_t>((crc << 8) ^ crc_table[index]);
}
constexpr std::uint16_t crc(std::span<std::byte const> bytes, std::uint16_t start = 0xFFFF) {
    for (std::byte b : bytes) start = crc_update(start, b);
    return start;
}

// Little-endian integers into and out of a payload.
template <class T>
constexpr std::byte* put(std::byte* out, T value) {
    auto v = static_cast<std::uint64_t>(value);
    for (std::size_t i = 0; i < sizeof(T); ++i, v >>= 8) *out++ = static_cast<std::byte>(v & 0xFFu);
    return out;
}
template <class T>
constexpr T get(std::byte const* in) {
    std::uint64_t v = 0;
    for (std::size_t i = sizeof(T); i-- > 0;) v = (v << 8) | static_cast<std::uint64_t>(in[i]);
    return static_cast<T>(v);
}

}  // namespace bsc::detail::trace
