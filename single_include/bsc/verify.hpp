#pragma once
// bsc::verify - the state-space explorer, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/verify.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/verify.hpp
// bsc::verify: exhaustive exploration of closed models of bsc machines, and the properties
// checked on it. Not included by <bsc/bsc.hpp>: it uses the heap and the standard library's
// strings and vectors, which the machines themselves never need.

// begin include/bsc/detail/verify/codec.hpp
// Fixed-size bit encodings of explored states, walked by the member layer (detail/members.hpp):
// a machine's configuration bytes, its timeouts, the events it keeps pending (deferred, and
// delayed with their ids and due times), its context member by member; time made relative to
// the machine's clock and counted in cycles, capped where more time changes nothing. Two states
// with equal encodings behave the same. Transient members (bsc::transient) are not encoded:
// decoded states keep the initial value of such members.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

// begin include/bsc/detail/key_field.hpp
// A named part of an explored state's key: where the explorer's codec put a member of a context
// (at any depth), a machine's configuration, timeouts or pending events. What the explorer reports
// when a bound stops it: which parts took the most values.

#include <cstddef>
#include <string>

namespace bsc::detail {

struct encoded_field {
    std::string name;
    std::size_t first_bit = 0;
    std::size_t bits = 0;
};

}  // namespace bsc::detail
// end include/bsc/detail/key_field.hpp
// begin include/bsc/detail/member_path.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
// The dotted name of a member during a named walk of a context (detail/members.hpp): "axis.position",
// "dwell.running". The explorer's codec names the fields of a state with it, the trace names the
// members it samples, and the inspector finds the input a page sets by it. Its own header: the
// machines' walks name nothing and need no strings.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bsc::detail {

class member_path {
public:
    /// Enters the scope `name` (an unnamed one, the walk's root, adds nothing); each is left again
    /// in order.
    void enter(std::string_view name) {
        starts_.push_back(text_.size());
        if (name.empty()) return;
        if (!text_.empty()) text_ += '.';
        text_ += name;
    }
    void leave() {
        if (starts_.empty()) return;
        text_.resize(starts_.back());
        starts_.pop_back();
    }
    /// The full name of the member `name` in the present scope (of "" the scope's own).
    std::string of(std::string_view name) const {
        if (text_.empty()) return std::string{name};
        return name.empty() ? text_ : text_ + "." + std::string{name};
    }
    /// Back to no scope, keeping the memory, so that a walk after the first allocates nothing.
    void clear() {
        text_.clear();
        starts_.clear();
    }

private:
    std::string text_;
    std::vector<std::size_t> starts_;  // text_'s length before each scope entered
};

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
// end include/bsc/detail/member_path.hpp
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

namespace bsc::detail {

// Periods since a timer or timeout started are kept in this many bits. The count is capped
// one period past the longest delay that can still matter, so it never wraps: a model whose
// delays need more periods than fit is refused (time_frame::cycles throws), never explored
// with a counter that would silently restart at zero.
inline constexpr unsigned cycle_bits = 32;
inline constexpr std::uint64_t max_cycles = (std::uint64_t{1} << cycle_bits) - 1;

// Time as the codec sees it: the clock of the enclosing machine and the cycle period
// (zero for models that never step, where time does not pass).
struct time_frame {
    duration clock{};
    duration period{};
    // The whole periods in `since .. clock`, capped at cap + one period.
    std::uint64_t cycles(duration since, duration cap) const {
        if (period <= duration::zero()) return 0;
        auto const d = elapsed(since, clock);
        if (d <= duration::zero()) return 0;
        auto const limit = static_cast<std::uint64_t>(cap / period) + 1;
        if (limit > max_cycles) refuse(cap, limit - 1);
        auto const n = static_cast<std::uint64_t>(d / period);
        return n < limit ? n : limit;
    }
    // The whole periods in `since .. clock`, not capped.
    std::uint64_t periods(duration since) const {
        if (period <= duration::zero()) return 0;
        auto const d = elapsed(since, clock);
        return d <= duration::zero() ? 0 : static_cast<std::uint64_t>(d / period);
    }
    // A delay of more periods than the counter holds: no exploration may rest on a counter that
    // would wrap. Thrown, or printed before aborting where exceptions are disabled.
    [[noreturn]] void refuse(duration delay, std::uint64_t periods) const {
        std::string const why = "bsc::verify: a delay of " + std::to_string(delay.count()) + " ns is " +
                                std::to_string(periods) + " periods of " + std::to_string(period.count()) +
                                " ns, more than the explorer counts (" + std::to_string(max_cycles - 1) +
                                "); explore with a longer period";
#if defined(__cpp_exceptions)
        throw std::length_error(why);
#else
        std::fputs((why + "\n").c_str(), stderr);
        std::abort();
#endif
    }
    // The time `cycles` periods before the clock.
    duration before(std::uint64_t cycles) const { return clock - static_cast<duration::rep>(cycles) * period; }
};

// Keys are bit strings: a flag takes one bit, a composite's byte only the bits its number of
// children needs, so a state of a controller with a dozen flags takes a few bytes.
class bit_writer {
public:
    bit_writer(std::byte* out, std::size_t capacity_bits) : out_(out), capacity_(capacity_bits) {}
    void put(std::uint64_t value, unsigned bits) {
        if (bit_ + bits > capacity_) std::abort();  // never write past the key

        while (bits > 0) {  // a byte (or what is left of it) at a time
            unsigned const offset = bit_ % 8;
            unsigned const n = bits < 8 - offset ? bits : 8 - offset;
            out_[bit_ / 8] |= static_cast<std::byte>((value & ((1u << n) - 1u)) << offset);
            value >>= n;
            bits -= n;
            bit_ += n;
        }
    }
    void put_bytes(void const* data, std::size_t n) {
        auto const* bytes = static_cast<unsigned char const*>(data);
        for (std::size_t k = 0; k < n; ++k) put(bytes[k], 8);
    }

    std::size_t bits() const { return bit_; }

private:
    std::byte* out_;
    std::size_t capacity_;
    std::size_t bit_ = 0;
};

class bit_reader {
public:
    bit_reader(std::byte const* in, std::size_t capacity_bits) : in_(in), capacity_(capacity_bits) {}
    std::uint64_t get(unsigned bits) {
        if (bit_ + bits > capacity_) std::abort();  // never read past the key

        std::uint64_t value = 0;
        for (unsigned done = 0; done < bits;) {
            unsigned const offset = bit_ % 8;
            unsigned const n = bits - done < 8 - offset ? bits - done : 8 - offset;
            std::uint64_t const chunk = (static_cast<unsigned>(in_[bit_ / 8]) >> offset) & ((1u << n) - 1u);
            value |= chunk << done;
            done += n;
            bit_ += n;
        }
        return value;
    }
    void get_bytes(void* data, std::size_t n) {
        auto* bytes = static_cast<unsigned char*>(data);
        for (std::size_t k = 0; k < n; ++k) bytes[k] = static_cast<unsigned char>(get(8));
    }

    std::size_t bits() const { return bit_; }

private:
    std::byte const* in_;
    std::size_t capacity_;
    std::size_t bit_ = 0;
};

// Sorts [first, last) by `less`, equal elements kept in their order: an insertion sort, for the
// few elements the codec orders (a state's timeouts, the delayed events pending). Not std::sort:
// GCC 12 at -O2 and above warns of a subscript out of bounds inside it when it sorts part of an
// array of two (-Warray-bounds); not std::stable_sort: it allocates.
template <class It, class Less>
constexpr void sort_few(It first, It last, Less less) {
    for (It i = first; i != last; ++i)
        for (It j = i; j != first && less(*j, *(j - 1)); --j) std::swap(*j, *(j - 1));
}

constexpr unsigned bits_for(int values) {
    unsigned bits = 0;
    while ((1 << bits) < values) ++bits;
    return bits;
}

// The bits of each composite's byte, by slot: enough for its number of children.
template <class M>
constexpr auto slot_bits() {
    using model = bsc::detail::chart_model<typename M::chart_type>;
    std::array<unsigned, static_cast<std::size_t>(model::tree.slots)> bits{};
    for (std::size_t s = 0; s < static_cast<std::size_t>(model::N); ++s)
        if (model::tree.slot[s] >= 0)
            bits[static_cast<std::size_t>(model::tree.slot[s])] = bits_for(model::tree.child_count[s]);
    return bits;
}

// The bits of a value of T (a member the explorer cannot encode is reported).
template <class Machine>
constexpr std::size_t machine_bits();

struct bits_folder : summing_fold<bits_folder> {
    template <class T, member_kind k>
    constexpr std::size_t share() const {
        using U = std::remove_cv_t<T>;
        if constexpr (k == member_kind::machine) {
            return machine_bits<U>();
        } else if constexpr (k == member_kind::timer) {
            return 2 + 1 + cycle_bits;  // phase, expired, periods since timing began
        } else if constexpr (k == member_kind::boolean) {
            return 1;
        } else if constexpr (k == member_kind::channel) {
            return 2 * fold<bits_folder, channel_value<U>>(*this);  // pending and current values
        } else if constexpr (k == member_kind::unwalkable) {
            return 0;  // reported by the member layer
        } else if constexpr (k == member_kind::opaque && std::is_empty_v<U>) {
            return 0;  // a tag holds nothing
        } else if constexpr (k == member_kind::opaque && !std::is_trivially_copyable_v<U>) {
            detail::report<error::member_not_explorable<U>>();
            return 0;
        } else {
            return 8 * sizeof(U);
        }
    }
};

template <class T>
constexpr std::size_t encoded_bits() {
    return fold<bits_folder, T>(bits_folder{});
}

// The bits of an event slot: the event's place plus one (0: none), then the largest event's.
template <class Events>
struct event_bits;
template <class... Es>
struct event_bits<type_list<Es...>> {
    static constexpr unsigned index = bits_for(static_cast<int>(sizeof...(Es)) + 1);
    template <class E>
    static constexpr std::size_t payload_of() {
        if constexpr (encoded_while_pending<E>)
            return encoded_bits<E>();
        else
            return 0;
    }
    static constexpr std::size_t payload = std::max({std::size_t{0}, payload_of<Es>()...});
    static constexpr std::size_t size = index + payload;
};

template <class Machine>
constexpr std::size_t pending_bits() {
    using pending = pending_layout<Machine>;
    using slot = event_bits<typename machine_model<Machine>::events>;
    std::size_t bits = 0;
    if constexpr (pending::defers)
        bits += 1 + bits_for(static_cast<int>(pending::deferred_capacity) + 1) +
                pending::deferred_capacity * slot::size;
    if constexpr (pending::delays)
        bits += bits_for(static_cast<int>(pending::delayed_capacity) + 1) +
                pending::delayed_capacity * (64 + 32 + slot::size);
    return bits;
}

template <class Machine>
constexpr std::size_t machine_bits() {
    static_assert(pending_layout<Machine>::checked || true);
    std::size_t config = 0;
    for (unsigned b : slot_bits<Machine>()) config += b;
    constexpr std::size_t timeouts = std::remove_cvref_t<decltype(access::armed(std::declval<Machine&>()))>{}.size();
    return config + cycle_bits * timeouts + pending_bits<Machine>() + encoded_bits<typename Machine::context_type>();
}

template <class T>
constexpr std::size_t encoded_size() {
    return (encoded_bits<T>() + 7) / 8;
}

template <class V>
void encode_value(V const& v, bit_writer& out) {
    if constexpr (std::is_same_v<V, bool>)
        out.put(v ? 1u : 0u, 1);
    else if constexpr (!std::is_empty_v<V>)
        out.put_bytes(&v, sizeof(V));
}
template <class V>
V decode_value(bit_reader& in) {
    if constexpr (std::is_same_v<V, bool>) {
        return in.get(1) != 0;
    } else if constexpr (std::is_empty_v<V>) {
        return V{};
    } else {
        V v;
        in.get_bytes(&v, sizeof(V));
        return v;
    }
}

// Writes a state's bits. With a list of fields, also records where each named leaf lies (names
// joined by '.', array elements as name[i]).
struct encode_visitor {
    bit_writer& out;
    time_frame frame;
    std::vector<encoded_field>* fields = nullptr;
    member_path path{};

    static constexpr bool named = true;
    std::string element_name(std::string_view name, std::size_t i) const {
        return std::string{name} + "[" + std::to_string(i) + "]";
    }
    void enter(std::string_view name) { path.enter(name); }
    void leave() { path.leave(); }
    void record(std::string_view name, std::size_t first) {
        if (fields != nullptr && out.bits() > first) fields->push_back({path.of(name), first, out.bits() - first});
    }

    template <class T, class Name>
    void leaf(T const& value, Name const& name);
};

template <class Machine>
void encode_machine(Machine const& value, encode_visitor& v);

template <class T, class Name>
void encode_visitor::leaf(T const& value, Name const& name) {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    std::size_t const first = out.bits();
    if constexpr (k == member_kind::machine) {
        enter(name);
        encode_machine(value, *this);
        leave();
        return;
    } else if constexpr (k == member_kind::timer) {
        out.put(access::timer_phase(value), 2);
        out.put(value.expired() ? 1u : 0u, 1);
        bool const timing = access::timer_phase(value) == 2;  // running, expired or not
        out.put(timing ? frame.cycles(access::timer_started(value), value.limit()) : 0, cycle_bits);
    } else if constexpr (k == member_kind::channel) {
        encode_visitor quiet{out, frame};  // a channel of an aggregate: member by member too
        walk(value.pending(), quiet, std::string_view{});
        walk(value.get(), quiet, std::string_view{});
    } else {
        encode_value(value, out);
    }
    record(name, first);
}

template <class T>
void encode(T const& value, bit_writer& out, time_frame frame, std::vector<encoded_field>* fields = nullptr) {
    encode_visitor v{out, frame, fields};
    walk(value, v, std::string_view{});
}

template <class Events, class Item>
void encode_event(Item const& item, bit_writer& out, time_frame frame) {
    using slot = event_bits<Events>;
    std::size_t const end = out.bits() + slot::size;
    out.put(item.index(), slot::index);
    std::visit(
        [&]<class E>(E const& e) {
            if constexpr (!std::is_same_v<E, std::monostate> && !std::is_same_v<E, action_failed>)
                encode(e, out, frame);
        },
        item);
    while (out.bits() < end) out.put(0, static_cast<unsigned>(std::min<std::size_t>(end - out.bits(), 32)));
}

inline void skip_bits(bit_writer& out, std::size_t n) {
    while (n > 0) {
        unsigned const k = static_cast<unsigned>(std::min<std::size_t>(n, 32));
        out.put(0, k);
        n -= k;
    }
}
inline void skip_bits(bit_reader& in, std::size_t n) {
    while (n > 0) {
        unsigned const k = static_cast<unsigned>(std::min<std::size_t>(n, 32));
        (void)in.get(k);
        n -= k;
    }
}

template <class Machine>
void encode_pending(Machine const& value, bit_writer& out, time_frame own) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    using slot = event_bits<events>;
    auto& m = const_cast<Machine&>(value);
    if constexpr (pending::defers) {
        auto const& deferred = access::deferred(m);
        out.put(access::deferral_pending_retry(m) && deferred.size() > 0 ? 1u : 0u, 1);
        out.put(deferred.size(), bits_for(static_cast<int>(pending::deferred_capacity) + 1));
        deferred.for_each_held([&](auto const& item) { encode_event<events>(item, out, own); });
        skip_bits(out, (pending::deferred_capacity - deferred.size()) * slot::size);
    }
    if constexpr (pending::delays) {
        auto const& queue = access::queue(m);
        using item_type = typename std::remove_cvref_t<decltype(queue)>::value_type;
        // In the order they come due (and, due together, were sent): two machines that hold the
        // same events sent in another order behave the same, and encode the same.
        struct scheduled {
            duration due;
            std::size_t sent;
            int id;
            item_type const* item;
        };
        std::array<scheduled, pending::delayed_capacity> waiting{};
        std::size_t count = 0;
        queue.for_each_scheduled([&](duration due, int id, item_type const& item) {
            waiting[count] = {due, count, id, &item};
            ++count;
        });
        sort_few(
            waiting.begin(), waiting.begin() + static_cast<std::ptrdiff_t>(count),
            [](scheduled const& a, scheduled const& b) { return a.due != b.due ? a.due < b.due : a.sent < b.sent; });
        out.put(count, bits_for(static_cast<int>(pending::delayed_capacity) + 1));
        for (std::size_t i = 0; i < count; ++i) {
            auto const left = static_cast<std::uint64_t>((waiting[i].due - own.clock).count());  // the time left
            out.put(left & 0xffffffffu, 32);
            out.put(left >> 32, 32);
            out.put(static_cast<std::uint32_t>(waiting[i].id), 32);
            encode_event<events>(*waiting[i].item, out, own);
        }
        skip_bits(out, (pending::delayed_capacity - count) * (64 + 32 + slot::size));
    }
}

// The periods since each timeout slot was armed, as a key holds them (0 for a slot whose state
// is inactive). A state's timeout matters only until it is due, so its count is capped one period
// past the longest delay. The timeouts of a state with several also compete by which came due
// first (docs/semantics.md, "Timers"), which the differences of their counts decide as long as
// they are below that cap: such a state's counts are kept in order, ties included, each above
// the next smaller one by its difference capped the same way (the smallest capped as a single
// count is). Two machines whose counts are so keyed alike behave alike.
template <class Machine>
auto timeout_periods(Machine& m, time_frame own) {
    using layout = chart_layout<machine_model<Machine>>;
    constexpr auto slots = static_cast<std::size_t>(layout::timeout_slots);
    auto const& armed = access::armed(m);
    duration const longest = access::longest_timeout(m);
    std::array<std::uint64_t, slots> out{};
    for (std::size_t i = 0; i < slots; ++i) out[i] = access::timeout_armed(m, i) ? own.cycles(armed[i], longest) : 0;
    if constexpr (layout::has_competing_timeouts) {
        // The cap of a single count (time_frame::cycles, which has refused a cap that does not fit).
        std::uint64_t const cap = own.period > duration::zero() ? static_cast<std::uint64_t>(longest / own.period) + 1
                                                                : 0;
        for (std::size_t s = 0; s < layout::timeout_slot_count.size(); ++s) {
            auto const count = static_cast<std::size_t>(layout::timeout_slot_count[s]);
            if (count < 2 || !access::timeout_armed(m, static_cast<std::size_t>(layout::timeout_slot[s]))) continue;
            auto const first = static_cast<std::size_t>(layout::timeout_slot[s]);
            std::array<std::size_t, slots> order{};  // the state's slots, fewest periods first
            std::array<std::uint64_t, slots> raw{};
            for (std::size_t k = 0; k < count; ++k) {
                order[k] = first + k;
                raw[first + k] = own.periods(armed[first + k]);
            }
            // (Equal ages stay in slot order: sort_few is stable, and the slots start in order.)
            sort_few(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count),
                     [&](std::size_t a, std::size_t b) { return raw[a] < raw[b]; });
            std::uint64_t kept = 0;
            for (std::size_t k = 0; k < count; ++k) {
                std::uint64_t const step = k == 0 ? raw[order[0]] : raw[order[k]] - raw[order[k - 1]];
                kept += step < cap ? step : cap;
                if (kept > max_cycles) own.refuse(longest, kept);
                out[order[k]] = kept;
            }
        }
    }
    return out;
}

template <class Machine>
void encode_machine(Machine const& value, encode_visitor& v) {
    auto& m = const_cast<Machine&>(value);
    bit_writer& out = v.out;
    std::size_t first = out.bits();
    auto const cfg = access::canonical_configuration(m);
    constexpr auto bits = slot_bits<Machine>();
    for (std::size_t k = 0; k < bits.size(); ++k) out.put(cfg.active[k], bits[k]);
    v.record("configuration", first);
    time_frame const own{access::clock(m), v.frame.period};
    first = out.bits();
    for (std::uint64_t periods : timeout_periods(m, own)) out.put(periods, cycle_bits);
    v.record("timeouts", first);
    first = out.bits();
    encode_pending(value, out, own);
    v.record("pending events", first);
    encode_visitor inner{out, own, v.fields, v.path};
    walk(value.context(), inner, std::string_view{});
}

struct decode_visitor {
    bit_reader& in;
    time_frame frame;
    template <class T>
    void leaf(T& value, no_name);
};

template <class T>
void decode(T& value, bit_reader& in, time_frame frame) {
    decode_visitor v{in, frame};
    walk(value, v);
}

template <class Events, class Item>
Item decode_event(bit_reader& in, time_frame frame) {
    using slot = event_bits<Events>;
    std::size_t const end = in.bits() + slot::size;
    auto const index = static_cast<int>(in.get(slot::index));
    Item item{};
    if (index > 0 && index < static_cast<int>(std::variant_size_v<Item>))
        visit_index<static_cast<int>(std::variant_size_v<Item>)>(index, [&](auto i) {
            using E = std::variant_alternative_t<decltype(i)::value, Item>;
            if constexpr (!std::is_same_v<E, std::monostate> && !std::is_same_v<E, action_failed> &&
                          std::is_default_constructible_v<E>) {
                E e{};
                decode(e, in, frame);
                item.template emplace<decltype(i)::value>(e);
            }
        });
    skip_bits(in, end - in.bits());
    return item;
}

template <class Machine>
void decode_pending(Machine& m, bit_reader& in, time_frame frame) {
    using pending = pending_layout<Machine>;
    using events = typename machine_model<Machine>::events;
    using slot = event_bits<events>;
    if constexpr (pending::defers) {
        auto& deferred = access::deferred(m);
        using item_type = typename std::remove_cvref_t<decltype(deferred)>::value_type;
        bool const retry = in.get(1) != 0;
        auto const count = static_cast<std::size_t>(in.get(bits_for(static_cast<int>(pending::deferred_capacity) + 1)));
        deferred.clear();
        deferred.clear_overflow();
        for (std::size_t i = 0; i < count; ++i) (void)deferred.push_item(decode_event<events, item_type>(in, frame));
        skip_bits(in, (pending::deferred_capacity - count) * slot::size);
        access::set_deferral_pending_retry(m, retry);
    }
    if constexpr (pending::delays) {
        auto& queue = access::queue(m);
        using item_type = typename std::remove_cvref_t<decltype(queue)>::value_type;
        auto const count = static_cast<std::size_t>(in.get(bits_for(static_cast<int>(pending::delayed_capacity) + 1)));
        queue.clear_scheduled();
        queue.set_clock(frame.clock);
        for (std::size_t i = 0; i < count; ++i) {
            std::uint64_t left = in.get(32);
            left |= in.get(32) << 32;
            auto const id = static_cast<int>(static_cast<std::uint32_t>(in.get(32)));
            auto const item = decode_event<events, item_type>(in, frame);
            // (Due past duration::max() from this clock: never, and not kept, as the queue keeps
            // none such: detail/runtime/delayed_events.hpp.)
            if (left > static_cast<std::uint64_t>(duration::max().count()) ||
                shifted_past_max(frame.clock, duration{static_cast<duration::rep>(left)}))
                continue;
            (void)queue.put_scheduled(frame.clock + duration{static_cast<duration::rep>(left)}, id, item);
        }
        skip_bits(in, (pending::delayed_capacity - count) * (64 + 32 + slot::size));
    }
}

template <class T>
void decode_visitor::leaf(T& value, no_name) {
    using U = std::remove_cv_t<T>;
    constexpr member_kind k = kind_of<U>();
    if constexpr (k == member_kind::machine) {
        auto& cfg = access::configuration(value);
        constexpr auto bits = slot_bits<U>();
        for (std::size_t s = 0; s < bits.size(); ++s)
            cfg.active[s] = static_cast<std::remove_cvref_t<decltype(cfg.active[s])>>(in.get(bits[s]));
        access::set_clock(value, frame.clock);
        for (auto& armed : access::armed(value)) armed = frame.before(in.get(cycle_bits));
        decode_pending(value, in, frame);
        decode(access::context(value), in, frame);
    } else if constexpr (k == member_kind::timer) {
        auto const phase = static_cast<std::uint8_t>(in.get(2));
        bool const expired = in.get(1) != 0;
        auto const started = frame.before(in.get(cycle_bits));
        access::set_timer(value, phase, expired, started, frame.clock - started);
    } else if constexpr (k == member_kind::channel) {
        using V = channel_value<U>;
        V pending = value.pending();
        V current = value.get();
        decode(pending, in, frame);
        decode(current, in, frame);
        access::set_channel(value, current, pending);
    } else {
        value = decode_value<U>(in);
    }
}

}  // namespace bsc::detail
// end include/bsc/detail/verify/codec.hpp
// begin include/bsc/verify/coverage.hpp
// Coverage of a chart by the explored state space: the states never active in any reachable
// state and the transition rows never fired on any explored step. Unlike the static checks,
// this accounts for guards and data: a row whose guard can never hold is reported here.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

// begin include/bsc/verify/explorer.hpp
// bsc::verify::explorer: breadth-first exploration of every state a closed model can reach.
// States are stored once, as fixed-size byte keys in one arena (the BFS queue itself), found
// again through an open-addressing hash table of indices; the graph is kept as compact
// adjacency arrays, so properties are checked after exploration without re-running the model.
// Breadth-first order makes every counterexample a shortest one.
//
// A model provides:
//   using state = ...;                                   // copyable
//   static constexpr std::size_t key_size;               // bytes of encode()
//   state initial() const;
//   void encode(state const&, std::byte* out) const;
//   state decode(std::byte const* in) const;
//   void successors(state const&, F&& emit) const;       // emit(std::uint16_t label, state const&)
//   std::string label(std::uint16_t) const;              // for traces
//   std::string describe(state const&) const;            // for traces: the configuration by name
//   duration period() const;                             // optional: the time of a step, for traces
//   std::vector<detail::encoded_field> fields() const;   // optional: the named parts of a key, for
//                                                        // the report of an exploration a bound stopped

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>


namespace bsc::verify {

/// Bounds that stop exploration with a report instead of exhausting the machine.
struct limits {
    std::size_t max_states = 20'000'000;
    std::size_t max_memory_bytes = std::size_t{8} << 30;
};

/// A part of the explored state (a member of a context, a machine's configuration, timeouts or
/// pending events) and the number of distinct values it took in the states found.
struct member_spread {
    std::string name;
    std::size_t values = 0;
};

/// What an exploration did.
struct statistics {
    std::size_t states = 0;
    std::size_t transitions = 0;  ///< edges of the state graph (successors, duplicates included)
    std::size_t depth = 0;        ///< breadth-first levels: the longest shortest path
    double seconds = 0;
    std::size_t memory_bytes = 0;  ///< held by the explorer at the end
    std::size_t key_bytes = 0;     ///< bytes stored per state for its encoding
    bool complete = false;         ///< false if a bound stopped exploration
    std::string stopped_by;        ///< which bound, if any
    /// When a bound stopped exploration: the parts of the state that took the most distinct
    /// values, most first (at most five), to say what multiplied the states
    /// (docs/verification.md: leaving a member out of the state). Counted over every state found,
    /// or over a million of them evenly spaced when more were found.
    std::vector<member_spread> widest;

    /// "filled_count: 5,633,072 values; configuration: 12 values": the widest parts, or empty.
    std::string widest_text() const {
        std::string out;
        for (auto const& w : widest) {
            // (Appended digit by digit, not inserted: GCC 12 at -O3 warns of an overlapping copy
            // inside std::string::insert, -Wrestrict.)
            std::string const digits = std::to_string(w.values);
            std::string n;
            for (std::size_t k = 0; k < digits.size(); ++k) {
                if (k > 0 && (digits.size() - k) % 3 == 0) n += ',';
                n += digits[k];
            }
            out += (out.empty() ? "" : "; ") + w.name + ": " + n + " values";
        }
        return out;
    }
};

/// How far an exploration has got: what a progress callback receives.
struct progress {
    std::size_t states = 0;    ///< found so far
    std::size_t expanded = 0;  ///< of which the successors are computed
    std::size_t depth = 0;     ///< the breadth-first level being expanded
    double seconds = 0;        ///< since run() began
    double states_per_second = 0;
    std::size_t memory_bytes = 0;  ///< held by the explorer now
    bool done = false;             ///< the last call, when run() ends
};

template <class Model>
class explorer {
public:
    using state = typename Model::state;
    static constexpr std::size_t key_size = Model::key_size;
    static constexpr std::uint32_t none = 0xffffffffu;

    explicit explorer(Model model, limits bounds = {}) : model_(std::move(model)), bounds_(bounds) {}

    /// Calls `report(progress)` every `every` expanded states during run(), and once when it
    /// ends (progress::done), for explorations long enough to want a sign of life.
    void on_progress(std::function<void(progress const&)> report, std::size_t every = 100'000) {
        report_ = std::move(report);
        report_every_ = every == 0 ? 1 : every;
    }

    /// Explores every reachable state (once; later calls return the same figures).
    statistics const& run() {
        if (ran_) return stats_;
        ran_ = true;
        auto const start = std::chrono::steady_clock::now();
        table_.assign(1u << 10, none);  // doubled as states come
        std::vector<std::byte> scratch(key_size);
        state const init = model_.initial();
        model_.encode(init, scratch.data());
        insert(scratch.data(), none, 0);
        std::size_t level_end = 1;
        std::size_t expanded = 0;  // states whose successors are computed
        for (std::size_t i = 0; i < count(); ++i) {
            if (i == level_end) {
                ++stats_.depth;
                level_end = count();
            }
            if (report_ && i > 0 && i % report_every_ == 0) report_progress(i, start, false);
            if (!within_bounds()) break;
            expanded = i + 1;
            edge_begin_.push_back(static_cast<std::uint32_t>(edge_to_.size()));
            state const s = model_.decode(key(i));
            std::size_t successors = 0;
            model_.successors(s, [&](std::uint16_t label, state const& next) {
                model_.encode(next, scratch.data());
                std::uint32_t const j = insert(scratch.data(), static_cast<std::uint32_t>(i), label);
                edge_to_.push_back(j);
                edge_label_.push_back(label);
                ++successors;
            });
            most_successors_ = std::max(most_successors_, successors);
        }
        stats_.complete = stats_.stopped_by.empty();
        while (edge_begin_.size() < count()) edge_begin_.push_back(static_cast<std::uint32_t>(edge_to_.size()));
        edge_begin_.push_back(static_cast<std::uint32_t>(edge_to_.size()));
        stats_.states = count();
        stats_.transitions = edge_to_.size();
        stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats_.memory_bytes = memory();
        stats_.key_bytes = key_size;
        if constexpr (requires { model_.fields(); })
            if (!stats_.complete) stats_.widest = widest_fields(model_.fields());
        if (report_) report_progress(expanded, start, true);
        return stats_;
    }

    statistics const& stats() const { return stats_; }
    std::size_t count() const { return keys_.size() / key_size; }
    state at(std::size_t i) const { return model_.decode(key(i)); }
    Model const& model() const { return model_; }

    // The graph, for property checks.
    std::uint32_t edges_begin(std::size_t i) const { return edge_begin_[i]; }
    std::uint32_t edges_end(std::size_t i) const { return edge_begin_[i + 1]; }
    std::uint32_t edge_target(std::size_t e) const { return edge_to_[e]; }
    std::uint16_t edge_label(std::size_t e) const { return edge_label_[e]; }
    std::uint32_t parent(std::size_t i) const { return parent_[i]; }
    std::uint16_t parent_label(std::size_t i) const { return via_[i]; }

private:
    std::byte const* key(std::size_t i) const { return keys_.data() + i * key_size; }

    void report_progress(std::size_t expanded, std::chrono::steady_clock::time_point start, bool done) const {
        progress p;
        p.states = count();
        p.expanded = expanded;
        p.depth = stats_.depth;
        p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        p.states_per_second = p.seconds > 0 ? static_cast<double>(p.states) / p.seconds : 0;
        p.memory_bytes = memory();
        p.done = done;
        report_(p);
    }

    static std::uint64_t hash(std::byte const* k) {
        std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a, then a final mix
        for (std::size_t i = 0; i < key_size; ++i) h = (h ^ static_cast<std::uint64_t>(k[i])) * 0x100000001b3ull;
        h ^= h >> 32;
        return h * 0x9e3779b97f4a7c15ull;
    }

    std::uint32_t insert(std::byte const* k, std::uint32_t from, std::uint16_t label) {
        if ((count() + 1) * 2 > table_.size()) grow();
        std::size_t const mask = table_.size() - 1;
        for (std::size_t slot = hash(k) & mask;; slot = (slot + 1) & mask) {
            std::uint32_t const at = table_[slot];
            if (at == none) {
                auto const index = static_cast<std::uint32_t>(count());
                table_[slot] = index;
                keys_.insert(keys_.end(), k, k + key_size);
                parent_.push_back(from);
                via_.push_back(label);
                return index;
            }
            if (std::memcmp(key(at), k, key_size) == 0) return at;
        }
    }

    void grow() {
        std::vector<std::uint32_t> bigger(table_.size() * 2, none);
        std::size_t const mask = bigger.size() - 1;
        for (std::uint32_t i = 0; i < count(); ++i) {
            std::size_t slot = hash(key(i)) & mask;
            while (bigger[slot] != none) slot = (slot + 1) & mask;
            bigger[slot] = i;
        }
        table_.swap(bigger);
    }

    // The bits [first, first + n) of key i: the value itself up to 64 bits, a hash of them beyond.
    std::uint64_t bits_of(std::size_t i, std::size_t first, std::size_t n) const {
        std::byte const* k = key(i);
        std::uint64_t value = 0;
        std::uint64_t hash = 0xcbf29ce484222325ull;
        for (std::size_t b = 0; b < n; ++b) {
            std::size_t const at = first + b;
            auto const bit = (static_cast<unsigned>(k[at / 8]) >> (at % 8)) & 1u;
            if (n <= 64)
                value |= std::uint64_t{bit} << b;
            else
                hash = (hash ^ bit ^ (b << 1)) * 0x100000001b3ull;
        }
        return n <= 64 ? value : hash;
    }

    // The named parts of the states found, those with the most distinct values first; counted
    // over at most spread_sample states, evenly spaced (the report must not cost what the
    // exploration was stopped for).
    static constexpr std::size_t spread_sample = 1'000'000;
    std::vector<member_spread> widest_fields(std::vector<detail::encoded_field> const& fields) const {
        std::vector<member_spread> spread;
        std::size_t const stride = count() / spread_sample + 1;
        std::vector<std::uint64_t> values((count() + stride - 1) / stride);
        for (auto const& f : fields) {
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = bits_of(i * stride, f.first_bit, f.bits);
            std::sort(values.begin(), values.end());
            auto const distinct = static_cast<std::size_t>(std::unique(values.begin(), values.end()) - values.begin());
            if (distinct > 1) spread.push_back({f.name, distinct});
        }
        std::sort(spread.begin(), spread.end(), [](auto const& a, auto const& b) {
            return a.values != b.values ? a.values > b.values : a.name < b.name;
        });
        if (spread.size() > 5) spread.resize(5);
        return spread;
    }

    std::size_t memory() const {
        return keys_.capacity() + table_.capacity() * 4 + parent_.capacity() * 4 + via_.capacity() * 2 +
               edge_begin_.capacity() * 4 + edge_to_.capacity() * 4 + edge_label_.capacity() * 2;
    }

    // What the containers may hold at the peak of the next state's expansion, which adds at
    // most most_successors_ states and edges: a vector that must grow holds its old and its
    // new buffer at once, the hash table its old and its doubled array.
    std::size_t peak_of_next_expansion() const {
        std::size_t const more = std::max<std::size_t>(most_successors_, 1);
        auto growth = [&](auto const& v, std::size_t added) -> std::size_t {
            if (v.size() + added <= v.capacity()) return 0;
            return std::max(v.capacity() * 2, v.size() + added) * sizeof(v[0]);
        };
        std::size_t peak = memory() + growth(keys_, more * key_size) + growth(parent_, more) + growth(via_, more) +
                           growth(edge_begin_, 1) + growth(edge_to_, more) + growth(edge_label_, more);
        if ((count() + more) * 2 > table_.size()) peak += table_.size() * 2 * sizeof(std::uint32_t);
        return peak;
    }

    bool within_bounds() {
        if (count() > bounds_.max_states) {
            stats_.stopped_by = "max_states (" + std::to_string(bounds_.max_states) + ")";
            return false;
        }
        if (peak_of_next_expansion() > bounds_.max_memory_bytes) {
            stats_.stopped_by = "max_memory_bytes (" + std::to_string(bounds_.max_memory_bytes) + ")";
            return false;
        }
        return true;
    }

    Model model_;
    limits bounds_;
    statistics stats_;
    std::function<void(progress const&)> report_;
    std::size_t report_every_ = 100'000;
    bool ran_ = false;
    std::vector<std::byte> keys_;
    std::vector<std::uint32_t> table_;
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint16_t> via_;
    std::vector<std::uint32_t> edge_begin_;
    std::vector<std::uint32_t> edge_to_;
    std::vector<std::uint16_t> edge_label_;
    std::size_t most_successors_ = 0;  // of any state expanded so far
};

}  // namespace bsc::verify
// end include/bsc/verify/explorer.hpp

namespace bsc::verify {

/// An observer that records which rows fire. Give it to the explored machine:
/// `bsc::machine<decltype(chart), bsc::default_policy, bsc::verify::row_recorder>`; copies of
/// the machine share the record.
struct row_recorder {
    std::vector<bool>* fired = nullptr;
    void on_row(int row) {
        if (fired && static_cast<std::size_t>(row) < fired->size()) (*fired)[static_cast<std::size_t>(row)] = true;
    }
};

struct coverage_report {
    std::vector<std::string> dead_states;       ///< never active in an explored state
    std::vector<std::string> dead_transitions;  ///< never fired on an explored step
    bool complete() const { return dead_states.empty() && dead_transitions.empty(); }
    std::string to_string() const {
        std::string out;
        for (auto const& s : dead_states) out += "never active: " + s + '\n';
        for (auto const& t : dead_transitions) out += "never fired: " + t + '\n';
        return out.empty() ? "every state and transition is exercised\n" : out;
    }
};

}  // namespace bsc::verify

namespace bsc::detail {
template <class Row>
std::string trigger_name() {
    if constexpr (bsc::detail::is_timeout_row<Row>)
        return "after";
    else if constexpr (std::is_void_v<typename bsc::detail::trigger_event<Row>::type>)
        return "[eventless]";
    else
        return std::string(name_of<typename bsc::detail::trigger_event<Row>::type>);
}
}  // namespace bsc::detail

namespace bsc::verify {

/// "Source + event -> Target" (or "Source + event (internal)") for each transition row of a
/// chart, by position in make_chart; empty for entry and exit rows.
template <class Chart>
std::vector<std::string> row_names() {
    using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
    std::vector<std::string> names(static_cast<std::size_t>(model::R));
    // clang-format off
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (
            [&] {
                using R = typename model::template row_at<static_cast<int>(I)>;
                if constexpr (bsc::detail::is_transition_row<R>) {
                    std::string n = std::string(name_of<typename R::source>) + " + " + detail::trigger_name<R>();
                    if constexpr (std::is_same_v<typename R::target, bsc::detail::no_target>)
                        n += " (internal)";
                    else
                        n += " -> " + std::string(name_of<typename R::target>);
                    names[I] = n;
                }
            }(),
            ...);
    }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
    // clang-format on
    return names;
}

/// Coverage of the chart of the machines that `get(state)` returns, over an explorer that
/// has run with a row_recorder writing to `fired`.
template <class Model, class Get>
coverage_report coverage(explorer<Model>& ex, std::vector<bool> const& fired, Get get) {
    ex.run();
    using machine_type = std::remove_cvref_t<decltype(get(ex.at(0)))>;
    using chart = typename machine_type::chart_type;
    using model = bsc::detail::chart_model<chart>;
    std::vector<bool> seen(static_cast<std::size_t>(model::N), false);
    for (std::size_t i = 0; i < ex.count(); ++i) {
        auto const s = ex.at(i);
        auto const active = bsc::detail::access::active_flags(get(s));
        for (std::size_t k = 0; k < active.size(); ++k) seen[k] = seen[k] || active[k];
    }
    coverage_report report;
    constexpr auto const& names = bsc::detail::state_names_of<model>;
    for (std::size_t k = 1; k < seen.size(); ++k)  // (a history state is never active: not dead)
        if (!seen[k] && model::tree.kinds[k] != bsc::detail::kind::history) report.dead_states.emplace_back(names[k]);
    auto const rows = row_names<chart>();
    for (std::size_t r = 0; r < rows.size(); ++r)
        if (!rows[r].empty() && (r >= fired.size() || !fired[r])) report.dead_transitions.push_back(rows[r]);
    return report;
}

/// Coverage for models whose state is the machine itself.
template <class Model>
coverage_report coverage(explorer<Model>& ex, std::vector<bool> const& fired) {
    return coverage(
        ex, fired, [](auto const& m) -> auto const& { return m; });
}

}  // namespace bsc::verify
// end include/bsc/verify/coverage.hpp
// begin include/bsc/verify/models.hpp
// Closed models of bsc machines for the explorer:
//  - event_model: a machine to which every listed event is offered in every state;
//  - cycle_model: a machine stepped with a fixed period, its inputs drawn each cycle from
//    a finite set of choices the user declares;
//  - system_model: any aggregate of machines and plant models, stepped by a user function
//    with a finite set of choices per cycle (the closed loops of the [BSC] and [COMDES] papers,
//    docs/references.md).
// Time is made relative: every explored state is decoded with its machines' clocks at the
// same origin, so states that differ only in absolute time are one state.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>


namespace bsc::detail {
// The clock every explored state is decoded at; far enough from zero that relative times fit.
inline constexpr duration origin = std::chrono::hours{1};

template <class T>
struct codec {
    static constexpr std::size_t key_size = encoded_size<T>();
    duration period{};
    void encode(T const& s, std::byte* out) const {
        std::memset(out, 0, key_size);
        bit_writer writer{out, encoded_bits<T>()};
        detail::encode(s, writer, time_frame{origin + period, period});
        if (writer.bits() != encoded_bits<T>()) std::abort();  // the size computed from the types is exact
    }
    // The named parts of a key, found by encoding a state of the model.
    std::vector<encoded_field> fields(T const& s) const {
        std::vector<std::byte> scratch(key_size);
        bit_writer writer{scratch.data(), encoded_bits<T>()};
        std::vector<encoded_field> out;
        detail::encode(s, writer, time_frame{origin + period, period}, &out);
        return out;
    }
    T decode(T prototype, std::byte const* in) const {
        bit_reader reader{in, encoded_bits<T>()};
        detail::decode(prototype, reader, time_frame{origin, period});
        if (reader.bits() != encoded_bits<T>()) std::abort();
        return prototype;
    }
};
// What every model of a bsc state keeps and does alike: the initial state, its states encoded
// and decoded by the codec, and the successors of a state, one per alternative the model
// offers (Model's labels() and advance(state, label)).
template <class Model, class State>
class encoded_model {
public:
    using state = State;
    static constexpr std::size_t key_size = codec<State>::key_size;

    template <class Emit>
    void successors(state const& s, Emit&& emit) const {
        auto const& model = static_cast<Model const&>(*this);
        auto const labels = static_cast<std::uint16_t>(model.labels());
        for (std::uint16_t label = 0; label < labels; ++label) {
            state next = s;
            model.advance(next, label);
            emit(label, next);
        }
    }
    state initial() const { return initial_; }
    void encode(state const& s, std::byte* out) const { codec_.encode(s, out); }
    state decode(std::byte const* in) const { return codec_.decode(initial_, in); }
    std::vector<encoded_field> fields() const { return codec_.fields(initial_); }

protected:
    encoded_model(State initial, duration period) : initial_(std::move(initial)), codec_{period} {}
    duration step_period() const { return codec_.period; }

private:
    State initial_;
    codec<State> codec_;
};
}  // namespace bsc::detail

namespace bsc::verify {

/// Offers each of the events Es... to the machine in every state (dispatch).
template <class Machine, class... Es>
class event_model : public detail::encoded_model<event_model<Machine, Es...>, Machine> {
public:
    using state = Machine;

    explicit event_model(Machine initial)
        : detail::encoded_model<event_model, Machine>(std::move(initial), duration{}) {}

    /// The number of alternatives offered in every state: the events.
    static constexpr std::size_t labels() { return sizeof...(Es); }
    /// Takes alternative `label` in place: dispatches the label-th event. `M` is the machine
    /// type or the same chart with another observer (bsc/benchmark.hpp replays with a logger).
    template <class M>
    void advance(M& s, std::uint16_t label) const {
        std::uint16_t k = 0;
        ((k++ == label ? static_cast<void>(s.dispatch(Es{})) : static_cast<void>(0)), ...);
    }
    std::string label(std::uint16_t i) const {
        constexpr std::string_view names[] = {event_name<Es>...};
        return std::string(names[i]);
    }
    std::string describe(state const& s) const { return s.active_states().joined(); }
};

// The label of a cycle_model's choice when the user gives none.
struct numbered_inputs {
    std::string operator()(std::size_t choice) const { return "cycle, inputs #" + std::to_string(choice); }
};

/// Steps the machine with a fixed period; before each cycle, `apply(context, choice)` sets the
/// inputs for one of `choices` alternatives (`context` is the machine's `context()`, const, the
/// environment's view: inputs are set through it), and every alternative is explored.
/// `label(choice)` names an alternative in traces; written as `name=value` words
/// ("P1=1 S1=0"), a trace shows only the words that changed from one step to the next
/// (verdict::to_string).
template <class Machine, class Apply, class Label = numbered_inputs>
class cycle_model : public detail::encoded_model<cycle_model<Machine, Apply, Label>, Machine> {
public:
    using state = Machine;

    // (The parameter is not `label`: a function pointer of that name shadows label() for -Wshadow.)
    cycle_model(Machine initial, duration period, std::size_t choices, Apply apply, Label choice_label = {})
        : detail::encoded_model<cycle_model, Machine>(std::move(initial), period),
          choices_(choices),
          apply_(std::move(apply)),
          label_(std::move(choice_label)) {}

    /// The number of alternatives offered in every state: the choices of inputs.
    std::size_t labels() const { return choices_; }
    /// Takes alternative `choice` in place: sets its inputs, then steps one period on. `M` is
    /// the machine type or the same chart with another observer.
    template <class M>
    void advance(M& s, std::uint16_t choice) const {
        apply_(s.context(), choice);
        s.step(detail::origin + period());
    }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return s.active_states().joined(); }
    /// The time between two cycles: a trace's step k is at k periods.
    duration period() const { return this->step_period(); }

private:
    std::size_t choices_;
    Apply apply_;
    Label label_;
};

/// A closed system: an aggregate `System` of machines and plant data, advanced by
/// `step(system, choice, now)` for each of `choices` alternatives per cycle. `describe`
/// names a system state for traces; `label(choice)` names an alternative.
template <class System, class Step, class Describe, class Label>
class system_model : public detail::encoded_model<system_model<System, Step, Describe, Label>, System> {
public:
    using state = System;

    system_model(System initial, duration period, std::size_t choices, Step step, Describe describe, Label choice_label)
        : detail::encoded_model<system_model, System>(std::move(initial), period),
          choices_(choices),
          step_(std::move(step)),
          describe_(std::move(describe)),
          label_(std::move(choice_label)) {}

    /// The number of alternatives offered in every state.
    std::size_t labels() const { return choices_; }
    /// Takes alternative `choice` in place: one step of the system.
    void advance(state& s, std::uint16_t choice) const { step_(s, choice, detail::origin + period()); }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return describe_(s); }
    /// The time between two steps: a trace's step k is at k periods.
    duration period() const { return this->step_period(); }

private:
    std::size_t choices_;
    Step step_;
    Describe describe_;
    Label label_;
};

}  // namespace bsc::verify
// end include/bsc/verify/models.hpp
// begin include/bsc/verify/properties.hpp
// Properties checked on an explored state graph, each with a verdict and, when it fails, a
// shortest counterexample in the chart's own names: deadlock freedom, invariants (A[] p),
// reachability (E<> p), reinitiability and leads-to (p --> q).

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
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

namespace bsc::detail {
// `now` as written, except that when every word of it is name=value (the inputs of a cycle),
// only the words not in `before` are kept: what changed ("(inputs unchanged)" if nothing did).
inline std::string changed_words(std::string const& before, std::string const& now) {
    auto const words = [](std::string const& text) {
        std::vector<std::string> out;
        for (std::size_t at = 0; at < text.size();) {
            std::size_t const end = std::min(text.find(' ', at), text.size());
            if (end > at) out.push_back(text.substr(at, end - at));
            at = end + 1;
        }
        return out;
    };
    auto const new_words = words(now);
    auto const assignment = [](std::string const& w) {
        auto const eq = w.find('=');
        return eq != std::string::npos && eq > 0 && eq + 1 < w.size();
    };
    if (new_words.empty() || !std::all_of(new_words.begin(), new_words.end(), assignment)) return now;
    auto const old_words = words(before);
    std::string out;
    for (auto const& w : new_words)
        if (std::find(old_words.begin(), old_words.end(), w) == old_words.end()) out += (out.empty() ? "" : " ") + w;
    return out.empty() ? "(inputs unchanged)" : out;
}
}  // namespace bsc::detail

namespace bsc::verify {

/// One step of a trace: what was applied (an event, an input choice) and the configuration after;
/// for a model stepped with a period (cycle_model, system_model), the time of the step from the
/// initial state (step k at k periods).
struct trace_step {
    std::string label;
    std::string configuration;
    std::optional<duration> time;
};

/// The outcome of one property.
struct verdict {
    enum class status { holds, fails, inconclusive };
    std::string property;
    status result = status::inconclusive;
    std::vector<trace_step> trace;  ///< counterexample (or witness, for reachability)
    std::string detail;             ///< e.g. where a leads-to counterexample starts to loop

    bool holds() const { return result == status::holds; }
    bool fails() const { return result == status::fails; }

    /// A readable report: the verdict, then the trace one step per line, with its time when the
    /// model has one. A label made of `name=value` words only (the inputs of a cycle) shows the
    /// words that changed since the step before. A run of steps that repeat the one before them
    /// (the same label, the same configuration; variables and timers may still change) is one
    /// line: "5-16. [500ms-1600ms] 12 steps, same inputs and configuration".
    std::string to_string() const {
        std::string out = property + ": " +
                          (result == status::holds   ? "holds"
                           : result == status::fails ? "FAILS"
                                                     : "inconclusive");
        if (!detail.empty()) out += " (" + detail + ")";
        out += '\n';
        auto const repeats = [&](std::size_t k) {
            return k > 0 && trace[k].label == trace[k - 1].label &&
                   trace[k].configuration == trace[k - 1].configuration;
        };
        for (std::size_t i = 0; i < trace.size();) {
            std::size_t end = i + 1;
            while (repeats(i) && end < trace.size() && repeats(end)) ++end;
            if (end - i >= 2) {
                out += "  " + std::to_string(i) + "-" + std::to_string(end - 1) + ". ";
                if (trace[i].time && trace[end - 1].time)
                    out += "[" + bsc::detail::delay_label(*trace[i].time) + "-" +
                           bsc::detail::delay_label(*trace[end - 1].time) + "] ";
                out += std::to_string(end - i) + " steps, same inputs and configuration\n";
            } else {
                out += "  " + std::to_string(i) + ". ";
                if (trace[i].time) out += "[" + bsc::detail::delay_label(*trace[i].time) + "] ";
                out += bsc::detail::changed_words(i > 0 ? trace[i - 1].label : std::string{}, trace[i].label) + " -> " +
                       trace[i].configuration + '\n';
            }
            i = end;
        }
        return out;
    }
};

}  // namespace bsc::verify

namespace bsc::detail {

// An argument a property cannot work with: thrown, or printed before aborting where exceptions
// are disabled.
[[noreturn]] inline void refuse_argument(char const* why) {
#if defined(__cpp_exceptions)
    throw std::invalid_argument(why);
#else
    std::fputs(why, stderr);
    std::fputs("\n", stderr);
    std::abort();
#endif
}

// Whether the model is stepped with a fixed period, which gives its traces their times.
template <class Model>
concept timed_model = requires(Model const& m) {
    { m.period() } -> std::convertible_to<duration>;
};

template <class Model>
void append_step(verify::explorer<Model> const& ex, std::vector<verify::trace_step>& out, std::string label,
                 std::size_t i) {
    std::optional<duration> time;
    if constexpr (timed_model<Model>) time = static_cast<duration::rep>(out.size()) * ex.model().period();
    out.push_back({std::move(label), ex.model().describe(ex.at(i)), time});
}

// The shortest path from the initial state to state i (breadth-first tree).
template <class Model>
std::vector<verify::trace_step> path_to(verify::explorer<Model> const& ex, std::size_t i) {
    std::vector<std::size_t> chain;
    for (std::size_t s = i; s != verify::explorer<Model>::none; s = ex.parent(s)) chain.push_back(s);
    std::vector<verify::trace_step> out;
    for (std::size_t k = chain.size(); k-- > 0;) {
        std::size_t const s = chain[k];
        append_step(ex, out, k + 1 == chain.size() ? "(initial)" : ex.model().label(ex.parent_label(s)), s);
    }
    return out;
}

template <class Model>
verify::verdict incomplete(verify::explorer<Model> const& ex, std::string property) {
    std::string why = "exploration stopped by " + ex.stats().stopped_by;
    if (!ex.stats().widest.empty())
        why += "; the parts of the state with the most distinct values: " + ex.stats().widest_text();
    verify::verdict v{std::move(property), verify::verdict::status::inconclusive, {}, std::move(why)};
    return v;
}

}  // namespace bsc::detail

namespace bsc::verify {

/// A[] p: p holds in every reachable state. `p` takes the model's state.
template <class Model, class Pred>
verdict always(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    for (std::size_t i = 0; i < ex.count(); ++i)
        if (!p(ex.at(i))) return {"A[] " + name, verdict::status::fails, detail::path_to(ex, i), {}};
    if (!ex.stats().complete) return detail::incomplete(ex, "A[] " + name);
    return {"A[] " + name, verdict::status::holds, {}, {}};
}

/// E<> p: some reachable state satisfies p; the trace is a shortest witness.
template <class Model, class Pred>
verdict reachable(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    for (std::size_t i = 0; i < ex.count(); ++i)
        if (p(ex.at(i))) return {"E<> " + name, verdict::status::holds, detail::path_to(ex, i), {}};
    if (!ex.stats().complete) return detail::incomplete(ex, "E<> " + name);
    return {"E<> " + name, verdict::status::fails, {}, {}};
}

/// Every reachable state has a successor other than itself, unless `is_final` holds in it.
template <class Model, class Final>
verdict deadlock_free(explorer<Model>& ex, Final is_final) {
    ex.run();
    std::string const name = "deadlock freedom";
    for (std::size_t i = 0; i < ex.count(); ++i) {
        bool moves = false;
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i) && !moves; ++e) moves = ex.edge_target(e) != i;
        if (!moves && !is_final(ex.at(i)) && (ex.stats().complete || ex.edges_end(i) > ex.edges_begin(i)))
            return {name, verdict::status::fails, detail::path_to(ex, i), "no successor but itself"};
    }
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    return {name, verdict::status::holds, {}, {}};
}

template <class Model>
verdict deadlock_free(explorer<Model>& ex) {
    return deadlock_free(ex, [](auto const&) { return false; });
}

}  // namespace bsc::verify

namespace bsc::detail {
// The graph's edges reversed, as adjacency arrays: the predecessors of i are
// from[begin[i]] .. from[begin[i + 1] - 1] (one entry per edge).
struct reverse_graph {
    std::vector<std::uint32_t> begin, from;
};
template <class Model>
reverse_graph reversed(verify::explorer<Model> const& ex) {
    std::size_t const n = ex.count();
    reverse_graph g{std::vector<std::uint32_t>(n + 1, 0), std::vector<std::uint32_t>(ex.stats().transitions)};
    for (std::size_t i = 0; i < n; ++i)
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i); ++e) ++g.begin[ex.edge_target(e) + 1];
    for (std::size_t i = 0; i < n; ++i) g.begin[i + 1] += g.begin[i];
    std::vector<std::uint32_t> fill(g.begin.begin(), g.begin.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i); ++e)
            g.from[fill[ex.edge_target(e)]++] = static_cast<std::uint32_t>(i);
    return g;
}

// The first state (in breadth-first order, so with a shortest path to it) from which no
// state marked in `goal` can be reached, or none.
template <class Model>
std::size_t first_cut_off(verify::explorer<Model> const& ex, std::vector<char> const& goal) {
    std::size_t const n = ex.count();
    reverse_graph const g = reversed(ex);
    std::vector<char> back(n, 0);
    std::vector<std::uint32_t> queue;
    for (std::size_t i = 0; i < n; ++i)
        if (goal[i]) {
            back[i] = 1;
            queue.push_back(static_cast<std::uint32_t>(i));
        }
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (auto e = g.begin[queue[k]]; e < g.begin[queue[k] + 1]; ++e)
            if (!back[g.from[e]]) {
                back[g.from[e]] = 1;
                queue.push_back(g.from[e]);
            }
    for (std::size_t i = 0; i < n; ++i)
        if (!back[i]) return i;
    return verify::explorer<Model>::none;
}

// No path bound: a state from which some path never reaches q (a cycle or a dead end without q).
inline constexpr std::size_t never = static_cast<std::size_t>(-1);

// For each state, the most steps a path from it can take before it reaches a state marked in
// `is_q` (0 for those), or `never`. The least fixpoint, by a backward worklist from q: a state
// with successors is settled when its last successor is, one step beyond the slowest of them.
template <class Model>
std::vector<std::size_t> steps_to(verify::explorer<Model> const& ex, std::vector<char> const& is_q) {
    std::size_t const n = ex.count();
    std::vector<std::size_t> slowest(n, never);
    std::vector<std::uint32_t> unsettled(n), queue;
    for (std::size_t i = 0; i < n; ++i) {
        unsettled[i] = ex.edges_end(i) - ex.edges_begin(i);
        if (is_q[i]) {
            slowest[i] = 0;
            queue.push_back(static_cast<std::uint32_t>(i));
        }
    }
    reverse_graph const g = reversed(ex);
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (auto e = g.begin[queue[k]]; e < g.begin[queue[k] + 1]; ++e) {
            std::uint32_t const i = g.from[e];
            if (slowest[i] != never || --unsettled[i] != 0) continue;
            std::size_t most = 0;  // every successor is settled, so finite
            for (auto f = ex.edges_begin(i); f < ex.edges_end(i); ++f)
                most = std::max(most, slowest[ex.edge_target(f)]);
            slowest[i] = most + 1;
            queue.push_back(i);
        }
    return slowest;
}
}  // namespace bsc::detail

namespace bsc::verify {

/// AG EF p: from every reachable state, some path reaches a p-state (the vivacity of the Basic
/// Statechart paper [BSC], docs/references.md, for p = "the device operates"). Fails with a path
/// to a state from which p is out of reach.
template <class Model, class Pred>
verdict always_reachable(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    name = "AG EF " + name;
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::vector<char> goal(ex.count());
    for (std::size_t i = 0; i < ex.count(); ++i) goal[i] = p(ex.at(i));
    std::size_t const cut = detail::first_cut_off(ex, goal);
    if (cut != explorer<Model>::none)
        return {name, verdict::status::fails, detail::path_to(ex, cut), "unreachable from the last state"};
    return {name, verdict::status::holds, {}, {}};
}

/// The initial state is reachable from every reachable state (the reinitiability of [BSC]).
template <class Model>
verdict reinitiable(explorer<Model>& ex) {
    ex.run();
    std::string const name = "reinitiability";
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::vector<char> goal(ex.count(), 0);
    goal[0] = 1;
    std::size_t const cut = detail::first_cut_off(ex, goal);
    if (cut != explorer<Model>::none)
        return {name, verdict::status::fails, detail::path_to(ex, cut),
                "the initial state is unreachable from the last state"};
    return {name, verdict::status::holds, {}, {}};
}

/// Reinitiability up to an equivalence: from every reachable state, a state `equivalent` to the
/// initial one can be reached, e.g. the same active configuration whatever the variables
/// (the reachability tree of [BSC] is over configurations). `equivalent(state, initial)`.
template <class Model, class Equivalent>
verdict reinitiable(explorer<Model>& ex, Equivalent equivalent) {
    ex.run();
    auto const initial = ex.at(0);
    verdict v = always_reachable(ex, "", [&](auto const& s) { return equivalent(s, initial); });
    v.property = "reinitiability (up to equivalence)";
    return v;
}

/// p --> q: from every reachable p-state, every path reaches a q-state. No fairness is
/// assumed: a cycle of non-q states, or a deadlock, after a p-state is a counterexample
/// (the trace ends where the loop closes).
template <class Model, class P, class Q>
verdict leads_to(explorer<Model>& ex, std::string name, P p, Q q) {
    ex.run();
    name = name.empty() ? "p --> q" : name;
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::size_t const n = ex.count();
    std::vector<char> is_q(n), is_p(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto const s = ex.at(i);
        is_q[i] = q(s);
        is_p[i] = p(s);
    }
    // sure[i]: every path from i reaches q.
    std::vector<std::size_t> const slowest = detail::steps_to(ex, is_q);
    auto const sure = [&](std::size_t i) { return slowest[i] != detail::never; };
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_p[i] || sure(i)) continue;
        auto trace = detail::path_to(ex, i);
        // Continue through states that can avoid q until one repeats or nothing follows.
        std::vector<char> seen(n, 0);
        std::size_t s = i;
        seen[s] = 1;
        std::string how = "no successor";
        for (;;) {
            std::size_t next = n;
            std::uint16_t label = 0;
            for (auto e = ex.edges_begin(s); e < ex.edges_end(s); ++e)
                if (!sure(ex.edge_target(e))) {
                    next = ex.edge_target(e);
                    label = ex.edge_label(e);
                    break;
                }
            if (next == n) break;
            detail::append_step(ex, trace, ex.model().label(label), next);
            if (seen[next]) {
                how = "loops without reaching q";
                break;
            }
            seen[next] = 1;
            s = next;
        }
        return {name, verdict::status::fails, std::move(trace),
                "from step " + std::to_string(detail::path_to(ex, i).size() - 1) + ": " + how};
    }
    return {name, verdict::status::holds, {}, {}};
}

/// p --> q within `bound`: from every reachable p-state, every path reaches a q-state within
/// `bound` (a q-state reached `bound` after p counts; so does q holding in the p-state itself).
/// What a safety engineer asks of a controller: "the press stops within 200 ms of the guard
/// opening". Time is the model's steps: the model is stepped with a period (cycle_model,
/// system_model), and `bound` covers floor(bound / period) steps. A deadlock or a cycle of non-q
/// states after a p-state also fails it. The counterexample runs to the p-state by a shortest
/// path, then along the slowest way to q for one step more than the bound allows.
template <class Model, class P, class Q>
verdict leads_to_within(explorer<Model>& ex, std::string name, P p, Q q, duration bound) {
    static_assert(detail::timed_model<Model>,
                  "bsc::verify::leads_to_within needs a model stepped with a period (cycle_model, system_model): "
                  "a bound in time has no meaning for an event_model");
    if (bound < duration::zero()) detail::refuse_argument("bsc::verify::leads_to_within: the bound is negative");
    if (ex.model().period() <= duration::zero())
        detail::refuse_argument("bsc::verify::leads_to_within: the model's period is not positive");
    ex.run();
    name = (name.empty() ? "p --> q" : name) + " within " + bsc::detail::delay_label(bound);
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::size_t const n = ex.count();
    auto const steps = static_cast<std::size_t>(bound / ex.model().period());
    std::vector<char> is_p(n), is_q(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto const s = ex.at(i);
        is_p[i] = p(s);
        is_q[i] = q(s);
    }
    std::vector<std::size_t> const slowest = detail::steps_to(ex, is_q);
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_p[i] || slowest[i] <= steps) continue;
        auto trace = detail::path_to(ex, i);
        std::size_t const start = trace.size() - 1;
        // Follow the slowest successor until the bound is passed, or a deadlock or a loop; among
        // equally slow ones, an unseen state, then the choice of the step before (so that a run
        // of the same choice folds into one line of the report).
        std::vector<char> seen(n, 0);
        std::size_t s = i;
        seen[s] = 1;
        std::uint16_t previous = i == 0 ? std::uint16_t{0} : ex.parent_label(i);
        std::string how = "q does not hold " + bsc::detail::delay_label(bound) + " later";
        for (std::size_t taken = 0; taken <= steps; ++taken) {
            std::size_t next = n;
            std::uint16_t label = 0;
            auto const better = [&](std::size_t t, std::uint16_t l) {
                if (next == n || slowest[t] != slowest[next]) return next == n || slowest[t] > slowest[next];
                if (seen[t] != seen[next]) return !seen[t];
                return l == previous && label != previous;
            };
            for (auto e = ex.edges_begin(s); e < ex.edges_end(s); ++e)
                if (better(ex.edge_target(e), ex.edge_label(e))) {
                    next = ex.edge_target(e);
                    label = ex.edge_label(e);
                }
            if (next == n) {
                how = "no successor, q never holds";
                break;
            }
            detail::append_step(ex, trace, ex.model().label(label), next);
            if (seen[next] && taken < steps) {
                how = "loops without reaching q";
                break;
            }
            seen[next] = 1;
            s = next;
            previous = label;
        }
        return {name, verdict::status::fails, std::move(trace),
                "p holds at step " + std::to_string(start) + "; " + how};
    }
    return {name, verdict::status::holds, {}, {}};
}

}  // namespace bsc::verify
// end include/bsc/verify/properties.hpp
// end include/bsc/verify.hpp
