#pragma once
// Fixed-size byte encodings of explored states: a machine's configuration bytes, its context
// member by member (no hand-written code for plain aggregates), and time made relative to the
// machine's clock and counted in cycles, capped where more time changes nothing. Two states
// with equal encodings behave the same.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <bsc/compiled/machine.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/fields.hpp>
#include <bsc/runtime/driver.hpp>
#include <bsc/runtime/queue_for.hpp>

namespace bsc::verify {
/// Specialize as true for a context member type that does not influence behaviour (a log, a
/// display, statistics): the explorer neither stores nor compares it, so it cannot split or
/// multiply states. Decoded states keep the initial value of such members.
template <class T>
inline constexpr bool unexplored = false;
}  // namespace bsc::verify

namespace bsc::detail {

template <class T>
constexpr bool is_aggregate_class() {
    return std::is_class_v<T> && std::is_aggregate_v<T> && !std::is_base_of_v<bsc::detail::channel_base, T>;
}

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
        if (model::tree.slot[s] >= 0) bits[static_cast<std::size_t>(model::tree.slot[s])] = bits_for(model::tree.child_count[s]);
    return bits;
}

template <class T>
constexpr std::size_t encoded_bits();

template <class Tuple>
struct fields_bits;
template <class... F>
struct fields_bits<std::tuple<F&...>> {
    static constexpr std::size_t value = (std::size_t{0} + ... + encoded_bits<std::remove_cv_t<F>>());
};


template <class T>
constexpr std::size_t encoded_bits() {
    if constexpr (verify::unexplored<T>) {
        return 0;
    } else if constexpr (is_machine<T>) {
        if constexpr (keeps_pending_events<chart_model<typename T::chart_type>>())
            detail::report<error::pending_events_not_encoded<typename T::chart_type>>();
        std::size_t config = 0;
        for (unsigned b : slot_bits<T>()) config += b;
        constexpr std::size_t timeouts = std::remove_cvref_t<decltype(access::armed(std::declval<T&>()))>{}.size();
        return config + encoded_bits<typename T::context_type>() + cycle_bits * timeouts;
    } else if constexpr (std::is_same_v<T, timer>) {
        return 2 + 1 + cycle_bits;  // phase, expired, periods since timing began
    } else if constexpr (std::is_same_v<T, bool>) {
        return 1;
    } else if constexpr (is_channel<T>) {
        return 2 * encoded_bits<channel_value<T>>();  // pending and current values
    } else if constexpr (is_aggregate_class<T>()) {
        return fields_bits<decltype(bsc::detail::tie_fields(std::declval<T&>()))>::value;
    } else {
        static_assert(std::is_trivially_copyable_v<T>,
                      "bsc: the explorer encodes scalars, enums, channels, timers, machines and aggregates of "
                      "them; this member type is none of those");
        return 8 * sizeof(T);
    }
}

template <class T>
constexpr std::size_t encoded_size() {
    return (encoded_bits<T>() + 7) / 8;
}

template <class T>
void encode(T const& value, bit_writer& out, time_frame frame);
template <class T>
void decode(T& value, bit_reader& in, time_frame frame);

template <class V>
void encode_value(V const& v, bit_writer& out) {
    if constexpr (std::is_same_v<V, bool>)
        out.put(v ? 1u : 0u, 1);
    else
        out.put_bytes(&v, sizeof(V));
}
template <class V>
V decode_value(bit_reader& in) {
    if constexpr (std::is_same_v<V, bool>) {
        return in.get(1) != 0;
    } else {
        V v;
        in.get_bytes(&v, sizeof(V));
        return v;
    }
}

template <class T>
void encode(T const& value, bit_writer& out, time_frame frame) {
    if constexpr (verify::unexplored<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        auto& m = const_cast<T&>(value);
        auto const cfg = access::canonical_configuration(m);
        constexpr auto bits = slot_bits<T>();
        for (std::size_t k = 0; k < bits.size(); ++k) out.put(cfg.active[k], bits[k]);
        time_frame const own{access::clock(m), frame.period};
        encode(m.context(), out, own);
        auto const& armed = access::armed(m);
        for (std::size_t i = 0; i < armed.size(); ++i)
            out.put(access::timeout_armed(m, i)
                        ? own.cycles(armed[i], access::longest_timeout(m))
                        : 0,
                    cycle_bits);
    } else if constexpr (std::is_same_v<T, timer>) {
        out.put(access::timer_phase(value), 2);
        out.put(value.expired() ? 1u : 0u, 1);
        bool const timing = access::timer_phase(value) == 2;  // running, expired or not
        out.put(timing ? frame.cycles(access::timer_started(value), value.limit()) : 0, cycle_bits);
    } else if constexpr (is_channel<T>) {
        encode(value.pending(), out, frame);  // a channel of an aggregate: member by member too
        encode(value.get(), out, frame);
    } else if constexpr (is_aggregate_class<T>()) {
        bsc::detail::for_each_field(value, [&](auto const& field) { encode(field, out, frame); });
    } else {
        encode_value(value, out);
    }
}

template <class T>
void decode(T& value, bit_reader& in, time_frame frame) {
    if constexpr (verify::unexplored<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        auto& cfg = access::configuration(value);
        constexpr auto bits = slot_bits<T>();
        for (std::size_t k = 0; k < bits.size(); ++k) cfg.active[k] = static_cast<std::uint8_t>(in.get(bits[k]));
        access::set_clock(value, frame.clock);
        decode(value.context(), in, frame);
        for (auto& armed : access::armed(value))
            armed = frame.before(in.get(cycle_bits));
    } else if constexpr (std::is_same_v<T, timer>) {
        auto const phase = static_cast<std::uint8_t>(in.get(2));
        bool const expired = in.get(1) != 0;
        auto const started = frame.before(in.get(cycle_bits));
        access::set_timer(value, phase, expired, started, frame.clock - started);
    } else if constexpr (is_channel<T>) {
        using V = channel_value<T>;
        V pending = value.pending();
        V current = value.get();
        decode(pending, in, frame);
        decode(current, in, frame);
        value.set(current);  // both values, through the channel's own cycle boundary
        access::latch(value);
        access::commit(value);
        value.set(pending);
    } else if constexpr (is_aggregate_class<T>()) {
        bsc::detail::for_each_field(value, [&](auto& field) { decode(field, in, frame); });
    } else {
        value = decode_value<T>(in);
    }
}

}  // namespace bsc::detail
