#pragma once
// Workload `sml_simple`: the simple CD player of Boost.SML's benchmark/ directory, ported from
// its description. Five states, Empty (initial), Open, Stopped, Playing, Pause; six events,
// play, end_pause, stop, pause, open_close, cd_detected (indices 0 to 5); twelve transitions,
// each with an action that does nothing (as there: the compiler removes them):
//
//   Stopped + play = Playing          Pause + end_pause = Playing      Open + open_close = Empty
//   Empty + open_close = Open         Pause + open_close = Open        Stopped + open_close = Open
//   Playing + open_close = Open       Playing + pause = Pause          Playing + stop = Stopped
//   Pause + stop = Stopped            Empty + cd_detected = Stopped    Stopped + stop = Stopped
//
// The sequence repeats Boost.SML's loop body, eleven events every one of which fires a
// transition: open_close, open_close, cd_detected, play, pause, end_pause, pause, stop, stop,
// open_close, open_close (909 times: 9,999 events). The observation is the active state.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"
#include "cd_player_switch.hpp"  // the states and events, numbered

namespace sml_simple_bench {

struct workload {
    static constexpr char const* name = "sml_simple";

    struct observation {
        std::uint8_t state = empty_s;
        bool operator==(observation const& o) const { return state == o.state; }
    };

    static std::string describe(observation const& o) {
        static char const* const names[] = {"Empty", "Open", "Stopped", "Playing", "Pause"};
        return names[o.state];
    }

    static bench::sequence record() {
        static constexpr std::uint8_t loop[] = {open_close_e, open_close_e, cd_detected_e, play_e,
                                                pause_e,      end_pause_e,  pause_e,       stop_e,
                                                stop_e,       open_close_e, open_close_e};
        bench::sequence s;
        for (int i = 0; i < 909; ++i)
            for (std::uint8_t e : loop) s.push_back(e);
        return s;
    }
};

}  // namespace sml_simple_bench
