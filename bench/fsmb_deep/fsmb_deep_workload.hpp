#pragma once
// Workload `fsmb_deep`: the "Deep" chart of fgoujeon/fsm-benchmark, ported from its description.
// The root holds three composite states lvl0_x (x = 0..2, lvl0_0 initial); each holds three
// composite states lvl1_xy (lvl1_x0 initial) and a final state; each lvl1_xy holds three basic
// states lvl2_xyz (lvl2_xy0 initial) and a final state: 39 states besides the finals. There are
// 27 events, one per basic state (index 9x + 3y + z). Basic state xyz takes its event to
// xy(z+1), or, for z = 2, to the final state of lvl1_xy; the completion of lvl1_xy leads to
// lvl1_x(y+1), or, for y = 2, to the final state of lvl0_x; the completion of lvl0_x leads to
// lvl0_(x+1 mod 3). Leaving basic state xyz adds x + y + z + 1 to a counter (108 per round); no
// guards, no transition actions.
//
// The sequence is the 27 events in order, 370 times (9,990 events), as fsm-benchmark's loop
// sends them: each round goes once around the whole chart. The observation is the active basic
// state and the counter.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace fsmb_deep_bench {

struct workload {
    static constexpr char const* name = "fsmb_deep";
    static constexpr std::size_t leaves = 27;

    struct observation {
        std::size_t leaf = 0;  // 9x + 3y + z
        std::uint64_t counter = 0;
        bool operator==(observation const& o) const { return leaf == o.leaf && counter == o.counter; }
    };

    static std::string describe(observation const& o) {
        return "lvl2_" + std::to_string(o.leaf / 9) + std::to_string(o.leaf / 3 % 3) + std::to_string(o.leaf % 3) +
               " counter " + std::to_string(o.counter);
    }

    static bench::sequence record() {
        bench::sequence s;
        for (int i = 0; i < 370; ++i)
            for (std::size_t k = 0; k < leaves; ++k) s.push_back(static_cast<std::uint8_t>(k));
        return s;
    }
};

}  // namespace fsmb_deep_bench
