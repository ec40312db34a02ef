// Workload sml_composite, hand-written: a switch on the event, and in each case the states that
// take it; the song is a second variable, set to Song1 whenever Playing is entered.

#include "sml_composite_workload.hpp"

namespace {

using namespace sml_composite_bench;

class cd_player_switch {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case play_e:
            if (state_ == stopped_s) play();
            break;
        case end_pause_e:
            if (state_ == paused_s) play();
            break;
        case stop_e:
            if (state_ == playing_s || state_ == paused_s || state_ == stopped_s) state_ = stopped_s;
            break;
        case pause_e:
            if (state_ == playing_s) state_ = paused_s;
            break;
        case open_close_e:
            if (state_ == open_s)
                state_ = empty_s;
            else if (state_ == empty_s || state_ == paused_s || state_ == stopped_s || state_ == playing_s)
                state_ = open_s;
            break;
        case cd_detected_e:
            if (state_ == empty_s) state_ = stopped_s;
            break;
        case next_song_e:
            if (state_ == playing_s && song_ < 3) ++song_;
            break;
        case previous_song_e:
            if (state_ == playing_s && song_ > 1) --song_;
            break;
        default: break;
        }
    }
    workload::observation observe() const { return {state_, state_ == playing_s ? song_ : std::uint8_t{0}}; }

private:
    void play() {
        state_ = playing_s;
        song_ = 1;
    }
    std::uint8_t state_ = empty_s;
    std::uint8_t song_ = 0;
};

}  // namespace

BENCH_IMPL(sml_composite_bench::workload, "hand_written", cd_player_switch);
