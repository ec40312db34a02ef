#pragma once
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

#include <bsc/machine.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/key_field.hpp>
#include <bsc/detail/member_path.hpp>
#include <bsc/detail/members.hpp>
#include <bsc/detail/state_bytes.hpp>
#include <bsc/detail/runtime/driver.hpp>
#include <bsc/detail/runtime/queue_for.hpp>

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
