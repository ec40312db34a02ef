#pragma once
// The CD player of Boost.SML's benchmark (sml_simple_workload.hpp describes it) written by hand:
// a switch on the event, and in each case the states that take it, one line per transition.
// Its states and events are numbered as the recorded sequences hold them. Shared by the
// workload (bench/sml_simple) and the Cortex-M4 programs (tests/cortex_m); C++17, without bsc,
// as the workload's other implementations include it.

#include <cstdint>

namespace sml_simple_bench {

enum state : std::uint8_t { empty_s, open_s, stopped_s, playing_s, pause_s };
enum event : std::uint8_t { play_e, end_pause_e, stop_e, pause_e, open_close_e, cd_detected_e, event_count };

class cd_player_switch {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case play_e:
            if (state_ == stopped_s) state_ = playing_s;
            break;
        case end_pause_e:
            if (state_ == pause_s) state_ = playing_s;
            break;
        case stop_e:
            if (state_ == playing_s || state_ == pause_s || state_ == stopped_s) state_ = stopped_s;
            break;
        case pause_e:
            if (state_ == playing_s) state_ = pause_s;
            break;
        case open_close_e:
            if (state_ == open_s)
                state_ = empty_s;
            else if (state_ == empty_s || state_ == pause_s || state_ == stopped_s || state_ == playing_s)
                state_ = open_s;
            break;
        case cd_detected_e:
            if (state_ == empty_s) state_ = stopped_s;
            break;
        default: break;
        }
    }
    state current() const { return state_; }

private:
    state state_ = empty_s;
};

}  // namespace sml_simple_bench
