#pragma once
// Workload `sml_complex`: the complex chart of Boost.SML's benchmark/ directory, ported from its
// description. Fifty states in a ring, idle (initial) and s1 to s49, and fifty events e1 to e50
// (indices 0 to 49): state k (idle being 0) takes e(k+1), with a guard that holds and an action
// that does nothing, to state k+1 (s49 takes e50 back to idle); every other event is ignored.
//
// The sequence follows Boost.SML's loop, which goes through e1 to e50 in order and sends each
// with probability 1/2 (there with rand(); here with the harness's generator, seed 11, so that
// every platform replays the same events): 10,000 events, most of them ignored where they
// arrive. The observation is the active state.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace sml_complex_bench {

struct workload {
    static constexpr char const* name = "sml_complex";
    static constexpr std::size_t states = 50;

    struct observation {
        std::size_t state = 0;
        bool operator==(observation const& o) const { return state == o.state; }
    };

    static std::string describe(observation const& o) { return o.state == 0 ? "idle" : "s" + std::to_string(o.state); }

    static bench::sequence record() {
        bench::rng r{11};
        bench::sequence s;
        while (s.size() < 10000)
            for (std::size_t k = 0; k < states && s.size() < 10000; ++k)
                if (r.below(2)) s.push_back(static_cast<std::uint8_t>(k));
        return s;
    }
};

}  // namespace sml_complex_bench
