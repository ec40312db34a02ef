#pragma once
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
