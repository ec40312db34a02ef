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
//           4  2 bytes  format version (1)
//           6  2 bytes  flags (0)
//           8  4 bytes  payload length
//          12  8 bytes  the chart's fingerprint: its states' names, kinds, history, nesting and
//                       order, and its timeout rows' states, places, targets and delays (what
//                       the saved bytes mean)
//          20  8 bytes  the context's fingerprint: each member's name, kind, size and order, at
//                       any depth (a renamed, retyped, added or moved member changes it)
//          28  payload  the machine: one byte per composite (its active or remembered child: the
//                       configuration and the history), the clock, whether a cycle has run, each
//                       timeout's start, the last outcome; then the context member by member
//                       (a channel's pending and current values, a timer's limit, start, elapsed
//                       time, phase and flag; a machine in the context as a machine)
//          end-4       CRC-32 (IEEE 802.3) of everything before it
// The size is fixed for a machine type (bsc::saved_size), so a controller can keep its state in a
// static buffer. Restoring checks everything before it changes anything: bytes that are not a
// saved state, of another version, chart or context layout, truncated, extended, corrupted, or
// holding a value no machine can hold (a configuration byte past its composite's children, a flag
// other than 0 or 1, an outcome, a timer's phase or a negative limit) are refused with the reason
// and the byte, and the machine is left as it was. (Within its type any value of a member is
// taken: restore does not know the program's invariants; enums must have a fixed underlying type,
// so that every such value is one of the enum's.) The internal queue is not saved: between runs it is empty (after the machine halted
// it may hold events that will never be processed). Neither is the exception of a last outcome
// `failed`, nor the observer.
//
// Opt-in: <bsc/bsc.hpp> does not include it.

#include <array>
#include <bit>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/access.hpp>
#include <bsc/detail/member_names.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/model/chart_model.hpp>
#include <bsc/model/layout.hpp>
#include <bsc/outcome.hpp>
#include <bsc/runtime/context_data.hpp>
#include <bsc/runtime/driver.hpp>
#include <bsc/runtime/queue_for.hpp>

namespace bsc {

/// Specialise as true for a context member type that is not saved (a log, a cache, a handle):
/// a restored machine keeps its own value of such members.
template <class T>
inline constexpr bool not_retained = false;

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
        case restore_error::machine_running: return "the machine is running (restore was called from one of its guards or actions)";
        case restore_error::truncated: return "truncated: the bytes end before the saved state does";
        case restore_error::not_saved_state: return "not a saved bsc machine: the bytes do not begin with \"bscR\"";
        case restore_error::unsupported_version: return "saved in a format version this library does not read";
        case restore_error::trailing_bytes: return "more bytes follow the saved state";
        case restore_error::corrupted: return "corrupted: the checksum does not match";
        case restore_error::other_chart: return "saved from another chart (its states differ)";
        case restore_error::other_layout: return "saved with another context layout (members, names, types or order differ)";
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
inline constexpr std::uint16_t format_version = 1;
inline constexpr std::size_t header_size = 28;
inline constexpr std::size_t trailer_size = 4;
inline constexpr std::size_t outcome_count = static_cast<std::size_t>(outcome::unknown_event) + 1;

template <class T>
inline constexpr bool is_chrono_duration = false;
template <class Rep, class Period>
inline constexpr bool is_chrono_duration<std::chrono::duration<Rep, Period>> = true;

// An enum whose every value of the underlying type is a value of the enum: a scoped enum, or one
// declared with `: type` (only those can be list-initialised from an integer). Restoring any
// other from bytes could make a value outside its range.
template <class T>
inline constexpr bool has_fixed_underlying_type = requires { T{std::underlying_type_t<T>{}}; };

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

template <class Machine>
using model_of = chart_model<typename Machine::chart_type>;

// What the saved bytes of a machine mean: its states and where its timeouts are.
template <class Machine>
constexpr std::uint64_t chart_fingerprint() {
    using model = model_of<Machine>;
    using layout = chart_layout<model>;
    constexpr auto const& names = state_names_of<model>;
    fingerprint f;
    f.add(static_cast<std::uint64_t>(model::N));
    for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s) {
        f.add(names[s]);
        f.add(static_cast<std::uint64_t>(model::tree.kinds[s]));
        f.add(static_cast<std::uint64_t>(model::tree.hist[s]));
        f.add(static_cast<std::uint64_t>(model::tree.parent[s] + 1));
    }
    f.add(static_cast<std::uint64_t>(layout::timeout_slots));
    if constexpr (layout::timeout_slots > 0)
        for (int s : layout::timeout_slot_state) f.add(static_cast<std::uint64_t>(s));
    return f.value;
}

// The same, with each timeout row's place among the rows, its target and its delay (a value of
// the chart, not of its type): a timeout row added, removed, moved or given another delay changes
// the meaning of the start times the bytes hold.
template <class Machine>
std::uint64_t chart_fingerprint(Machine const& m) {
    using model = model_of<Machine>;
    using layout = chart_layout<model>;
    fingerprint f{chart_fingerprint<Machine>()};
    auto const delays = access::row_delays(m);
    for (std::size_t row = 0; row < delays.size(); ++row) {
        if (!layout::is_timeout_row(static_cast<int>(row))) continue;
        f.add(row);
        f.add(static_cast<std::uint64_t>(model::rows.target[row] + 2));
        f.add(static_cast<std::uint64_t>(delays[row].count()));
    }
    return f.value;
}

enum class member_kind : std::uint8_t { boolean, signed_integer, unsigned_integer, enumeration, floating, time,
                                        input, output, inout, timer, array, aggregate, machine, skipped };

template <class T>
constexpr std::size_t size_of();

// A member's size; a const member (or a const reference) cannot be restored.
template <class Field>
constexpr std::size_t field_size() {
    if constexpr (std::is_const_v<Field>) {
        detail::report<error::member_not_retainable<Field>>();
        return 0;
    } else {
        return size_of<Field>();
    }
}

template <class Machine>
constexpr std::size_t machine_size() {
    using layout = chart_layout<model_of<Machine>>;
    return static_cast<std::size_t>(model_of<Machine>::tree.slots) + 8 + 1 +
           8 * static_cast<std::size_t>(layout::timeout_slots) + 1 + size_of<typename Machine::context_type>();
}

template <class T>
constexpr std::size_t size_of() {
    if constexpr (not_retained<T>) {
        return 0;
    } else if constexpr (is_machine<T>) {
        if constexpr (keeps_pending_events<chart_model<typename T::chart_type>>())
            detail::report<error::pending_events_not_encoded<typename T::chart_type>>();
        return machine_size<T>();
    } else if constexpr (is_channel<T>) {
        return 2 * size_of<channel_value<T>>();
    } else if constexpr (is_timer<T>) {
        return 3 * 8 + 2;
    } else if constexpr (std::is_same_v<T, bool>) {
        return 1;
    } else if constexpr (std::is_integral_v<T> && sizeof(T) <= 8) {
        return sizeof(T);
    } else if constexpr (std::is_enum_v<T> && has_fixed_underlying_type<T>) {
        return sizeof(T);
    } else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
        return sizeof(T);
    } else if constexpr (is_chrono_duration<T>) {
        return size_of<typename T::rep>();
    } else if constexpr (is_std_array<T>) {
        return std::tuple_size_v<T> * size_of<typename T::value_type>();
    } else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T> && !has_reference_field<T>) {
        return []<class... Fields>(std::tuple<Fields&...>*) {
            return (std::size_t{0} + ... + field_size<Fields>());
        }(static_cast<decltype(tie_fields(std::declval<T&>()))*>(nullptr));
    } else {
        detail::report<error::member_not_retainable<T>>();
        return 0;
    }
}

template <class Machine>
constexpr std::uint64_t layout_fingerprint();

// Adds T's description to f: kind, size, and for composites their parts (members by name).
template <class T>
constexpr void describe(fingerprint& f) {
    if constexpr (not_retained<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::skipped));
    } else if constexpr (is_machine<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::machine));
        f.add(chart_fingerprint<T>());
        f.add(layout_fingerprint<T>());
    } else if constexpr (is_channel<T>) {
        using V = channel_value<T>;
        f.add(static_cast<std::uint64_t>(std::is_same_v<T, input<V>>    ? member_kind::input
                                         : std::is_same_v<T, output<V>> ? member_kind::output
                                                                        : member_kind::inout));
        describe<V>(f);
    } else if constexpr (is_timer<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::timer));
    } else if constexpr (std::is_same_v<T, bool>) {
        f.add(static_cast<std::uint64_t>(member_kind::boolean));
    } else if constexpr (std::is_enum_v<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::enumeration));
        f.add(name_of<T>);
        f.add(sizeof(T));
        f.add(std::is_signed_v<std::underlying_type_t<T>> ? 1 : 0);
    } else if constexpr (std::is_integral_v<T>) {
        f.add(static_cast<std::uint64_t>(std::is_signed_v<T> ? member_kind::signed_integer
                                                               : member_kind::unsigned_integer));
        f.add(sizeof(T));
    } else if constexpr (std::is_floating_point_v<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::floating));
        f.add(sizeof(T));
    } else if constexpr (is_chrono_duration<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::time));
        f.add(static_cast<std::uint64_t>(T::period::num));
        f.add(static_cast<std::uint64_t>(T::period::den));
        describe<typename T::rep>(f);
    } else if constexpr (is_std_array<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::array));
        f.add(std::tuple_size_v<T>);
        describe<typename T::value_type>(f);
    } else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T> && !has_reference_field<T>) {
        f.add(static_cast<std::uint64_t>(member_kind::aggregate));
        [&]<class... Fields>(std::tuple<Fields&...>*) {
            f.add(sizeof...(Fields));
            std::size_t i = 0;
            ((f.add(member_names<T>[i++]), describe<std::remove_cv_t<Fields>>(f)), ...);
        }(static_cast<decltype(tie_fields(std::declval<T&>()))*>(nullptr));
    }
    // Anything else was reported by size_of.
}

template <class Machine>
constexpr std::uint64_t layout_fingerprint() {
    fingerprint f;
    describe<typename Machine::context_type>(f);
    return f.value;
}

class writer {
public:
    explicit writer(std::byte* out) : out_(out) {}
    void put(std::uint64_t v, std::size_t bytes) {
        for (std::size_t i = 0; i < bytes; ++i, v >>= 8) out_[pos_++] = static_cast<std::byte>(v & 0xffu);
    }
    std::size_t position() const { return pos_; }

private:
    std::byte* out_;
    std::size_t pos_ = 0;
};

// A little-endian number of `bytes` (at most 8) bytes.
inline std::uint64_t read_le(std::byte const* p, std::size_t bytes) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

// Reads what writer wrote; the first value out of range is remembered with its position.
class reader {
public:
    reader(std::byte const* in, std::size_t begin, std::size_t end) : in_(in), pos_(begin), end_(end) {}
    std::uint64_t get(std::size_t bytes) {
        if (pos_ + bytes > end_) {  // not reached: the payload's length is checked first
            refuse(restore_error::truncated, end_);
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
        if (v >= limit) refuse(restore_error::invalid_value, at);
        return v < limit ? v : 0;
    }
    void refuse(restore_error e, std::size_t at) {
        if (result_.error == restore_error::none) result_ = {e, at};
    }
    restore_result result() const { return result_; }
    std::size_t position() const { return pos_; }

private:
    std::byte const* in_;
    std::size_t pos_;
    std::size_t end_;
    restore_result result_{};
};

// What a reading pass does with the values: only check them, or also store them, each machine's
// clock continuing at `resume` if given.
struct pass {
    bool apply = false;
    std::optional<duration> resume{};
    duration shift{};  // added to every time the enclosing machine keeps
};

// to - from, saturated.
constexpr duration difference(duration to, duration from) {
    duration::rep d{};
    if (__builtin_sub_overflow(to.count(), from.count(), &d)) return from.count() < 0 ? duration::max() : duration::min();
    return duration{d};
}

template <class T>
void put(writer& w, T const& value);

template <class Machine>
void put_machine(writer& w, Machine const& m) {
    auto& machine = const_cast<Machine&>(m);  // access reads through non-const references too
    for (auto byte : access::configuration(machine).active) w.put(byte, 1);
    w.put(static_cast<std::uint64_t>(access::clock(m).count()), 8);
    w.put(access::clock_started(m) ? 1 : 0, 1);
    for (duration armed : access::armed(machine)) w.put(static_cast<std::uint64_t>(armed.count()), 8);
    w.put(static_cast<std::uint64_t>(access::last_outcome(m)), 1);
    put(w, m.context());
}

template <class T>
void put(writer& w, T const& value) {
    if constexpr (not_retained<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        put_machine(w, value);
    } else if constexpr (is_channel<T>) {
        put(w, value.pending());
        put(w, value.get());
    } else if constexpr (is_timer<T>) {
        w.put(static_cast<std::uint64_t>(value.limit().count()), 8);
        w.put(static_cast<std::uint64_t>(access::timer_started(value).count()), 8);
        w.put(static_cast<std::uint64_t>(value.elapsed().count()), 8);
        w.put(access::timer_phase(value), 1);
        w.put(value.expired() ? 1 : 0, 1);
    } else if constexpr (std::is_same_v<T, bool>) {
        w.put(value ? 1 : 0, 1);
    } else if constexpr (std::is_enum_v<T>) {
        put(w, static_cast<std::underlying_type_t<T>>(value));
    } else if constexpr (std::is_integral_v<T> && sizeof(T) <= 8) {
        w.put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(value)), sizeof(T));
    } else if constexpr (std::is_same_v<T, float>) {
        w.put(std::bit_cast<std::uint32_t>(value), 4);
    } else if constexpr (std::is_same_v<T, double>) {
        w.put(std::bit_cast<std::uint64_t>(value), 8);
    } else if constexpr (is_chrono_duration<T>) {
        put(w, value.count());
    } else if constexpr (is_std_array<T>) {
        for (auto const& element : value) put(w, element);
    } else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T>) {
        for_each_field(value, [&](auto const& field) { put(w, field); });
    }
}

template <class T>
void get(reader& r, T& target, pass const& p);

template <class Machine>
void get_machine(reader& r, Machine& m, pass const& p) {
    using model = model_of<Machine>;
    constexpr auto& tree = model::tree;
    // The children of the composite that owns each configuration byte.
    constexpr auto children_by_slot = [] {
        std::array<int, static_cast<std::size_t>(tree.slots)> children{};
        for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s)
            if (tree.slot[s] >= 0) children[static_cast<std::size_t>(tree.slot[s])] = tree.child_count[s];
        return children;
    }();
    if (access::running(m)) r.refuse(restore_error::machine_running, r.position());  // one held in the context
    auto config = access::configuration(m);
    for (std::size_t k = 0; k < children_by_slot.size(); ++k)
        config.active[k] = static_cast<std::uint8_t>(r.get_below(1, static_cast<std::uint64_t>(children_by_slot[k])));
    auto const clock = duration{static_cast<duration::rep>(r.get(8))};
    bool const started = r.get_below(1, 2) != 0;
    auto armed = access::armed(m);
    for (auto& a : armed) a = duration{static_cast<duration::rep>(r.get(8))};
    auto const last = static_cast<outcome>(r.get_below(1, outcome_count));
    // resume_at: this machine's clock continues at the given time, and what it keeps moves with
    // it. A machine whose clock has not started keeps no time of the caller's: nothing moves.
    pass const own{p.apply, p.resume, started && p.resume ? difference(*p.resume, clock) : duration{}};
    get(r, m.context(), own);
    if (!p.apply) return;
    access::configuration(m) = config;
    access::set_clock(m, shifted(clock, own.shift), started);
    for (std::size_t i = 0; i < armed.size(); ++i) access::armed(m)[i] = shifted(armed[i], own.shift);
    access::set_last_outcome(m, last);
    access::forget_failure(m);  // the exception of a last outcome `failed` is not saved
    access::queue(m).clear();
    access::queue(m).clear_overflow();
}

template <class T>
void get(reader& r, T& target, pass const& p) {
    if constexpr (not_retained<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        get_machine(r, target, p);
    } else if constexpr (is_channel<T>) {
        using V = channel_value<T>;
        // Read into copies, then store both through the channel's own cycle boundary.
        V pending = target.pending();
        V current = target.get();
        pass const into_copies{true, p.resume, p.shift};
        get(r, pending, into_copies);
        get(r, current, into_copies);
        if (!p.apply) return;
        target.set(current);
        access::latch(target);
        access::commit(target);
        target.set(pending);
    } else if constexpr (is_timer<T>) {
        std::size_t const at = r.position();
        auto const limit = duration{static_cast<duration::rep>(r.get(8))};
        auto const started = duration{static_cast<duration::rep>(r.get(8))};
        auto const elapsed = duration{static_cast<duration::rep>(r.get(8))};
        auto const phase = static_cast<std::uint8_t>(r.get_below(1, 3));
        bool const expired = r.get_below(1, 2) != 0;
        // Only what a timer can come to: a limit and an elapsed time not below zero, the flag only
        // while timing (phase 2), no elapsed time while idle or pending.
        constexpr std::uint8_t timing = 2;
        if (limit < duration::zero() || elapsed < duration::zero() || (expired && phase != timing) ||
            (phase != timing && elapsed != duration::zero()))
            r.refuse(restore_error::invalid_value, at);
        if (!p.apply) return;
        access::set_timer_limit(target, limit);
        access::set_timer(target, phase, expired, shifted(started, p.shift), elapsed);
    } else if constexpr (std::is_same_v<T, bool>) {
        bool const v = r.get_below(1, 2) != 0;
        if (p.apply) target = v;
    } else if constexpr (std::is_enum_v<T>) {
        std::underlying_type_t<T> v{};
        get(r, v, pass{true, {}, {}});
        if (p.apply) target = static_cast<T>(v);
    } else if constexpr (std::is_integral_v<T> && sizeof(T) <= 8) {
        // Unsigned to signed is modular (C++20): every saved value comes back exactly.
        auto const v = static_cast<T>(static_cast<std::make_unsigned_t<T>>(r.get(sizeof(T))));
        if (p.apply) target = v;
    } else if constexpr (std::is_same_v<T, float>) {
        auto const v = std::bit_cast<float>(static_cast<std::uint32_t>(r.get(4)));
        if (p.apply) target = v;
    } else if constexpr (std::is_same_v<T, double>) {
        auto const v = std::bit_cast<double>(r.get(8));
        if (p.apply) target = v;
    } else if constexpr (is_chrono_duration<T>) {
        typename T::rep v{};
        get(r, v, pass{true, {}, {}});
        if (p.apply) target = T{v};
    } else if constexpr (is_std_array<T>) {
        for (auto& element : target) get(r, element, p);
    } else if constexpr (std::is_class_v<T> && std::is_aggregate_v<T>) {
        for_each_field(target, [&](auto& field) { get(r, field, p); });
    }
}


template <class Machine>
restore_result restore(Machine& m, std::span<std::byte const> bytes, std::optional<duration> resume) {
    static_assert(is_machine<Machine>, "bsc::restore: the argument must be a bsc::machine or bsc::table_machine");
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
    if (read_le(in + 12, 8) != chart_fingerprint(m)) return {restore_error::other_chart, 12};
    if (read_le(in + 20, 8) != layout_fingerprint<Machine>() || payload != machine_size<Machine>())
        return {restore_error::other_layout, 20};

    // First only check every value, then store them: a refusal changes nothing.
    reader check{in, header_size, checked};
    get_machine(check, m, pass{false, {}, {}});
    if (!check.result()) return check.result();
    reader store{in, header_size, checked};
    get_machine(store, m, pass{true, resume, {}});
    return {};
}

}  // namespace bsc::detail::retain

namespace bsc {

/// The number of bytes bsc::save writes for a machine of type Machine (header, payload and
/// checksum): fixed, known at compile time. Fails to compile, with
/// bsc::error::member_not_retainable<T>, if the context holds a member that cannot be saved.
template <class Machine>
inline constexpr std::size_t saved_size =
    detail::retain::header_size + detail::retain::machine_size<Machine>() + detail::retain::trailer_size;

/// Saves the machine into `out`. Returns the bytes written (saved_size<Machine>), or 0 when
/// `out` is shorter than that or the machine is running (save was called from one of its guards
/// or actions, when its state is in flux). Save between dispatches and cycles.
template <class Machine>
std::size_t save(Machine const& m, std::span<std::byte> out) {
    static_assert(detail::is_machine<Machine>, "bsc::save: the argument must be a bsc::machine or bsc::table_machine");
    constexpr std::size_t size = saved_size<Machine>;
    if (out.size() < size || detail::access::running(m)) return 0;
    detail::retain::writer w{out.data()};
    for (char c : detail::retain::mark) w.put(static_cast<unsigned char>(c), 1);
    w.put(detail::retain::format_version, 2);
    w.put(0, 2);
    w.put(detail::retain::machine_size<Machine>(), 4);
    w.put(detail::retain::chart_fingerprint(m), 8);
    w.put(detail::retain::layout_fingerprint<Machine>(), 8);
    detail::retain::put_machine(w, m);
    w.put(detail::retain::crc32(out.data(), w.position()), 4);
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
