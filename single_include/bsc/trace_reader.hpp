#pragma once
// bsc::trace_reader - the trace stream read back, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/trace_reader.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/trace_reader.hpp
// bsc::trace_reader: reads a trace stream (docs/trace.md) back, from a file or a socket, in
// pieces of any size: the frames whose checksum holds, in order, with the chart's dictionary
// gathered on the way, a count of the frames a gap in the sequence numbers says were lost, and
// of the bytes skipped to find the next frame after damage. Any input is safe to feed: a reader
// never trusts a length or a number it has not checked.
//
//   bsc::trace_reader reader;
//   reader.feed(bytes);
//   while (auto record = reader.next()) std::cout << reader.describe(*record) << '\n';

#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// begin include/bsc/detail/delay_label.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// A duration as short exact text, for the exports' timeout labels and the logger's times.

#include <string>


namespace bsc::detail {

/// "3s", "250ms", "20us" or "7ns": the largest unit that divides the delay.
inline std::string delay_label(std::chrono::nanoseconds d) {
    auto const n = d.count();
    if (n % 1'000'000'000 == 0) return std::to_string(n / 1'000'000'000) + "s";
    if (n % 1'000'000 == 0) return std::to_string(n / 1'000'000) + "ms";
    if (n % 1'000 == 0) return std::to_string(n / 1'000) + "us";
    return std::to_string(n) + "ns";
}

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// end include/bsc/detail/delay_label.hpp
// begin include/bsc/detail/trace/format.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
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
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
// end include/bsc/detail/trace/format.hpp

namespace bsc {

/// The kinds of record: detail::trace::record_type, whose comments give each payload.
using trace_record_type = detail::trace::record_type;

/// One member's new value in a values record: its number and its bits (a real's as
/// std::bit_cast<std::uint64_t>(double), a signed integer's two's complement).
struct trace_value {
    std::uint16_t member = 0;
    std::uint64_t bits = 0;
};

/// One record as read. The fields a record type does not carry keep their defaults.
struct trace_record {
    static constexpr std::uint16_t none = detail::trace::no_number;
    trace_record_type type = trace_record_type::hello;
    std::uint16_t sequence = 0;
    /// dispatch, cycle, values: the record's time; others: the last time read before them.
    duration time{};
    std::uint16_t state = none;   ///< exit, entry, deferral; the number a state record names
    std::uint16_t source = none;  ///< transition
    std::uint16_t target = none;  ///< transition; none for an internal transition
    std::uint16_t event = none;   ///< dispatch, transition, deferral; the number an event record names
    std::uint16_t row = none;     ///< transition: the row's position in make_chart
    std::uint16_t member = none;  ///< the number a member record names
    // (a row record names r.row)
    duration delay{};                 ///< transition on a timeout: its delay
    std::uint64_t dropped = 0;        ///< overflow: the frames the writer dropped so far
    std::vector<trace_value> values;  ///< values
    /// configuration: the active states it lists; `begins` whether a configuration begins with
    /// them (else they add to the last one's, which had more states than a record holds)
    std::vector<std::uint16_t> active;
    bool begins = false;
    /// Whether the transition's trigger is an eventless row (then `event` is not an event's number).
    bool eventless() const { return event == detail::trace::eventless_trigger; }
    /// Whether the transition's trigger is a timeout (its delay in `delay`).
    bool timeout() const { return event == detail::trace::timeout_trigger; }
};

/// The names a stream's dictionary gave, by number.
struct trace_dictionary {
    struct state_entry {
        std::string name;
        std::uint16_t parent = trace_record::none;
        std::uint8_t kind = 0;  ///< bsc::detail::kind: 0 top, 1 basic, 2 final, 3 composite, 4 parallel, 5 history
    };
    struct member_entry {
        std::string name;       ///< the dotted path in the context: "axis.position", "dwell.running"
        std::uint8_t kind = 0;  ///< 0 bool, 1 signed integer, 2 unsigned integer or enum, 3 real
        std::uint8_t width = 0;
    };
    struct row_entry {
        std::uint16_t source = trace_record::none;
        std::uint16_t target = trace_record::none;   ///< none: an internal transition
        std::uint16_t trigger = trace_record::none;  ///< an event's number, or 0xFFFE eventless, 0xFFFD timeout
        std::uint8_t flags = 0;                      ///< 1: the row defers its event; 2: a local transition
        std::string label;                           ///< "event [guard] / action", as the exports write it
    };
    unsigned version = 0;  ///< the hello's format version (0: no hello read)
    std::string chart;     ///< the root state's name
    std::vector<state_entry> states;
    std::vector<std::string> events;
    std::vector<row_entry> rows;  ///< by row number (a position in make_chart); only transitions have a label
    std::vector<member_entry> members;

    /// A state's name, or "#n" if the dictionary has none for it.
    std::string state_name(std::uint16_t n) const {
        return n < states.size() && !states[n].name.empty() ? states[n].name : "#" + std::to_string(n);
    }
    /// An event's name, or "#n" if the dictionary has none for it.
    std::string event_name(std::uint16_t n) const {
        return n < events.size() && !events[n].empty() ? events[n] : "#" + std::to_string(n);
    }
    /// A member's name, or "#n".
    std::string member_name(std::uint16_t n) const {
        return n < members.size() && !members[n].name.empty() ? members[n].name : "#" + std::to_string(n);
    }
    /// A member's value as text, by its kind: "true", "-3", "42", "0.5".
    std::string value_text(trace_value const& v) const {
        std::uint8_t const kind = v.member < members.size() ? members[v.member].kind : 2;
        std::uint8_t const width = v.member < members.size() ? members[v.member].width : 64;
        char text[40];
        std::to_chars_result r{};
        if (kind == 0 && v.bits <= 1) return v.bits ? "true" : "false";
        if (kind == 3) {
            r = std::to_chars(text, text + sizeof text, std::bit_cast<double>(v.bits));
        } else if (kind == 1) {
            // Sign-extended from the member's width.
            std::uint64_t bits = v.bits;
            if (width > 0 && width < 64 && (bits >> (width - 1) & 1u)) bits |= ~std::uint64_t{0} << width;
            r = std::to_chars(text, text + sizeof text, static_cast<std::int64_t>(bits));
        } else {
            r = std::to_chars(text, text + sizeof text, v.bits);
        }
        return std::string(text, r.ptr);
    }
};

/// Reads frames out of the bytes fed to it; see the top of this header.
class trace_reader {
public:
    /// Appends bytes of the stream (any piece: a frame may be cut anywhere).
    void feed(std::span<std::byte const> bytes) {
        if (start_ > 0 && start_ * 2 >= pending_.size()) {
            pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(start_));
            start_ = 0;
        }
        pending_.insert(pending_.end(), bytes.begin(), bytes.end());
    }

    /// Says that no more bytes will come (the end of a file): a frame begun at the end can no
    /// longer be completed, so next() skips its first byte and reads on instead of waiting.
    void finish() { finished_ = true; }

    /// The next whole frame whose checksum holds, or nothing until more bytes are fed. Bytes
    /// that start no valid frame are skipped (skipped_bytes()); a frame whose payload does not
    /// fit its type is dropped (malformed()).
    std::optional<trace_record> next() {
        namespace t = detail::trace;
        for (;;) {
            while (start_ < pending_.size() && pending_[start_] != t::sync) skip();
            if (pending_.size() - start_ < t::header_size) {
                if (!finished_ || start_ == pending_.size()) return std::nullopt;
                skip();
                continue;
            }
            std::byte const* frame = pending_.data() + start_;
            std::size_t const length = static_cast<std::size_t>(frame[4]);
            std::size_t const size = t::header_size + length + t::trailer_size;
            if (pending_.size() - start_ < size) {
                if (!finished_) return std::nullopt;
                skip();
                continue;
            }
            std::uint16_t const expected = t::get<std::uint16_t>(frame + t::header_size + length);
            if (t::crc(std::span<std::byte const>{frame + 1, 4 + length}) != expected) {
                skip();
                continue;
            }
            start_ += size;
            ++frames_;
            auto const sequence = t::get<std::uint16_t>(frame + 2);
            if (sequenced_) missing_ += static_cast<std::uint16_t>(sequence - next_sequence_);
            next_sequence_ = static_cast<std::uint16_t>(sequence + 1);
            sequenced_ = true;
            if (auto record = decode(static_cast<t::record_type>(frame[1]), sequence, frame + t::header_size, length))
                return record;
            ++malformed_;
        }
    }

    /// The dictionary read so far.
    trace_dictionary const& dictionary() const { return dictionary_; }
    /// The frames read whose checksum held.
    std::uint64_t frames() const { return frames_; }
    /// The frames the gaps in the sequence numbers say were lost between the writer and this reader.
    std::uint64_t missing() const { return missing_; }
    /// The bytes skipped because they started no valid frame.
    std::uint64_t skipped_bytes() const { return skipped_; }
    /// The frames with a valid checksum but an unknown type or a payload that does not fit it.
    std::uint64_t malformed() const { return malformed_; }

    /// The record as one line, with the dictionary's names: "[1500ms] transition Idle -> Busy
    /// on go (row 3)", "[2s] values speed=3 running=true".
    std::string describe(trace_record const& r) const {
        auto const& d = dictionary_;
        std::string line = "[" + detail::delay_label(r.time) + "] ";
        switch (r.type) {
            case trace_record_type::hello: return line + "chart " + d.chart;
            case trace_record_type::state:
                return line + "state " + std::to_string(r.state) + " " + d.state_name(r.state);
            case trace_record_type::event:
                return line + "event " + std::to_string(r.event) + " " + d.event_name(r.event);
            case trace_record_type::row: {
                if (r.row >= d.rows.size()) return line + "row " + std::to_string(r.row);
                auto const& row = d.rows[r.row];
                return line + "row " + std::to_string(r.row) + " " + d.state_name(row.source) + " -> " +
                       (row.target == trace_record::none ? std::string{"internal"} : d.state_name(row.target)) +
                       (row.label.empty() ? "" : " : " + row.label);
            }
            case trace_record_type::member:
                return line + "member " + std::to_string(r.member) + " " + d.member_name(r.member);
            case trace_record_type::dispatch: return line + "dispatch " + d.event_name(r.event);
            case trace_record_type::cycle: return line + "cycle";
            case trace_record_type::cycle_end: return line + "cycle end";
            case trace_record_type::exit: return line + "exit " + d.state_name(r.state);
            case trace_record_type::entry: return line + "entry " + d.state_name(r.state);
            case trace_record_type::transition: {
                line += "transition " + d.state_name(r.source) + " -> " +
                        (r.target == trace_record::none ? std::string{"internal"} : d.state_name(r.target)) + " on ";
                if (r.eventless())
                    line += "condition";
                else if (r.timeout())
                    line += "after(" + detail::delay_label(r.delay) + ")";
                else
                    line += d.event_name(r.event);
                return line + " (row " + std::to_string(r.row) + ")";
            }
            case trace_record_type::deferral:
                return line + "defer " + d.event_name(r.event) + " in " + d.state_name(r.state);
            case trace_record_type::values: {
                line += "values";
                for (auto const& v : r.values) line += " " + d.member_name(v.member) + "=" + d.value_text(v);
                return line;
            }
            case trace_record_type::configuration: {
                line += r.begins ? "configuration" : "configuration (more)";
                for (auto const s : r.active) line += " " + d.state_name(s);
                return line;
            }
            case trace_record_type::overflow:
                return line + "overflow: " + std::to_string(r.dropped) + " frames dropped";
        }
        return line;
    }

private:
    void skip() {
        ++start_;
        ++skipped_;
    }

    // The record a checked frame holds, with the dictionary updated, or nothing if its payload
    // does not fit its type.
    std::optional<trace_record> decode(trace_record_type type, std::uint16_t sequence, std::byte const* p,
                                       std::size_t n) {
        namespace t = detail::trace;
        using u16 = std::uint16_t;
        trace_record r;
        r.type = type;
        r.sequence = sequence;
        r.time = duration{time_};
        auto const text = [&](std::size_t from) {
            return std::string(reinterpret_cast<char const*>(p) + from, n - from);
        };
        auto const at = []<class T>(std::vector<T>& v, std::size_t i) -> T& {
            if (v.size() <= i) v.resize(i + 1);
            return v[i];
        };
        switch (type) {
            case trace_record_type::hello:
                if (n < 7) return std::nullopt;
                dictionary_ = {};
                dictionary_.version = static_cast<unsigned>(p[0]);
                dictionary_.chart = text(7);
                return r;
            case trace_record_type::row: {
                if (n < 9) return std::nullopt;
                r.row = t::get<u16>(p);
                auto& row = at(dictionary_.rows, r.row);
                row.source = t::get<u16>(p + 2);
                row.target = t::get<u16>(p + 4);
                row.trigger = t::get<u16>(p + 6);
                row.flags = static_cast<std::uint8_t>(p[8]);
                row.label = text(9);
                return r;
            }
            case trace_record_type::state: {
                if (n < 5) return std::nullopt;
                r.state = t::get<u16>(p);
                auto& s = at(dictionary_.states, r.state);
                s.parent = t::get<u16>(p + 2);
                s.kind = static_cast<std::uint8_t>(p[4]);
                s.name = text(5);
                return r;
            }
            case trace_record_type::event:
                if (n < 2) return std::nullopt;
                r.event = t::get<u16>(p);
                at(dictionary_.events, r.event) = text(2);
                return r;
            case trace_record_type::member: {
                if (n < 4) return std::nullopt;
                r.member = t::get<u16>(p);
                auto& m = at(dictionary_.members, r.member);
                m.kind = static_cast<std::uint8_t>(p[2]);
                m.width = static_cast<std::uint8_t>(p[3]);
                m.name = text(4);
                return r;
            }
            case trace_record_type::dispatch:
                if (n != 10) return std::nullopt;
                time_ = t::get<std::int64_t>(p);
                r.time = duration{time_};
                r.event = t::get<u16>(p + 8);
                return r;
            case trace_record_type::cycle:
                if (n != 8) return std::nullopt;
                time_ = t::get<std::int64_t>(p);
                r.time = duration{time_};
                return r;
            case trace_record_type::cycle_end: return n == 0 ? std::optional{r} : std::nullopt;
            case trace_record_type::exit:
            case trace_record_type::entry:
                if (n != 2) return std::nullopt;
                r.state = t::get<u16>(p);
                return r;
            case trace_record_type::transition:
                if (n != 8 && n != 16) return std::nullopt;
                r.row = t::get<u16>(p);
                r.source = t::get<u16>(p + 2);
                r.target = t::get<u16>(p + 4);
                r.event = t::get<u16>(p + 6);
                if ((n == 16) != r.timeout()) return std::nullopt;
                if (n == 16) r.delay = duration{t::get<std::int64_t>(p + 8)};
                return r;
            case trace_record_type::deferral:
                if (n != 4) return std::nullopt;
                r.state = t::get<u16>(p);
                r.event = t::get<u16>(p + 2);
                return r;
            case trace_record_type::values:
                if (n < 8 || (n - 8) % 10 != 0) return std::nullopt;
                time_ = t::get<std::int64_t>(p);
                r.time = duration{time_};
                for (std::size_t i = 8; i < n; i += 10)
                    r.values.push_back({t::get<u16>(p + i), t::get<std::uint64_t>(p + i + 2)});
                return r;
            case trace_record_type::configuration:
                if (n < 1 || (n - 1) % 2 != 0 || static_cast<unsigned>(p[0]) > 1) return std::nullopt;
                r.begins = p[0] == std::byte{1};
                for (std::size_t i = 1; i < n; i += 2) r.active.push_back(t::get<u16>(p + i));
                return r;
            case trace_record_type::overflow:
                if (n != 8) return std::nullopt;
                r.dropped = t::get<std::uint64_t>(p);
                return r;
        }
        return std::nullopt;
    }

    std::vector<std::byte> pending_;
    std::size_t start_ = 0;  // the first byte of pending_ not yet read
    trace_dictionary dictionary_;
    std::int64_t time_ = 0;
    std::uint64_t frames_ = 0, missing_ = 0, skipped_ = 0, malformed_ = 0;
    std::uint16_t next_sequence_ = 0;
    bool sequenced_ = false;
    bool finished_ = false;
};

}  // namespace bsc
// end include/bsc/trace_reader.hpp
