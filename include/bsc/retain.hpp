#pragma once
// Retentive state: a machine saved to bytes and restored into a fresh machine of the same chart,
// so that a controller continues after a restart where it stopped (a PLC's retentive memory).
//
//   std::array<std::byte, bsc::saved_size<cell::machine>> bytes;
//   bsc::save(m, bytes);                          // between cycles: configuration, history,
//   ...                                           // context, timers, timeouts, time
//   cell::machine fresh{cell::chart};
//   if (auto r = bsc::restore(fresh, bytes); !r) std::puts(bsc::to_string(r).c_str());
//
// The format (all integers little-endian, the same on every platform):
//   offset  0  4 bytes  "bscR"
//           4  2 bytes  format version (2; version 1 did not hold pending events and is refused)
//           6  2 bytes  flags (0)
//           8  4 bytes  payload length
//          12  8 bytes  the chart's fingerprint: its states' names, kinds, history, nesting and
//                       order, and its timeout rows' states, places, targets and delays (what
//                       the saved bytes mean)
//          20  8 bytes  the context's fingerprint: each member's name, kind, size and order, at
//                       any depth (a renamed, retyped, added or moved member changes it)
//          28  payload  the machine: one byte per composite (two if one has over 255 children; its active or remembered child: the
//                       configuration and the history), the clock, whether a cycle has run, each
//                       timeout's start, the last outcome, the events it keeps pending (deferred,
//                       and delayed with their ids and due times); then the context member by
//                       member (a channel's pending and current values, a timer's limit, start,
//                       elapsed time, phase and flag; a machine in the context as a machine);
//                       detail/state_bytes.hpp gives every field
//          end-4       CRC-32 (IEEE 802.3) of everything before it
// The size is fixed for a machine type (bsc::saved_size), so a controller can keep its state in a
// static buffer. Restoring checks everything before it changes anything: bytes that are not a
// saved state, of another version, chart or context layout, truncated, extended, corrupted, or
// holding a value no machine can hold (a configuration byte past its composite's children, a flag
// other than 0 or 1, an outcome, a timer's phase or a negative limit) are refused with the reason
// and the byte, and the machine is left as it was. (Within its type any value of a member is
// taken: restore does not know the program's invariants; enums must have a fixed underlying type,
// so that every such value is one of the enum's.) The queue of raised events is not saved: between
// runs it is empty (after the machine halted it may hold events that will never be processed).
// Neither is the exception of a last outcome `failed`, nor the observer, nor transient members
// (bsc::transient).
//
// Opt-in: <bsc/bsc.hpp> does not include it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <bsc/detail/access.hpp>
#include <bsc/detail/bytes.hpp>
#include <bsc/detail/state_bytes.hpp>
#include <bsc/duration.hpp>
#include <bsc/detail/runtime/driver.hpp>

namespace bsc {

/// Why bsc::restore refused bytes (none: it restored them).
enum class restore_error : std::uint8_t {
    none,                 ///< restored
    machine_running,      ///< called from inside one of the machine's guards or actions
    truncated,            ///< the bytes end before the saved state does
    not_saved_state,      ///< the bytes do not begin with bsc's mark "bscR"
    unsupported_version,  ///< written in a format version (or with flags) this library does not read
    trailing_bytes,       ///< more bytes follow the saved state
    corrupted,            ///< the checksum does not match: the bytes changed after saving
    other_chart,          ///< saved from a chart with other states
    other_layout,         ///< saved with another context layout
    invalid_value,        ///< a value no machine can hold (a configuration byte, a flag, an outcome, a timer's state)
};

/// The result of bsc::restore: true when restored; otherwise why not, and the byte at which the
/// problem was found.
struct restore_result {
    restore_error error = restore_error::none;
    std::size_t offset = 0;
    constexpr explicit operator bool() const { return error == restore_error::none; }
    friend constexpr bool operator==(restore_result const&, restore_result const&) = default;
};

/// A sentence for each reason.
constexpr std::string_view to_string(restore_error e) {
    switch (e) {
        case restore_error::none: return "restored";
        case restore_error::machine_running:
            return "the machine is running (restore was called from one of its guards or actions)";
        case restore_error::truncated: return "truncated: the bytes end before the saved state does";
        case restore_error::not_saved_state: return "not a saved bsc machine: the bytes do not begin with \"bscR\"";
        case restore_error::unsupported_version: return "saved in a format version this library does not read";
        case restore_error::trailing_bytes: return "more bytes follow the saved state";
        case restore_error::corrupted: return "corrupted: the checksum does not match";
        case restore_error::other_chart: return "saved from another chart (its states differ)";
        case restore_error::other_layout:
            return "saved with another context layout (members, names, types or order differ)";
        case restore_error::invalid_value: return "a saved value is out of range";
    }
    return "unknown restore_error";
}

/// "corrupted: the checksum does not match (byte 412)"; "restored" when it was.
inline std::string to_string(restore_result const& r) {
    std::string text{to_string(r.error)};
    if (r.error != restore_error::none && r.error != restore_error::machine_running)
        text += " (byte " + std::to_string(r.offset) + ")";
    return text;
}

/// A restore option: continue the machine's time at `now` rather than at the saved time (for a
/// caller whose clock restarted). Every time the machine keeps (its clock, its timeouts' starts,
/// its timers' starts) moves by the same amount, so what had elapsed at the save has elapsed at
/// `now`; the downtime does not count. A machine held in the context continues at `now` too; one
/// that has not run a cycle keeps no time and is restored as saved.
struct resume_at {
    duration now;
};

}  // namespace bsc

namespace bsc::detail::retain {

inline constexpr std::array<char, 4> mark = {'b', 's', 'c', 'R'};
inline constexpr std::uint16_t format_version = 2;
inline constexpr std::size_t header_size = 28;
inline constexpr std::size_t trailer_size = 4;

inline restore_result result_of(byte_reader const& r) {
    switch (r.failure()) {
        case byte_reader::fault::none: return {};
        case byte_reader::fault::truncated: return {restore_error::truncated, r.failed_at()};
        case byte_reader::fault::invalid_value: return {restore_error::invalid_value, r.failed_at()};
        case byte_reader::fault::machine_running: return {restore_error::machine_running, r.failed_at()};
    }
    return {restore_error::invalid_value, r.failed_at()};
}

template <class Machine>
restore_result restore(Machine& m, std::span<std::byte const> bytes, std::optional<duration> resume) {
    static_assert(is_machine<Machine>, "bsc::restore: the argument must be a bsc::machine or bsc::table::machine");
    if (access::running(m)) return {restore_error::machine_running, 0};
    std::size_t const n = bytes.size();
    std::byte const* in = bytes.data();
    for (std::size_t i = 0; i < mark.size(); ++i) {
        if (i >= n) return {restore_error::truncated, n};
        if (in[i] != static_cast<std::byte>(mark[i])) return {restore_error::not_saved_state, i};
    }
    if (n < header_size) return {restore_error::truncated, n};
    if (read_le(in + 4, 2) != format_version || read_le(in + 6, 2) != 0) return {restore_error::unsupported_version, 4};
    std::uint64_t const payload = read_le(in + 8, 4);
    std::uint64_t const total = header_size + payload + trailer_size;
    if (total > n) return {restore_error::truncated, n};
    if (total < n) return {restore_error::trailing_bytes, static_cast<std::size_t>(total)};
    std::size_t const checked = header_size + static_cast<std::size_t>(payload);
    if (read_le(in + checked, 4) != crc32(in, checked)) return {restore_error::corrupted, checked};
    if (read_le(in + 12, 8) != detail::chart_fingerprint(m)) return {restore_error::other_chart, 12};
    if (read_le(in + 20, 8) != detail::layout_fingerprint<Machine>() || payload != detail::machine_size<Machine>())
        return {restore_error::other_layout, 20};

    // First only check every value, then store them: a refusal changes nothing.
    byte_reader check{in, header_size, checked};
    get_machine(check, m, pass{false, {}, {}});
    if (auto const r = result_of(check); !r) return r;
    byte_reader store{in, header_size, checked};
    get_machine(store, m, pass{true, resume, {}});
    return {};
}

}  // namespace bsc::detail::retain

namespace bsc {

/// The number of bytes bsc::save writes for a machine of type Machine (header, payload and
/// checksum): fixed, known at compile time. Fails to compile, with
/// bsc::error::member_not_retainable<T>, if the context holds a member that cannot be saved, and
/// with bsc::error::pending_events_not_encoded<Chart, Event> if the machine can keep an event
/// pending that cannot be.
template <class Machine>
inline constexpr std::size_t saved_size = detail::retain::header_size +
                                          detail::machine_size<Machine>() + detail::retain::trailer_size;

/// Saves the machine into `out`. Returns the bytes written (saved_size<Machine>), or 0 when
/// `out` is shorter than that or the machine is running (save was called from one of its guards
/// or actions, when its state is in flux). Save between dispatches and cycles.
template <class Machine>
std::size_t save(Machine const& m, std::span<std::byte> out) {
    static_assert(detail::is_machine<Machine>, "bsc::save: the argument must be a bsc::machine or bsc::table::machine");
    constexpr std::size_t size = saved_size<Machine>;
    if (out.size() < size || detail::access::running(m)) return 0;
    detail::byte_writer w{out.data()};
    for (char c : detail::retain::mark) w.put(static_cast<unsigned char>(c), 1);
    w.put(detail::retain::format_version, 2);
    w.put(0, 2);
    w.put(detail::machine_size<Machine>(), 4);
    w.put(detail::chart_fingerprint(m), 8);
    w.put(detail::layout_fingerprint<Machine>(), 8);
    detail::put_machine(w, m);
    w.put(detail::crc32(out.data(), w.position()), 4);
    return w.position();
}

/// Saves the machine into a new vector of saved_size<Machine> bytes; empty when the machine is
/// running.
template <class Machine>
std::vector<std::byte> save(Machine const& m) {
    std::vector<std::byte> bytes(saved_size<Machine>);
    bytes.resize(save(m, std::span<std::byte>{bytes}));
    return bytes;
}

/// Restores into `m` a machine that bsc::save saved, with the saved time. Everything is checked
/// before anything changes: on any refusal `m` is left as it was and the result says why.
template <class Machine>
restore_result restore(Machine& m, std::span<std::byte const> bytes) {
    return detail::retain::restore(m, bytes, std::nullopt);
}

/// As restore(m, bytes), continuing the machine's time at `when.now` (bsc::resume_at).
template <class Machine>
restore_result restore(Machine& m, std::span<std::byte const> bytes, resume_at when) {
    return detail::retain::restore(m, bytes, when.now);
}

}  // namespace bsc
