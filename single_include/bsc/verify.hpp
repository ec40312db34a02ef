#pragma once
// bsc::verify - the state-space explorer, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/verify.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/verify.hpp
// bsc::verify: exhaustive exploration of closed models of bsc machines, and the properties
// checked on it. Not included by <bsc/bsc.hpp>: it uses the heap and the standard library's
// strings and vectors, which the machines themselves never need.

// begin include/bsc/verify/codec.hpp
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
// end include/bsc/verify/codec.hpp
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

#include <algorithm>
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

    std::size_t memory() const {
        return keys_.capacity() + table_.capacity() * 4 + parent_.capacity() * 4 + via_.capacity() * 2 +
               edge_begin_.capacity() * 4 + edge_to_.capacity() * 4 +
               edge_label_.capacity() * 2;
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
    return coverage(ex, fired, [](auto const& m) -> auto const& { return m; });
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
    T decode(T prototype, std::byte const* in) const {
        bit_reader reader{in, encoded_bits<T>()};
        detail::decode(prototype, reader, time_frame{origin, period});
        if (reader.bits() != encoded_bits<T>()) std::abort();
        return prototype;
    }
};
}  // namespace bsc::detail

namespace bsc::verify {

/// Offers each of the events Es... to the machine in every state (dispatch).
template <class Machine, class... Es>
class event_model {
public:
    using state = Machine;
    static constexpr std::size_t key_size = detail::codec<Machine>::key_size;

    explicit event_model(Machine initial) : initial_(std::move(initial)) {}

    state initial() const { return initial_; }
    void encode(state const& s, std::byte* out) const { codec_.encode(s, out); }
    state decode(std::byte const* in) const { return codec_.decode(initial_, in); }
    template <class Emit>
    void successors(state const& s, Emit&& emit) const {
        std::uint16_t label = 0;
        (
            [&] {
                state next = s;
                next.dispatch(Es{});
                emit(label++, next);
            }(),
            ...);
    }
    std::string label(std::uint16_t i) const {
        constexpr std::string_view names[] = {event_name<Es>...};
        return std::string(names[i]);
    }
    std::string describe(state const& s) const { return s.active_states().joined(); }

private:
    Machine initial_;
    detail::codec<Machine> codec_{};
};

// The label of a cycle_model's choice when the user gives none.
struct numbered_inputs {
    std::string operator()(std::size_t choice) const { return "cycle, inputs #" + std::to_string(choice); }
};

/// Steps the machine with a fixed period; before each cycle, `apply(context, choice)` sets the
/// inputs for one of `choices` alternatives, and every alternative is explored. `label(choice)`
/// names an alternative in traces; written as `name=value` words ("P1=1 S1=0"), a trace shows
/// only the words that changed from one step to the next (verdict::to_string).
template <class Machine, class Apply, class Label = numbered_inputs>
class cycle_model {
public:
    using state = Machine;
    static constexpr std::size_t key_size = detail::codec<Machine>::key_size;

    cycle_model(Machine initial, duration period, std::size_t choices, Apply apply, Label label = {})
        : initial_(std::move(initial)),
          choices_(choices),
          apply_(std::move(apply)),
          label_(std::move(label)),
          codec_{period} {}

    state initial() const { return initial_; }
    void encode(state const& s, std::byte* out) const { codec_.encode(s, out); }
    state decode(std::byte const* in) const { return codec_.decode(initial_, in); }
    template <class Emit>
    void successors(state const& s, Emit&& emit) const {
        for (std::size_t c = 0; c < choices_; ++c) {
            state next = s;
            apply_(next.context(), c);
            next.step(detail::origin + codec_.period);
            emit(static_cast<std::uint16_t>(c), next);
        }
    }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return s.active_states().joined(); }
    /// The time between two cycles: a trace's step k is at k periods.
    duration period() const { return codec_.period; }

private:
    Machine initial_;
    std::size_t choices_;
    Apply apply_;
    Label label_;
    detail::codec<Machine> codec_;
};

/// A closed system: an aggregate `System` of machines and plant data, advanced by
/// `step(system, choice, now)` for each of `choices` alternatives per cycle. `describe`
/// names a system state for traces; `label(choice)` names an alternative.
template <class System, class Step, class Describe, class Label>
class system_model {
public:
    using state = System;
    static constexpr std::size_t key_size = detail::codec<System>::key_size;

    system_model(System initial, duration period, std::size_t choices, Step step, Describe describe, Label label)
        : initial_(std::move(initial)),
          choices_(choices),
          step_(std::move(step)),
          describe_(std::move(describe)),
          label_(std::move(label)),
          codec_{period} {}

    state initial() const { return initial_; }
    void encode(state const& s, std::byte* out) const { codec_.encode(s, out); }
    state decode(std::byte const* in) const { return codec_.decode(initial_, in); }
    template <class Emit>
    void successors(state const& s, Emit&& emit) const {
        for (std::size_t c = 0; c < choices_; ++c) {
            state next = s;
            step_(next, c, detail::origin + codec_.period);
            emit(static_cast<std::uint16_t>(c), next);
        }
    }
    std::string label(std::uint16_t i) const { return label_(i); }
    std::string describe(state const& s) const { return describe_(s); }
    /// The time between two steps: a trace's step k is at k periods.
    duration period() const { return codec_.period; }

private:
    System initial_;
    std::size_t choices_;
    Step step_;
    Describe describe_;
    Label label_;
    detail::codec<System> codec_;
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
                          (result == status::holds ? "holds" : result == status::fails ? "FAILS" : "inconclusive");
        if (!detail.empty()) out += " (" + detail + ")";
        out += '\n';
        auto const repeats = [&](std::size_t k) {
            return k > 0 && trace[k].label == trace[k - 1].label && trace[k].configuration == trace[k - 1].configuration;
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
void append_step(verify::explorer<Model> const& ex, std::vector<verify::trace_step>& out, std::string label, std::size_t i) {
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
    verify::verdict v{std::move(property), verify::verdict::status::inconclusive, {}, "exploration stopped by " + ex.stats().stopped_by};
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
            for (auto f = ex.edges_begin(i); f < ex.edges_end(i); ++f) most = std::max(most, slowest[ex.edge_target(f)]);
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
        return {name, verdict::status::fails, std::move(trace), "p holds at step " + std::to_string(start) + "; " + how};
    }
    return {name, verdict::status::holds, {}, {}};
}

}  // namespace bsc::verify
// end include/bsc/verify/properties.hpp
// end include/bsc/verify.hpp
