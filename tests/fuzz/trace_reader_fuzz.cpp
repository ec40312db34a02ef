// libFuzzer target for bsc::trace_reader: no input may crash it, read out of bounds or leak,
// whatever the pieces it comes in.
//
// The first byte of an input picks how the rest is fed: bits 0 to 6 give the size of the pieces
// (0: one piece), so that frames are cut at every place; with bit 7 set, the rest is first made
// into frames with valid checksums ([type][length][payload] each, a sequence number skipped
// where the type's bit 6 is set), so that every record's decoding is reached. Whatever is read must add up: every
// frame with a valid checksum is a record or counted malformed, and frames and skipped bytes
// together never exceed the input. Each record is described with the dictionary read so far.
//
// Build with -DBSC_BUILD_FUZZERS=ON and Clang; run e.g. `trace_reader_fuzz -runs=1000000`.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include <bsc/trace_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
    if (size == 0) return 0;
    std::size_t const piece = (data[0] & 0x7Fu) == 0 ? size : (data[0] & 0x7Fu);
    std::span<std::byte const> input{reinterpret_cast<std::byte const*>(data + 1), size - 1};
    std::vector<std::byte> framed;
    if (data[0] & 0x80u) {
        namespace t = bsc::detail::trace;
        std::uint16_t sequence = 0;
        for (std::size_t at = 0; at + 2 <= input.size();) {
            auto const type = static_cast<std::uint8_t>(input[at]);
            std::size_t length = static_cast<std::size_t>(input[at + 1]);
            if (length > input.size() - at - 2) length = input.size() - at - 2;
            if (type & 0x40u) ++sequence;
            std::byte header[t::header_size] = {t::sync, static_cast<std::byte>(type & 0xBFu)};
            t::put(header + 2, sequence++);
            header[4] = static_cast<std::byte>(length);
            auto const payload = input.subspan(at + 2, length);
            std::byte trailer[2];
            t::put(trailer, t::crc(payload, t::crc(std::span<std::byte const>{header + 1, 4})));
            framed.insert(framed.end(), header, header + t::header_size);
            framed.insert(framed.end(), payload.begin(), payload.end());
            framed.insert(framed.end(), trailer, trailer + 2);
            at += 2 + length;
        }
        input = framed;
    }
    bsc::trace_reader reader;
    std::uint64_t records = 0;
    for (std::size_t at = 0; at < input.size(); at += piece) {
        reader.feed(input.subspan(at, piece < input.size() - at ? piece : input.size() - at));
        while (auto r = reader.next()) {
            (void)reader.describe(*r);
            ++records;
        }
    }
    // The smallest frame is 7 bytes.
    if (records + reader.malformed() != reader.frames() || reader.frames() * 7 + reader.skipped_bytes() > input.size())
        std::abort();
    return 0;
}
