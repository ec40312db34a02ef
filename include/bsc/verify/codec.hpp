#pragma once
// Fixed-size byte encodings of explored states: a machine's configuration bytes, its context
// member by member (no hand-written code for plain aggregates), and time made relative to the
// machine's clock and counted in cycles, capped where more time changes nothing. Two states
// with equal encodings behave the same.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <bsc/compiled/machine.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/fields.hpp>

namespace bsc::verify::detail {

using bsc::detail::machine_access;
using bsc::detail::timer_access;

template <class T>
inline constexpr bool is_machine = false;
template <class C, class P, class O>
inline constexpr bool is_machine<bsc::machine<C, P, O>> = true;

}  // namespace bsc::verify::detail

namespace bsc::verify {
/// Specialize as true for a context member type that does not influence behaviour (a log, a
/// display, statistics): the explorer neither stores nor compares it, so it cannot split or
/// multiply states. Decoded states keep the initial value of such members.
template <class T>
inline constexpr bool unexplored = false;
}  // namespace bsc::verify

namespace bsc::verify::detail {

template <class T>
constexpr bool is_aggregate_class() {
    return std::is_class_v<T> && std::is_aggregate_v<T> && !std::is_base_of_v<bsc::detail::channel_base, T>;
}

// Time as the codec sees it: the clock of the enclosing machine and the cycle period
// (zero for models that never step, where time does not pass).
struct time_frame {
    duration clock{};
    duration period{};
    constexpr std::uint16_t cycles(duration d, duration cap) const {
        if (period <= duration::zero() || d <= duration::zero()) return 0;
        auto const capped = std::min(d, cap + period);
        return static_cast<std::uint16_t>(capped / period);
    }
};

template <class T>
constexpr std::size_t encoded_size();

template <class Tuple>
struct fields_size;
template <class... F>
struct fields_size<std::tuple<F&...>> {
    static constexpr std::size_t value = (std::size_t{0} + ... + encoded_size<std::remove_cv_t<F>>());
};

template <class T>
constexpr std::size_t encoded_size() {
    if constexpr (unexplored<T>) {
        return 0;
    } else if constexpr (is_machine<T>) {
        using ctx = typename T::context_type;
        return (std::is_empty_v<typename T::configuration_type> ? 0 : sizeof(typename T::configuration_type)) +
               encoded_size<ctx>() +
               2 * std::tuple_size_v<std::remove_reference_t<decltype(machine_access::armed(std::declval<T&>()))>>;
    } else if constexpr (std::is_same_v<T, timer>) {
        return 4;
    } else if constexpr (is_aggregate_class<T>()) {
        return fields_size<decltype(bsc::detail::tie_fields(std::declval<T&>()))>::value;
    } else {
        static_assert(std::is_trivially_copyable_v<T>,
                      "bsc: the explorer encodes scalars, enums, channels, timers, machines and aggregates of "
                      "them; this member type is none of those");
        return sizeof(T);
    }
}

template <class T>
void encode(T const& value, std::byte*& out, time_frame frame);
template <class T>
void decode(T& value, std::byte const*& in, time_frame frame);

inline void put16(std::byte*& out, std::uint16_t v) {
    std::memcpy(out, &v, 2);
    out += 2;
}
inline std::uint16_t get16(std::byte const*& in) {
    std::uint16_t v;
    std::memcpy(&v, in, 2);
    in += 2;
    return v;
}

template <class T>
void encode(T const& value, std::byte*& out, time_frame frame) {
    if constexpr (unexplored<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        auto& m = const_cast<T&>(value);
        auto const cfg = machine_access::canonical_configuration(m);
        if constexpr (!std::is_empty_v<std::remove_cvref_t<decltype(cfg)>>) {
            std::memcpy(out, cfg.active.data(), cfg.active.size());
            out += cfg.active.size();
        }
        time_frame const own{machine_access::clock(m), frame.period};
        encode(m.context(), out, own);
        auto const& armed = machine_access::armed(m);
        for (std::size_t i = 0; i < armed.size(); ++i)
            put16(out, machine_access::timeout_armed(m, i)
                           ? own.cycles(own.clock - armed[i], machine_access::longest_timeout(m))
                           : 0);
    } else if constexpr (std::is_same_v<T, timer>) {
        *out++ = static_cast<std::byte>(timer_access::phase(value));
        *out++ = static_cast<std::byte>(value.expired());
        bool const timing = timer_access::phase(value) == 2;  // running, expired or not
        put16(out, timing ? frame.cycles(frame.clock - timer_access::started(value), value.limit()) : 0);
    } else if constexpr (is_aggregate_class<T>()) {
        bsc::detail::for_each_field(value, [&](auto const& field) { encode(field, out, frame); });
    } else {
        std::memcpy(out, &value, sizeof(T));
        out += sizeof(T);
    }
}

template <class T>
void decode(T& value, std::byte const*& in, time_frame frame) {
    if constexpr (unexplored<T>) {
        return;
    } else if constexpr (is_machine<T>) {
        auto& cfg = machine_access::configuration(value);
        if constexpr (!std::is_empty_v<std::remove_cvref_t<decltype(cfg)>>) {
            std::memcpy(cfg.active.data(), in, cfg.active.size());
            in += cfg.active.size();
        }
        machine_access::clock(value) = frame.clock;
        decode(value.context(), in, frame);
        for (auto& armed : machine_access::armed(value)) armed = frame.clock - get16(in) * frame.period;
    } else if constexpr (std::is_same_v<T, timer>) {
        auto const phase = static_cast<std::uint8_t>(*in++);
        bool const expired = *in++ != std::byte{0};
        auto const elapsed = get16(in) * frame.period;
        timer_access::set(value, phase, expired, frame.clock - elapsed, elapsed);
    } else if constexpr (is_aggregate_class<T>()) {
        bsc::detail::for_each_field(value, [&](auto& field) { decode(field, in, frame); });
    } else {
        std::memcpy(&value, in, sizeof(T));
        in += sizeof(T);
    }
}

}  // namespace bsc::verify::detail
