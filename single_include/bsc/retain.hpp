#pragma once
// bsc::save and bsc::restore - retentive state, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/retain.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/retain.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_RETAIN_HPP
#define BSC_SINGLE_INCLUDE_BSC_RETAIN_HPP
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

// begin include/bsc/detail/bytes.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
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
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_BYTES_HPP
// end include/bsc/detail/bytes.hpp
// begin include/bsc/detail/state_bytes.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
// A machine's state as bytes, and the values of its context: what bsc::save writes and
// bsc::restore reads (bsc/retain.hpp), and the values bsc::net sends (net/wire.hpp). Walked by
// the member layer (detail/members.hpp), so that every kind of member is encoded in one place:
//
//   a machine   one byte per composite, two in a chart with a composite of more than 255
//               children (its active or remembered child: the configuration and
//               the history), the clock (8), whether a cycle has run (1), each timeout's start
//               (8 each), the last outcome (1); for a chart that defers: whether the deferred
//               events wait for a retry (1), their number (2) and each of them (an event slot);
//               for a chart that sends delayed events: the queue's clock (8), the number pending
//               (2) and each of them in the order sent: due time (8), id (4), event slot; then
//               the context
//   an event    slot: the event's place among the chart's events plus one (0: none) in 1 byte
//               (2 above 255 events), then its members, padded to the largest event's size
//   a channel   its pending and its current value
//   a timer     limit, start, elapsed time (8 each), phase (1), expired (1)
//   a scalar    bool 1 byte; integers, enums, float, double, durations in their size
//   std::array, aggregate, bsc::fields type: the elements or members in order
// All numbers little-endian. Transient members (bsc::transient) take no bytes.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>


namespace bsc::detail {

inline constexpr std::size_t outcome_count = static_cast<std::size_t>(outcome::unknown_event) + 1;

template <class Machine>
using machine_model = chart_model<typename Machine::chart_type>;

// ---- what a member is to the bytes -----------------------------------------------------------------

// Whether a leaf has a fixed encoding (else the retentive state refuses it).
template <class T>
constexpr bool encodable_leaf() {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (is_transient<U>)
        return true;
    else if constexpr (std::is_const_v<T>)
        return false;  // cannot be restored
    else if constexpr (k == member_kind::enumeration)
        return has_fixed_underlying_type<U>;
    else if constexpr (k == member_kind::time)
        return kind_of<typename U::rep>() != member_kind::opaque;
    else if constexpr (k == member_kind::opaque)
        return std::is_empty_v<U>;  // a tag with constructors holds nothing
    else
        return k != member_kind::unwalkable;
}

// Whether every leaf of T has one, and none is a reference (what lies behind one is not the
// machine's); no error is reported (the pending events' check names the event).
struct encodable_folder {
    using result = bool;
    template <class T>
    constexpr bool leaf() const {
        if constexpr (kind_of<std::remove_cv_t<T>>() == member_kind::channel)
            return encodable_leaf<T>() && fold_type<encodable_folder, channel_value<std::remove_cv_t<T>>>(*this);
        else
            return encodable_leaf<T>();
    }
    template <class T>
    constexpr bool array(bool element) const {
        return element;
    }
    template <class T, std::size_t N>
    constexpr bool record(std::array<bool, N> const& members) const {
        if constexpr (!described_by_fields<T>)
            if (has_reference_field<T>) return false;
        return std::all_of(members.begin(), members.end(), [](bool b) { return b; });
    }
};
template <class T>
inline constexpr bool encodable = fold_type<encodable_folder, T>(encodable_folder{});

template <class Machine>
constexpr std::size_t machine_size();

// The bytes of a value of T; a member that has none is reported (member_not_retainable).
struct size_folder : summing_fold<size_folder> {
    template <class T, member_kind k>
    constexpr std::size_t share() const {
        using U = std::remove_cv_t<T>;
        if constexpr (!encodable_leaf<T>()) {
            detail::report<error::member_not_retainable<T>>();
            return 0;
        } else if constexpr (k == member_kind::machine) {
            return machine_size<U>();
        } else if constexpr (k == member_kind::channel) {
            return 2 * fold<size_folder, channel_value<U>>(*this);
        } else if constexpr (k == member_kind::timer) {
            return 3 * 8 + 2;
        } else if constexpr (k == member_kind::boolean) {
            return 1;
        } else if constexpr (k == member_kind::time) {
            return sizeof(typename U::rep);
        } else if constexpr (k == member_kind::opaque) {
            return 0;  // empty (encodable_leaf)
        } else {
            return sizeof(U);
        }
    }
    template <class T, std::size_t N>
    constexpr std::size_t record(std::array<std::size_t, N> const& members) const {
        if constexpr (!described_by_fields<T>)
            if constexpr (has_reference_field<T>) detail::report<error::member_not_retainable<T>>();
        return summing_fold<size_folder>::record<T>(members);
    }
};
template <class T>
constexpr std::size_t size_of() {
    return fold<size_folder, T>(size_folder{});
}

// ---- the pending events of a machine -----------------------------------------------------------------

// The events that can wait in a machine between calls: every event of the chart but
// bsc::action_failed (which carries an exception, and which no row defers or delays).
// Whether an event that waits in a machine is encoded with its members (retain's bytes, the
// explorer's bits): bsc::action_failed never waits; an event that cannot be encoded is reported
// (pending_events_encodable), and takes no room.
template <class E>
inline constexpr bool encoded_while_pending = !std::is_same_v<E, action_failed> && encodable<E> &&
                                              std::is_default_constructible_v<E>;

template <class Chart, class E>
constexpr bool pending_event_encodable() {
    if constexpr (std::is_same_v<E, action_failed> || encoded_while_pending<E>)
        return true;
    else
        return detail::report<error::pending_events_not_encoded<Chart, E>>();
}
template <class Chart, class... Es>
constexpr bool pending_events_encodable(type_list<Es...>) {
    return ((pending_event_encodable<Chart, Es>() ? 0 : 1) + ... + 0) == 0;
}

template <class Events>
struct event_slot;
template <class... Es>
struct event_slot<type_list<Es...>> {
    static constexpr std::size_t index_bytes = sizeof...(Es) + 1 <= 256 ? 1 : 2;
    template <class E>
    static constexpr std::size_t payload_of() {
        if constexpr (encoded_while_pending<E>)
            return size_of<E>();
        else
            return 0;
    }
    static constexpr std::size_t payload = std::max({std::size_t{0}, payload_of<Es>()...});
    static constexpr std::size_t size = index_bytes + payload;
};

template <class Machine>
struct pending_layout {
    using model = machine_model<Machine>;
    using slot = event_slot<typename model::events>;
    static constexpr bool defers = model::has_deferral;
    static constexpr bool delays = chart_sends_delayed<model>();
    static constexpr bool check() {
        if constexpr (defers || delays)
            return pending_events_encodable<typename Machine::chart_type>(typename model::events{});
        else
            return true;
    }
    static constexpr bool checked = check();
    static constexpr std::size_t deferred_capacity = [] {
        if constexpr (defers)
            return std::remove_cvref_t<decltype(access::deferred(std::declval<Machine&>()))>::capacity();
        else
            return std::size_t{0};
    }();
    static constexpr std::size_t delayed_capacity = [] {
        if constexpr (delays)
            return std::remove_cvref_t<decltype(access::queue(std::declval<Machine&>()))>::slot_count();
        else
            return std::size_t{0};
    }();
    static constexpr std::size_t size = [] {
        if constexpr (defers || delays)
            return (defers ? 1 + 2 + deferred_capacity * slot::size : 0) +
                   (delays ? 8 + 2 + delayed_capacity * (8 + 4 + slot::size) : 0);
        else
            return std::size_t{0};
    }();
};

template <class Machine>
constexpr std::size_t machine_size() {
    using layout = chart_layout<machine_model<Machine>>;
    static_assert(pending_layout<Machine>::checked || true);
    return static_cast<std::size_t>(machine_model<Machine>::tree.slots) *
               sizeof(typename machine_model<Machine>::ordinal_type) +
           8 + 1 + 8 * static_cast<std::size_t>(layout::timeout_slots) + 1 + pending_layout<Machine>::size +
           size_of<typename Machine::context_type>();
}

// ---- fingerprints --------------------------------------------------------------------------------

// What the saved bytes of a machine mean: its states and where its timeouts are.
template <class Machine>
constexpr std::uint64_t chart_fingerprint() {
    using model = machine_model<Machine>;
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
    using model = machine_model<Machine>;
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

template <class Machine>
constexpr std::uint64_t layout_fingerprint();

// A type's description: its kind, size and, for composites, their parts (members by name).
struct describe_folder {
    using result = std::uint64_t;
    template <class T>
    constexpr std::uint64_t leaf() const {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        fingerprint f;
        if constexpr (is_transient<U>) {
            f.add("transient");
        } else {
            f.add(static_cast<std::uint64_t>(k));
            if constexpr (k == member_kind::machine) {
                f.add(chart_fingerprint<U>());
                f.add(layout_fingerprint<U>());
            } else if constexpr (k == member_kind::channel) {
                using V = channel_value<U>;
                f.add(std::is_same_v<U, input<V>> ? 1u : std::is_same_v<U, output<V>> ? 2u : 3u);
                f.add(fold<describe_folder, V>(*this));
            } else if constexpr (k == member_kind::enumeration) {
                f.add(name_of<U>);
                f.add(sizeof(U));
                f.add(std::is_signed_v<std::underlying_type_t<U>> ? 1 : 0);
            } else if constexpr (k == member_kind::time) {
                f.add(static_cast<std::uint64_t>(U::period::num));
                f.add(static_cast<std::uint64_t>(U::period::den));
                f.add(fold<describe_folder, typename U::rep>(*this));
            } else if constexpr (k != member_kind::timer) {
                f.add(sizeof(U));
            }
        }
        return f.value;
    }
    template <class T>
    constexpr std::uint64_t array(std::uint64_t element) const {
        fingerprint f;
        f.add(static_cast<std::uint64_t>(member_kind::array));
        f.add(std::tuple_size_v<T>);
        f.add(element);
        return f.value;
    }
    template <class T, std::size_t N>
    constexpr std::uint64_t record(std::array<std::uint64_t, N> const& members) const {
        fingerprint f;
        f.add(static_cast<std::uint64_t>(member_kind::record));
        f.add(N);
        for (std::size_t i = 0; i < N; ++i) {
            // (A struct with a reference member is refused by size_of: its names are not constants.)
            if constexpr (described_by_fields<T> || !has_reference_field<T>) f.add(names_of<T>()[i]);
            f.add(members[i]);
        }
        return f.value;
    }
};

template <class T>
constexpr std::uint64_t describe() {
    return fold<describe_folder, T>(describe_folder{});
}

template <class Machine>
constexpr std::uint64_t layout_fingerprint() {
    fingerprint f;
    f.add(describe<typename Machine::context_type>());
    using pending = pending_layout<Machine>;
    if constexpr (pending::defers || pending::delays) {
        f.add(pending::deferred_capacity);
        f.add(pending::delayed_capacity);
        // clang-format off
        [&]<class... Es>(type_list<Es...>) {
            // (In order, as a list: a chart may have more events than a fold takes, detail::max_fold.)
            [[maybe_unused]] int const added[] = {
                (f.add(name_of<Es>), f.add(std::is_same_v<Es, action_failed> ? 0 : describe<Es>()), 0)..., 0};
        }(typename machine_model<Machine>::events{});
        // clang-format on
    }
    return f.value;
}

// ---- writing -----------------------------------------------------------------------------------------

template <class Machine>
void put_machine(byte_writer& w, Machine const& m);

struct put_visitor {
    byte_writer& w;
    template <class T>
    void leaf(T const& value, no_name) {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        if constexpr (k == member_kind::machine) {
            put_machine(w, value);
        } else if constexpr (k == member_kind::channel) {
            walk(value.pending(), *this);
            walk(value.get(), *this);
        } else if constexpr (k == member_kind::timer) {
            w.put(static_cast<std::uint64_t>(value.limit().count()), 8);
            w.put(static_cast<std::uint64_t>(access::timer_started(value).count()), 8);
            w.put(static_cast<std::uint64_t>(value.elapsed().count()), 8);
            w.put(access::timer_phase(value), 1);
            w.put(value.expired() ? 1 : 0, 1);
        } else if constexpr (k == member_kind::boolean) {
            w.put(value ? 1 : 0, 1);
        } else if constexpr (k == member_kind::enumeration) {
            using R = std::underlying_type_t<U>;
            w.put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<R>>(static_cast<R>(value))), sizeof(U));
        } else if constexpr (k == member_kind::signed_integer || k == member_kind::unsigned_integer) {
            w.put(static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<U>>(value)), sizeof(U));
        } else if constexpr (std::is_same_v<U, float>) {
            w.put(std::bit_cast<std::uint32_t>(value), 4);
        } else if constexpr (std::is_same_v<U, double>) {
            w.put(std::bit_cast<std::uint64_t>(value), 8);
        } else if constexpr (k == member_kind::time) {
            leaf(value.count(), no_name{});
        }
        // (opaque and unwalkable members are refused by size_of before anything is written)
    }
};

template <class T>
void put(byte_writer& w, T const& value) {
    put_visitor v{w};
    walk(value, v);
}

// An event slot: the event's place plus one, its members, zeros up to the slot's size.
template <class Events, class Item>
void put_event(byte_writer& w, Item const& item) {
    using slot = event_slot<Events>;
    std::size_t const end = w.position() + slot::size;
    w.put(item.index(), slot::index_bytes);
    std::visit(
        [&]<class E>(E const& e) {
            if constexpr (!std::is_same_v<E, std::monostate> && !std::is_same_v<E, action_failed>) put(w, e);
        },
        item);
    while (w.position() < end) w.put(0, 1);
}

template <class Machine>
void put_pending(byte_writer& w, Machine const& m) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    auto& machine = const_cast<Machine&>(m);  // access reads through non-const references too
    if constexpr (pending::defers) {
        auto const& deferred = access::deferred(machine);
        w.put(access::deferral_pending_retry(m) && deferred.size() > 0 ? 1 : 0, 1);
        w.put(deferred.size(), 2);
        deferred.for_each_held([&](auto const& item) { put_event<events>(w, item); });
        for (std::size_t i = deferred.size(); i < pending::deferred_capacity; ++i)
            for (std::size_t b = 0; b < pending::slot::size; ++b) w.put(0, 1);
    }
    if constexpr (pending::delays) {
        auto const& queue = access::queue(machine);
        w.put(static_cast<std::uint64_t>(queue.clock().count()), 8);
        std::size_t const count = queue.scheduled();
        w.put(count, 2);
        queue.for_each_scheduled([&](duration due, int id, auto const& item) {
            w.put(static_cast<std::uint64_t>(due.count()), 8);
            w.put(static_cast<std::uint32_t>(id), 4);
            put_event<events>(w, item);
        });
        for (std::size_t i = count; i < pending::delayed_capacity; ++i)
            for (std::size_t b = 0; b < 8 + 4 + pending::slot::size; ++b) w.put(0, 1);
    }
}

template <class Machine>
void put_machine(byte_writer& w, Machine const& m) {
    auto& machine = const_cast<Machine&>(m);  // access reads through non-const references too
    for (auto ordinal : access::configuration(machine).active) w.put(ordinal, sizeof(ordinal));
    w.put(static_cast<std::uint64_t>(access::clock(m).count()), 8);
    w.put(access::clock_started(m) ? 1 : 0, 1);
    for (duration armed : access::armed(machine)) w.put(static_cast<std::uint64_t>(armed.count()), 8);
    w.put(static_cast<std::uint64_t>(access::last_outcome(m)), 1);
    put_pending(w, m);
    put(w, m.context());
}

// ---- reading -------------------------------------------------------------------------------------------

// What a reading pass does with the values: only check them, or also store them, each machine's
// clock continuing at `resume` if given.
struct pass {
    bool apply = false;
    std::optional<duration> resume{};
    duration shift{};  // added to every time the enclosing machine keeps
};

template <class Machine>
void get_machine(byte_reader& r, Machine& m, pass const& p);

struct get_visitor {
    byte_reader& r;
    pass const& p;
    template <class T>
    void leaf(T& target, no_name) {
        using U = std::remove_cv_t<T>;
        constexpr member_kind k = kind_of<U>();
        if constexpr (k == member_kind::machine) {
            get_machine(r, target, p);
        } else if constexpr (k == member_kind::channel) {
            using V = channel_value<U>;
            // Read into copies, then store both at once.
            V pending = target.pending();
            V current = target.get();
            pass const into_copies{true, p.resume, p.shift};
            get_visitor copies{r, into_copies};
            walk(pending, copies);
            walk(current, copies);
            if (!p.apply) return;
            access::set_channel(target, current, pending);
        } else if constexpr (k == member_kind::timer) {
            std::size_t const at = r.position();
            auto const limit = duration{static_cast<duration::rep>(r.get(8))};
            auto const started = duration{static_cast<duration::rep>(r.get(8))};
            auto const elapsed = duration{static_cast<duration::rep>(r.get(8))};
            auto const phase = static_cast<std::uint8_t>(r.get_below(1, 3));
            bool const expired = r.get_below(1, 2) != 0;
            // Only what a timer can come to: a limit and an elapsed time not below zero, the flag
            // only while timing (phase 2), no elapsed time while idle or pending.
            constexpr std::uint8_t timing = 2;
            if (limit < duration::zero() || elapsed < duration::zero() || (expired && phase != timing) ||
                (phase != timing && elapsed != duration::zero()))
                r.refuse(byte_reader::fault::invalid_value, at);
            if (!p.apply) return;
            access::set_timer_limit(target, limit);
            access::set_timer(target, phase, expired, shifted(started, p.shift), elapsed);
        } else if constexpr (k == member_kind::boolean) {
            bool const v = r.get_below(1, 2) != 0;
            if (p.apply) target = v;
        } else if constexpr (k == member_kind::enumeration) {
            using R = std::underlying_type_t<U>;
            auto const v = static_cast<R>(static_cast<std::make_unsigned_t<R>>(r.get(sizeof(U))));
            if (p.apply) target = static_cast<U>(v);
        } else if constexpr (k == member_kind::signed_integer || k == member_kind::unsigned_integer) {
            // Unsigned to signed is modular (C++20): every saved value comes back exactly.
            auto const v = static_cast<U>(static_cast<std::make_unsigned_t<U>>(r.get(sizeof(U))));
            if (p.apply) target = v;
        } else if constexpr (std::is_same_v<U, float>) {
            auto const v = std::bit_cast<float>(static_cast<std::uint32_t>(r.get(4)));
            if (p.apply) target = v;
        } else if constexpr (std::is_same_v<U, double>) {
            auto const v = std::bit_cast<double>(r.get(8));
            if (p.apply) target = v;
        } else if constexpr (k == member_kind::time) {
            typename U::rep v{};
            pass const into_copy{true, {}, {}};
            get_visitor copy{r, into_copy};
            copy.leaf(v, no_name{});
            if (p.apply) target = U{v};
        }
    }
};

template <class T>
void get(byte_reader& r, T& target, pass const& p) {
    get_visitor v{r, p};
    walk(target, v);
}

// Reads an event slot; the event, or std::monostate for an empty slot. A place past the chart's
// events, or one of an event that never waits (bsc::action_failed), is refused.
template <class Events, class Item>
Item get_event(byte_reader& r) {
    using slot = event_slot<Events>;
    std::size_t const end = r.position() + slot::size;
    std::size_t const at = r.position();
    auto const index = static_cast<std::size_t>(r.get_below(slot::index_bytes, std::variant_size_v<Item>));
    Item item{};
    visit_index<static_cast<int>(std::variant_size_v<Item>)>(static_cast<int>(index), [&](auto i) {
        using E = std::variant_alternative_t<decltype(i)::value, Item>;
        if constexpr (std::is_same_v<E, action_failed>) {
            r.refuse(byte_reader::fault::invalid_value, at);
        } else if constexpr (!std::is_same_v<E, std::monostate>) {
            if constexpr (std::is_default_constructible_v<E>) {
                E e{};
                get(r, e, pass{true, {}, {}});
                item.template emplace<decltype(i)::value>(e);
            } else {
                r.refuse(byte_reader::fault::invalid_value, at);
            }
        }
    });
    r.skip_to(end);
    return item;
}

template <class Machine>
void get_pending(byte_reader& r, Machine& m, pass const& p, duration shift) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    if constexpr (pending::defers) {
        auto& deferred = access::deferred(m);
        using item_type = typename std::remove_cvref_t<decltype(deferred)>::value_type;
        bool const retry = r.get_below(1, 2) != 0;
        std::size_t const at = r.position();
        auto const count = static_cast<std::size_t>(r.get_below(2, pending::deferred_capacity + 1));
        std::array<item_type, pending::deferred_capacity> items{};
        for (std::size_t i = 0; i < pending::deferred_capacity; ++i) {
            items[i] = get_event<events, item_type>(r);
            if ((i < count) == (items[i].index() == 0)) r.refuse(byte_reader::fault::invalid_value, at);
        }
        if (p.apply) {
            deferred.clear();
            deferred.clear_overflow();
            for (std::size_t i = 0; i < count; ++i) (void)deferred.push_item(items[i]);
            access::set_deferral_pending_retry(m, retry);
        }
    }
    if constexpr (pending::delays) {
        auto& queue = access::queue(m);
        using item_type = typename std::remove_cvref_t<decltype(queue)>::value_type;
        auto const clock = duration{static_cast<duration::rep>(r.get(8))};
        std::size_t const at = r.position();
        auto const count = static_cast<std::size_t>(r.get_below(2, pending::delayed_capacity + 1));
        struct scheduled {
            duration due;
            int id;
            item_type item;
        };
        std::array<scheduled, pending::delayed_capacity> items{};
        for (std::size_t i = 0; i < pending::delayed_capacity; ++i) {
            items[i].due = duration{static_cast<duration::rep>(r.get(8))};
            items[i].id = static_cast<int>(static_cast<std::uint32_t>(r.get(4)));
            items[i].item = get_event<events, item_type>(r);
            if ((i < count) == (items[i].item.index() == 0)) r.refuse(byte_reader::fault::invalid_value, at);
        }
        if (p.apply) {
            queue.clear_scheduled();
            queue.set_clock(shifted(clock, shift));
            // (Moved past duration::max() by resume_at, an event never comes due: not kept, as
            // detail/runtime/delayed_events.hpp keeps none such.)
            for (std::size_t i = 0; i < count; ++i)
                if (!shifted_past_max(items[i].due, shift))
                    (void)queue.put_scheduled(shifted(items[i].due, shift), items[i].id, items[i].item);
        }
    }
}

template <class Machine>
void get_machine(byte_reader& r, Machine& m, pass const& p) {
    using model = machine_model<Machine>;
    constexpr auto& tree = model::tree;
    // The children of the composite that owns each configuration byte.
    constexpr auto children_by_slot = [] {
        std::array<int, static_cast<std::size_t>(tree.slots)> children{};
        for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s)
            if (tree.slot[s] >= 0) children[static_cast<std::size_t>(tree.slot[s])] = tree.child_count[s];
        return children;
    }();
    if (access::running(m)) r.refuse(byte_reader::fault::machine_running, r.position());  // one held in the context
    auto config = access::configuration(m);
    for (std::size_t k = 0; k < children_by_slot.size(); ++k)
        config.active[k] = static_cast<typename decltype(config)::ordinal_type>(
            r.get_below(sizeof(config.active[k]), static_cast<std::uint64_t>(children_by_slot[k])));
    auto const clock = duration{static_cast<duration::rep>(r.get(8))};
    bool const started = r.get_below(1, 2) != 0;
    auto armed = access::armed(m);
    for (auto& a : armed) a = duration{static_cast<duration::rep>(r.get(8))};
    auto const last = static_cast<outcome>(r.get_below(1, outcome_count));
    // resume_at: this machine's clock continues at the given time, and what it keeps moves with
    // it. A machine whose clock has not started keeps no time of the caller's: nothing moves.
    pass const own{p.apply, p.resume, started && p.resume ? difference(*p.resume, clock) : duration{}};
    get_pending(r, m, p, own.shift);
    get(r, access::context(m), own);
    if (!p.apply) return;
    access::configuration(m) = config;
    access::set_clock(m, shifted(clock, own.shift), started);
    for (std::size_t i = 0; i < armed.size(); ++i) access::armed(m)[i] = shifted(armed[i], own.shift);
    access::set_last_outcome(m, last);
    access::forget_failure(m);  // the exception of a last outcome `failed` is not saved
    access::queue(m).clear();   // raised events: none between runs
    access::queue(m).clear_overflow();
}

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_STATE_BYTES_HPP
// end include/bsc/detail/state_bytes.hpp

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
#endif  // BSC_SINGLE_INCLUDE_BSC_RETAIN_HPP
// end include/bsc/retain.hpp
