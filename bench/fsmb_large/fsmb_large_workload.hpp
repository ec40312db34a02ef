#pragma once
// Workload `fsmb_large`: the "Large" chart of fgoujeon/fsm-benchmark, ported from its
// description. A flat chart of 25 states, state0 (initial) to state24, and 26 events, sevent0 to
// sevent24 (indices 0 to 24) and ievent, each carrying `int two = 2`; the context is an int
// counter. State n takes sevent n, when two >= 0, with the action counter = (counter + 1) * two,
// to state n + 1 (mod 25); it takes ievent with the internal action counter /= two. Every state's
// exit action raises ievent, which the machine processes after the transition, in the new state:
// each sevent adds 1 to the counter, and costs a raised event.
//
// The sequence is sevent0 to sevent24 in order, 400 times (10,000 events), as fsm-benchmark's
// loop sends them (it also builds a new machine every 25,000 events, which this harness does
// not). The observation is the active state and the counter.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace fsmb_large_bench {

struct workload {
    static constexpr char const* name = "fsmb_large";
    static constexpr std::size_t states = 25;

    struct observation {
        std::size_t state = 0;
        int counter = 0;
        bool operator==(observation const& o) const { return state == o.state && counter == o.counter; }
    };

    static std::string describe(observation const& o) {
        return "state" + std::to_string(o.state) + " counter " + std::to_string(o.counter);
    }

    static bench::sequence record() {
        bench::sequence s;
        for (int i = 0; i < 400; ++i)
            for (std::size_t n = 0; n < states; ++n) s.push_back(static_cast<std::uint8_t>(n));
        return s;
    }
};

}  // namespace fsmb_large_bench
