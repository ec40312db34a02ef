#pragma once
// Workload `sml_composite`: the composite CD player of Boost.SML's benchmark/ directory, ported
// from its description. The simple CD player (sml_simple_workload.hpp; its Pause is called
// Paused here) whose Playing is a composite state of three songs, Song1 (initial), Song2 and
// Song3, and two more events, next_song and previous_song (indices 6 and 7), with four inner
// transitions: Song1 + next_song = Song2, Song2 + next_song = Song3, Song3 + previous_song =
// Song2, Song2 + previous_song = Song1. Every action does nothing, as there.
//
// The sequence is Boost.SML's loop body twice (8,022 events): open_close, open_close,
// cd_detected, play (Playing is entered at Song1); 1,000 times next_song, next_song,
// previous_song, previous_song; then pause, end_pause, pause, stop, stop, open_close, open_close.
// The observation is the active state and, in Playing, the active song.

#include <cstddef>
#include <cstdint>
#include <string>

#include "../harness.hpp"

namespace sml_composite_bench {

enum state : std::uint8_t { empty_s, open_s, stopped_s, playing_s, paused_s };
enum event : std::uint8_t {
    play_e,
    end_pause_e,
    stop_e,
    pause_e,
    open_close_e,
    cd_detected_e,
    next_song_e,
    previous_song_e
};

struct workload {
    static constexpr char const* name = "sml_composite";

    struct observation {
        std::uint8_t state = empty_s;
        std::uint8_t song = 0;  // 1 to 3 in Playing, else 0
        bool operator==(observation const& o) const { return state == o.state && song == o.song; }
    };

    static std::string describe(observation const& o) {
        static char const* const names[] = {"Empty", "Open", "Stopped", "Playing", "Paused"};
        return std::string(names[o.state]) + (o.song ? " Song" + std::to_string(o.song) : "");
    }

    static bench::sequence record() {
        bench::sequence s;
        for (int outer = 0; outer < 2; ++outer) {
            for (std::uint8_t e : {open_close_e, open_close_e, cd_detected_e, play_e}) s.push_back(e);
            for (int inner = 0; inner < 1000; ++inner)
                for (std::uint8_t e : {next_song_e, next_song_e, previous_song_e, previous_song_e}) s.push_back(e);
            for (std::uint8_t e : {pause_e, end_pause_e, pause_e, stop_e, stop_e, open_close_e, open_close_e})
                s.push_back(e);
        }
        return s;
    }
};

}  // namespace sml_composite_bench
