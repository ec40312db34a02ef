#pragma once
// Workload `wide`: a parallel root W with 8 orthogonal regions G0..G7, each a composite of
// three states A(r,0), A(r,1), A(r,2); region r starts in A(r, r mod 3). Three event types,
// each broadcast to every region, where each region reacts on its own:
//   step:  A(r,j) -> A(r,(j+1) mod 3), n[r] += 1              (every state)
//   reset: A(r,1), A(r,2) -> A(r,0),   n[r] += 16             (ignored in A(r,0))
//   flip:  A(r,0) -> A(r,2) if r is even, A(r,1) if r is odd;  n[r] += 4
//                                                             (ignored in A(r,1), A(r,2))
// So every event is offered to all 8 regions, and in one microstep 8 transitions (step) or
// those of the regions in matching states (reset, flip) fire. 48 transitions in all.
//
// The recorded sequence has 10,000 events drawn uniformly from step, reset, flip (seed 5).
// The observation is the state of every region and the counters n[0..7].

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace wide_bench {

inline constexpr std::size_t regions = 8;
inline constexpr std::size_t event_count = 3;  // 0 step, 1 reset, 2 flip

constexpr int initial_of(int r) { return r % 3; }
constexpr int flip_target(int r) { return r % 2 == 0 ? 2 : 1; }

struct workload {
    static constexpr char const* name = "wide";

    struct observation {
        std::array<std::uint8_t, regions> state{};
        std::array<std::uint64_t, regions> n{};
        bool operator==(observation const& o) const { return state == o.state && n == o.n; }
    };

    static std::string describe(observation const& o) {
        std::string s = "states";
        for (auto v : o.state) s += " " + std::to_string(v);
        s += " counters";
        for (auto v : o.n) s += " " + std::to_string(v);
        return s;
    }

    static bench::sequence record() {
        bench::rng r{5};
        bench::sequence s(10000);
        for (auto& e : s) e = static_cast<std::uint8_t>(r.below(event_count));
        return s;
    }
};

}  // namespace wide_bench
