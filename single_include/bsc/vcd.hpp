#pragma once
// bsc::vcd_recorder - waveforms of a machine's scans, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/vcd.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/vcd.hpp
// bsc::vcd_recorder: writes what a machine does, scan by scan, as a value change dump (VCD,
// IEEE 1364-2005 section 18), the waveform format of GTKWave and of every hardware and PLC
// engineer's viewer:
//
//   bsc::machine m{cell::chart};
//   std::ofstream file{"cell.vcd"};
//   bsc::vcd_recorder vcd{file, m};
//   for (bsc::duration t{}; ...; t += 100ms) { m.step(t); vcd.sample(); }
//
// Each sample records, at the machine's time, what changed since the last one:
//   scope "states":  for each composite state (each component of a parallel state is one), the
//                    name of its active child ("-" while the composite is inactive), as a
//                    GTKWave string variable; and in scope "active" one wire per state, 1 while
//                    the state is active;
//   scope "data":    the context by member name: every channel's value (an input as latched, an
//                    output as published), every timer (scope with `running`, `expired`,
//                    `elapsed` in ns) and every plain variable of type bool (wire), signed
//                    integer (integer), unsigned integer or enum (reg) or floating point (real);
//                    aggregates as scopes, std::array elements as name_0, name_1, ...
//                    Members of other types (strings, handles) are not recorded, nor transient
//                    members (bsc::transient).
// Names keep their spelling but for whitespace, which becomes '_'. Numbers are written the same
// whatever the stream's locale. The recorder's destruction writes the last sample's time.
//
// Opt-in: <bsc/bsc.hpp> does not include it; a machine never knows it is recorded, so a
// program that does not sample pays nothing.

#include <array>
#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

// begin include/bsc/detail/recorded_members.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
// The members a recorder shows (the waveform, the trace stream): the channels of a scalar type,
// the timers and the plain scalar variables of a context, walked by the member layer
// (detail/members.hpp) with their names, each leaf given as a kind, a width and a value.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>


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
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
// end include/bsc/detail/recorded_members.hpp

namespace bsc::detail::vcd {

// Identifiers of variables: the printable characters '!' to '~' but for '#' and '$' (legal,
// but they start a time and a keyword, which trips simple readers), in base 92.
inline std::string identifier(std::size_t n) {
    constexpr std::string_view digits =
        "!\"%&'()*+,-./0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\]^_`abcdefghijklmnopqrstuvwxyz{|}~";
    static_assert(digits.size() == 92);
    std::string id;
    do {
        id += digits[n % digits.size()];
        n /= digits.size();
    } while (n > 0);
    return id;
}

// A name as VCD needs it: no whitespace or control characters, which would split it (a state
// named by a template, "Mode<1, 2>", becomes "Mode<1,_2>").
inline std::string token(std::string_view name) {
    std::string out{name};
    for (char& c : out)
        if (static_cast<unsigned char>(c) <= ' ' || c == '\x7f') c = '_';
    return out.empty() ? std::string{"_"} : out;
}

// Numbers through std::to_chars: the stream's locale and flags must not change the file.
template <class T>
std::string number(T v) {
    char buffer[40];
    auto const result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

inline void write_value(std::ostream& out, recorded::var_kind kind, recorded::value const& v, std::string const& id) {
    switch (kind) {
        case recorded::var_kind::wire:
            if (v.bits <= 1) {
                out << (v.bits ? '1' : '0') << id << '\n';
                return;
            }
            [[fallthrough]];
        case recorded::var_kind::integer:
        case recorded::var_kind::reg: {
            // Leading zeros are left out: a reader extends a vector's value with zeros.
            std::string digits;
            for (std::uint64_t b = v.bits; b != 0; b >>= 1) digits.insert(digits.begin(), (b & 1) ? '1' : '0');
            out << 'b' << (digits.empty() ? "0" : digits) << ' ' << id << '\n';
            return;
        }
        case recorded::var_kind::real:
            // The shortest text that reads back as the same double.
            out << 'r' << number(v.real) << ' ' << id << '\n';
            return;
        case recorded::var_kind::string: out << 's' << token(v.text) << ' ' << id << '\n'; return;
    }
}

}  // namespace bsc::detail::vcd

namespace bsc {

/// Records a machine's states, channels, timers and variables as a value change dump (VCD).
/// Construction writes the header (the variables); each sample() writes what changed since the
/// last, at the machine's time (step(now)'s `now`; nanoseconds, `$timescale 1 ns`). Sample after
/// each step (or dispatch). Requirements: the machine and the stream outlive the recorder; the
/// machine's context is an aggregate (as for any machine with channels).
template <class Machine>
class vcd_recorder {
public:
    using machine_type = Machine;

    /// Writes the header to `out`. `top` names the outermost scope (by default the chart's root state).
    vcd_recorder(std::ostream& out, Machine const& machine, std::string_view top = {}) : out_(out), machine_(machine) {
        out_ << "$comment bsc::vcd_recorder: the states, channels, timers and variables of one machine $end\n"
             << "$timescale 1 ns $end\n"
             << "$scope module " << detail::vcd::token(top.empty() ? state_names[root] : top) << " $end\n";
        declare declaring{*this};
        visit(declaring);
        out_ << "$upscope $end\n$enddefinitions $end\n";
    }

    /// Writes the time of the last sample if nothing changed at it, so that a viewer shows the
    /// whole run.
    ~vcd_recorder() {
        if (sampled_ && time_ != stamp_) out_ << '#' << detail::vcd::number(time_) << '\n';
    }

    vcd_recorder(vcd_recorder const&) = delete;
    vcd_recorder& operator=(vcd_recorder const&) = delete;

    /// Records the machine's present values at its time: on the first call all of them
    /// ($dumpvars), then those that changed. A time earlier than the last sample's (a clock
    /// before zero) is written as the last sample's time, so that the file's times never decrease.
    void sample() {
        duration::rep t = machine_.now().count();
        if (t < time_) t = time_;
        compare comparing{*this, t};
        visit(comparing);
        if (!sampled_) {
            out_ << "$end\n";  // closes the first sample's $dumpvars
            sampled_ = true;
        }
        time_ = t;
        ++samples_;
    }

    /// The number of variables in the file.
    std::size_t variables() const { return vars_.size(); }
    /// The number of samples taken.
    std::size_t samples() const { return samples_; }

private:
    using model = detail::chart_model<typename Machine::chart_type>;
    static constexpr auto const& tree = model::tree;
    static constexpr int root = 1;
    static constexpr auto state_count = static_cast<std::size_t>(model::N);
    static constexpr auto const& state_names = detail::state_names_of<model>;

    struct variable {
        detail::recorded::var_kind kind;
        std::string id;
        detail::recorded::value last;
    };

    // Writes the declarations and keeps the variables.
    struct declare {
        vcd_recorder& self;
        void scope(std::string_view name) { self.out_ << "$scope module " << detail::vcd::token(name) << " $end\n"; }
        void upscope() { self.out_ << "$upscope $end\n"; }
        void var(detail::recorded::var_kind kind, unsigned width, std::string_view name,
                 detail::recorded::value const&) {
            static constexpr char const* kinds[] = {"wire", "integer", "reg", "real", "string"};
            auto id = detail::vcd::identifier(self.vars_.size());
            self.out_ << "$var " << kinds[static_cast<int>(kind)] << ' ' << detail::vcd::number(width) << ' ' << id
                      << ' ' << detail::vcd::token(name) << " $end\n";
            // The first sample writes every value: the "last" one is marked as never seen.
            self.vars_.push_back({kind, std::move(id), {}});
        }
    };

    // Writes the values that changed (all of them on the first sample).
    struct compare {
        vcd_recorder& self;
        duration::rep time;
        std::size_t next = 0;
        bool written = false;
        void scope(std::string_view) {}
        void upscope() {}
        void var(detail::recorded::var_kind, unsigned, std::string_view, detail::recorded::value const& v) {
            variable& var = self.vars_[next++];
            if (self.sampled_ && var.last == v) return;
            if (!written) {
                if (!self.stamped_ || time != self.stamp_) self.out_ << '#' << detail::vcd::number(time) << '\n';
                self.stamp_ = time;
                if (!self.sampled_) self.out_ << "$dumpvars\n";
                self.stamped_ = true;
                written = true;
            }
            detail::vcd::write_value(self.out_, var.kind, v, var.id);
            var.last = v;
        }
    };

    template <class Visitor>
    void visit(Visitor& v) const {
        auto const active = detail::access::active_flags(machine_);
        v.scope("states");
        // Each composite state's active child, by name.
        for (std::size_t s = 1; s < state_count; ++s) {
            if (tree.kinds[s] != detail::kind::composite) continue;
            detail::recorded::value current;
            current.text = "-";
            for (int c = tree.first_child[s]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (active[static_cast<std::size_t>(c)]) current.text = state_names[static_cast<std::size_t>(c)];
            v.var(detail::recorded::var_kind::string, 1, state_names[s], current);
        }
        v.scope("active");
        for (std::size_t s = 1; s < state_count; ++s)
            v.var(detail::recorded::var_kind::wire, 1, state_names[s], detail::recorded::scalar_value(bool{active[s]}));
        v.upscope();
        v.upscope();
        using members_visitor = detail::recorded::recorded_members<Visitor>;
        if constexpr (detail::reaches<members_visitor, typename Machine::context_type>()) {
            members_visitor data{v};
            detail::walk(machine_.context(), data, std::string_view{"data"});
        }
    }

    std::ostream& out_;
    Machine const& machine_;
    std::vector<variable> vars_;
    duration::rep time_ = 0;   // the last sample's time
    duration::rep stamp_ = 0;  // the last time written (#t)
    std::size_t samples_ = 0;
    bool sampled_ = false;  // the first sample ($dumpvars) is written
    bool stamped_ = false;  // a time is written: stamp_ is the file's present time
};

template <class Machine>
vcd_recorder(std::ostream&, Machine const&) -> vcd_recorder<Machine>;
template <class Machine>
vcd_recorder(std::ostream&, Machine const&, std::string_view) -> vcd_recorder<Machine>;

}  // namespace bsc
// end include/bsc/vcd.hpp
