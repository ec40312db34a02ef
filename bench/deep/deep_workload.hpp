#pragma once
// Workload `deep`: 8 levels of nesting. The root R holds D1 (initial) and P1; each Dk, k < 8,
// is a composite holding D(k+1) (initial) and P(k+1); D8 is a basic state, 8 levels below R.
// There is one event type per level, L1..L8, and its two transitions are declared at that
// level: Dk + Lk / count += k = Pk (leaves Dk and everything active below it) and
// Pk + Lk / count += 100 k = Dk (enters Dk and its default completion down to D8). Entering
// any Dk adds 1 to `entries` (an entry action). So an event finds its transition only at its
// own level, and whether it fires depends on the states active there: dispatch must find the
// right level. The recorded sequence has 10,000 events drawn uniformly from L1..L8 (seed 11).
//
// The configuration is fully described by the depth d (0..8): D1..Dd are active, and P(d+1)
// too when d < 8. The observation is the depth, the count and the entries.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace deep_bench {

inline constexpr std::size_t levels = 8;

struct workload {
    static constexpr char const* name = "deep";

    struct observation {
        int depth = 8;
        std::uint64_t count = 0;
        std::uint64_t entries = 0;
        bool operator==(observation const& o) const {
            return depth == o.depth && count == o.count && entries == o.entries;
        }
    };

    static std::string describe(observation const& o) {
        return "depth " + std::to_string(o.depth) + " count " + std::to_string(o.count) + " entries " +
               std::to_string(o.entries);
    }

    static bench::sequence record() {
        bench::rng r{11};
        bench::sequence s(10000);
        for (auto& e : s) e = static_cast<std::uint8_t>(r.below(levels));  // event index k-1 is Lk
        return s;
    }
};

}  // namespace deep_bench
