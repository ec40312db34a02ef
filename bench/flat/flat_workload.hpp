#pragma once
// Workload `flat`: a flat chart of N = 50 states S0..S49 and 50 event types E0..E49, with 50
// transitions. State Si handles exactly one event, E((7i + 3) mod N), and goes to S((i + 1)
// mod N) with the action `count += i + 1`; every other event is ignored in Si. The recorded
// sequence has 10,000 events (seed 7): each is, with probability 1/2, the event the current
// state handles, otherwise an event drawn uniformly (so about half the events fire a
// transition and half are ignored). The observation is the active state and the count.
//
// The chart is generated from N with templates (flat/flat_chart_*.hpp), so that the
// compile-time measurements (scripts/benchmarks.py) can instantiate it for other N.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace flat_bench {

/// The event handled by state i, and the state it goes to, in a flat chart of n states.
constexpr std::size_t handled_by(std::size_t i, std::size_t n) { return (7 * i + 3) % n; }
constexpr std::size_t next_of(std::size_t i, std::size_t n) { return (i + 1) % n; }

struct workload {
    static constexpr char const* name = "flat";
    static constexpr std::size_t states = 50;

    struct observation {
        std::size_t state = 0;
        std::uint64_t count = 0;
        bool operator==(observation const& o) const { return state == o.state && count == o.count; }
    };

    static std::string describe(observation const& o) {
        return "state S" + std::to_string(o.state) + " count " + std::to_string(o.count);
    }

    static bench::sequence record() {
        bench::rng r{7};
        bench::sequence s(10000);
        std::size_t state = 0;
        for (auto& e : s) {
            std::size_t const ev = r.below(2) ? handled_by(state, states) : r.below(states);
            e = static_cast<std::uint8_t>(ev);
            if (ev == handled_by(state, states)) state = next_of(state, states);
        }
        return s;
    }
};

}  // namespace flat_bench
