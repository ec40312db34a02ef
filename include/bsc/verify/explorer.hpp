#pragma once
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

#include <bsc/detail/key_field.hpp>

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
