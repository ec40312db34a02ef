#pragma once
// The members a recorder shows (the waveform, the trace stream): the channels of a scalar type,
// the timers and the plain scalar variables of a context, walked by the member layer
// (detail/members.hpp) with their names, each leaf given as a kind, a width and a value.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/data/channel.hpp>
#include <bsc/data/timer.hpp>
#include <bsc/detail/members.hpp>

namespace bsc::detail::recorded {

// integer: a signed integral type; reg: an unsigned one, an enum or a bool wider than a wire.
enum class var_kind : std::uint8_t { wire, integer, reg, real, string };

// One variable's value: the bits of a wire or integer, a real, or a string's text (a state's
// name, which lives as long as the program).
struct value {
    std::uint64_t bits = 0;
    double real = 0;
    std::string_view text;
    friend bool operator==(value const& a, value const& b) {
        // Reals compare by representation, so that a NaN equals itself and is written once.
        return a.bits == b.bits && std::bit_cast<std::uint64_t>(a.real) == std::bit_cast<std::uint64_t>(b.real) &&
               a.text == b.text;
    }
};

template <class T>
constexpr bool is_scalar_variable = std::is_arithmetic_v<T> || std::is_enum_v<T>;

template <class T>
value scalar_value(T v) {
    value out;
    if constexpr (std::is_floating_point_v<T>) {
        out.real = static_cast<double>(v);
    } else if constexpr (std::is_enum_v<T>) {
        out.bits = static_cast<std::uint64_t>(
            static_cast<std::make_unsigned_t<std::underlying_type_t<T>>>(static_cast<std::underlying_type_t<T>>(v)));
    } else if constexpr (std::is_same_v<T, bool>) {
        out.bits = v ? 1 : 0;
    } else {
        out.bits = static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(v));
    }
    return out;
}

template <class T>
constexpr var_kind var_kind_of() {
    if constexpr (std::is_same_v<T, bool>)
        return var_kind::wire;
    else if constexpr (std::is_floating_point_v<T>)
        return var_kind::real;
    else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>)
        return var_kind::integer;
    else
        return var_kind::reg;
}

template <class T>
constexpr unsigned width_of() {
    if constexpr (std::is_same_v<T, bool>)
        return 1;
    else if constexpr (std::is_floating_point_v<T>)
        return 64;
    else
        return 8 * sizeof(T);
}

// What the recorder shows: a channel of a scalar type, a timer, a plain scalar variable, found
// by the member layer (detail/members.hpp) as the machine finds its channels.
template <class T>
constexpr bool is_recorded() {
    if constexpr (is_channel<T>)
        return is_scalar_variable<channel_value<T>>;
    else
        return is_timer<T> || is_scalar_variable<T>;
}

// An array's element as the recorders name it: name_0, name_1, ...
inline std::string element_name(std::string_view name, std::size_t i) {
    return std::string{name} + "_" + std::to_string(i);
}

// Walks a context's recorded members, calling the visitor's scope(name), upscope() and
// var(kind, width, name, value), in declaration order: a struct is a scope, a timer a scope of
// three variables, an array's elements are name_0, name_1, ...
template <class Visitor>
struct recorded_members {
    static constexpr bool named = true;
    template <class T>
    static constexpr bool visits = is_recorded<T>();
    Visitor& v;
    std::string element_name(std::string_view name, std::size_t i) const { return recorded::element_name(name, i); }
    void enter(std::string_view name) { v.scope(name); }
    void leave() { v.upscope(); }
    template <class T>
    void leaf(T const& member, std::string_view name) {
        if constexpr (is_channel<T>) {
            using V = channel_value<T>;
            v.var(var_kind_of<V>(), width_of<V>(), name, scalar_value(member.get()));
        } else if constexpr (is_timer<T>) {
            v.scope(name);
            v.var(var_kind::wire, 1, "running", scalar_value(member.running()));
            v.var(var_kind::wire, 1, "expired", scalar_value(member.expired()));
            v.var(var_kind::integer, 64, "elapsed", scalar_value(static_cast<std::int64_t>(member.elapsed().count())));
            v.upscope();
        } else {
            v.var(var_kind_of<T>(), width_of<T>(), name, scalar_value(member));
        }
    }
};

}  // namespace bsc::detail::recorded
