// Boost.SML's composite CD player (bench/sml_composite: Playing a composite of three songs), as a
// program of its own: the chart, a machine, and the loop of Boost.SML's benchmark/composite
// program, around the same small driver (scripts/peer_compile.py).

#include <bsc/bsc.hpp>

#include "small_driver.hpp"

namespace {
struct play {};
struct end_pause {};
struct stop {};
struct pause {};
struct open_close {};
struct cd_detected {};
struct next_song {};
struct previous_song {};
struct Player;
struct Empty;
struct Open;
struct Stopped;
struct Playing;
struct Paused;
struct Song1;
struct Song2;
struct Song3;
struct none {};

auto start_playback = [] {};
auto open_drawer = [] {};
auto close_drawer = [] {};
auto store_cd_info = [] {};
auto stop_playback = [] {};
auto pause_playback = [] {};
auto resume_playback = [] {};
auto stop_and_open = [] {};
auto stopped_again = [] {};
auto start_next_song = [] {};
auto start_prev_song = [] {};

constexpr auto player = bsc::make_chart<none>(
    bsc::composite<Player>(bsc::initial<Empty>, bsc::state<Open>, bsc::state<Stopped>,
                           bsc::composite<Playing>(bsc::initial<Song1>, bsc::state<Song2>, bsc::state<Song3>),
                           bsc::state<Paused>),
    bsc::state<Stopped> + bsc::event<play> / start_playback = bsc::state<Playing>,
    bsc::state<Stopped> + bsc::event<open_close> / open_drawer = bsc::state<Open>,
    bsc::state<Stopped> + bsc::event<stop> / stopped_again = bsc::state<Stopped>,
    bsc::state<Open> + bsc::event<open_close> / close_drawer = bsc::state<Empty>,
    bsc::state<Empty> + bsc::event<open_close> / open_drawer = bsc::state<Open>,
    bsc::state<Empty> + bsc::event<cd_detected> / store_cd_info = bsc::state<Stopped>,
    bsc::state<Playing> + bsc::event<stop> / stop_playback = bsc::state<Stopped>,
    bsc::state<Playing> + bsc::event<pause> / pause_playback = bsc::state<Paused>,
    bsc::state<Playing> + bsc::event<open_close> / stop_and_open = bsc::state<Open>,
    bsc::state<Paused> + bsc::event<end_pause> / resume_playback = bsc::state<Playing>,
    bsc::state<Paused> + bsc::event<stop> / stop_playback = bsc::state<Stopped>,
    bsc::state<Paused> + bsc::event<open_close> / stop_and_open = bsc::state<Open>,
    bsc::state<Song1> + bsc::event<next_song> / start_next_song = bsc::state<Song2>,
    bsc::state<Song2> + bsc::event<previous_song> / start_prev_song = bsc::state<Song1>,
    bsc::state<Song2> + bsc::event<next_song> / start_next_song = bsc::state<Song3>,
    bsc::state<Song3> + bsc::event<previous_song> / start_prev_song = bsc::state<Song2>);
}  // namespace

int main() {
    bsc::machine<bsc::chart_ref<player>> machine{player};
    probe_driver::time_loop([&] {
        for (int i = 0; i < 1'000; ++i) {
            machine.dispatch(open_close{});
            machine.dispatch(open_close{});
            machine.dispatch(cd_detected{});
            machine.dispatch(play{});
            for (int j = 0; j < 1'000; ++j) {
                machine.dispatch(next_song{});
                machine.dispatch(next_song{});
                machine.dispatch(previous_song{});
                machine.dispatch(previous_song{});
            }
            machine.dispatch(pause{});
            machine.dispatch(end_pause{});
            machine.dispatch(pause{});
            machine.dispatch(stop{});
            machine.dispatch(stop{});
            machine.dispatch(open_close{});
            machine.dispatch(open_close{});
        }
    });
    probe_driver::print_size(machine);
    return machine.is<Empty>() ? 0 : 1;
}
