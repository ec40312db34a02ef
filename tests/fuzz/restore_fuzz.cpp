// libFuzzer target for bsc::restore: no input may crash it, leak, or be accepted wrongly.
//
// The first byte of an input picks how the rest is used:
//   0  as the bytes to restore, unchanged;
//   1  as edits (position, value pairs; a last odd byte cuts or extends the result) of a valid
//      saved state, so that mutations stay near the format;
//   2  as 1, then the header and the checksum made valid again, so that the checks of the
//      payload's values are reached.
// and bit 7 of it restores with bsc::resume_at (a time taken from the input).
// Every input must leave the machine as it was when refused; when accepted, the bytes must be
// exactly what bsc::save writes for the restored machine (nothing was accepted that save could
// not have written), and the machine must run on (dispatches and cycles, under the sanitizers).
//
// Build with -DBSC_BUILD_FUZZERS=ON and Clang; run e.g. `restore_fuzz -runs=1000000`.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../unit/retain_fixture.hpp"

namespace {

using machine = bsc::machine<decltype(retain_test::chart)>;

// A machine in the middle of a run, and its saved bytes.
machine running_machine() {
    machine m{retain_test::chart, retain_test::ctx{}};
    for (int k = 0; k < 12; ++k) retain_test::drive(m, k);
    return m;
}

void fail(char const* what) {
    std::fprintf(stderr, "restore_fuzz: %s\n", what);
    std::abort();
}

void put_le(std::vector<std::byte>& bytes, std::size_t at, std::uint64_t v, std::size_t n) {
    for (std::size_t i = 0; i < n && at + i < bytes.size(); ++i, v >>= 8)
        bytes[at + i] = static_cast<std::byte>(v & 0xffu);
}

std::vector<std::byte> edited(std::vector<std::byte> bytes, std::uint8_t const* data, std::size_t size) {
    std::size_t i = 0;
    for (; i + 1 < size; i += 2)
        if (!bytes.empty()) bytes[data[i] % bytes.size()] = std::byte{data[i + 1]};
    if (i < size) {  // a last odd byte: cut (below 128) or extend
        if (data[i] < 128)
            bytes.resize(bytes.size() * data[i] / 128);
        else
            bytes.resize(bytes.size() + (data[i] - 127u), std::byte{data[i]});
    }
    return bytes;
}

void make_header_valid(std::vector<std::byte>& bytes, std::vector<std::byte> const& valid) {
    namespace r = bsc::detail::retain;
    if (bytes.size() < r::header_size + r::trailer_size) return;
    for (std::size_t i = 0; i < r::header_size; ++i) bytes[i] = valid[i];
    put_le(bytes, 8, bytes.size() - r::header_size - r::trailer_size, 4);
    std::size_t const checked = bytes.size() - r::trailer_size;
    put_le(bytes, checked, bsc::detail::crc32(bytes.data(), checked), 4);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(std::uint8_t const* data, std::size_t size) {
    if (size == 0) return 0;
    static machine const reference = running_machine();
    static std::vector<std::byte> const valid = bsc::save(reference);

    std::uint8_t const mode = data[0];
    std::uint8_t const* rest = data + 1;
    std::size_t const n = size - 1;
    std::vector<std::byte> bytes;
    switch (mode % 3) {
        case 0:
            bytes.assign(reinterpret_cast<std::byte const*>(rest), reinterpret_cast<std::byte const*>(rest) + n);
            break;
        case 1: bytes = edited(valid, rest, n); break;
        default:
            bytes = edited(valid, rest, n);
            make_header_valid(bytes, valid);
            break;
    }
    bool const resume = (mode & 0x80) != 0;
    auto const resume_time = bsc::duration{static_cast<bsc::duration::rep>(n > 0 ? rest[0] : 0) *
                                           7'000'000'000'000'000};

    machine m = running_machine();
    m.dispatch(retain_test::back{}, bsc::allow_unhandled);
    auto const before = bsc::save(m);
    auto const result = resume ? bsc::restore(m, bytes, bsc::resume_at{resume_time}) : bsc::restore(m, bytes);
    if (!result) {
        if (bsc::save(m) != before) fail("a refused restore changed the machine");
        if (result.error == bsc::restore_error::none) fail("refused without a reason");
        return 0;
    }
    if (!resume && bsc::save(m) != bytes) fail("accepted bytes that save would not have written");
    if (bytes.size() != bsc::saved_size<machine>) fail("accepted bytes of another size");
    // The restored machine runs on, whatever its values.
    for (int k = 0; k < 24; ++k) retain_test::drive(m, 40 + k);
    return 0;
}
