// Workload sml_simple, hand-written: a switch on the event, and in each case the states that
// take it (one line per transition of the chart).

#include "sml_simple_workload.hpp"

namespace {

using namespace sml_simple_bench;

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
    workload::observation observe() const { return {state_}; }

private:
    std::uint8_t state_ = empty_s;
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "hand_written", cd_player_switch);
