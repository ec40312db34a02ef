// Boost.SML's CD player (bench/sml_simple), as a program of its own: the chart, a machine, and
// the loop of Boost.SML's benchmark/simple program, around the same small driver, so that its
// compile time is measured side by side with that program's (scripts/peer_compile.py).

#include <bsc/bsc.hpp>

#include "../sml_simple/cd_player_chart.hpp"
#include "small_driver.hpp"

namespace {
using namespace cd;  // the events and states of bench/sml_simple/cd_player_chart.hpp

auto start_playback = [] {};
auto resume_playback = [] {};
auto close_drawer = [] {};
auto open_drawer = [] {};
auto stop_and_open = [] {};
auto stopped_again = [] {};
auto store_cd_info = [] {};
auto pause_playback = [] {};
auto stop_playback = [] {};

constexpr auto player = bsc::make_chart<none>(
    bsc::composite<Player>(bsc::initial<Empty>, bsc::state<Open>, bsc::state<Stopped>, bsc::state<Playing>,
                           bsc::state<Pause>),
    bsc::state<Stopped> + bsc::event<play> / start_playback = bsc::state<Playing>,
    bsc::state<Pause> + bsc::event<end_pause> / resume_playback = bsc::state<Playing>,
    bsc::state<Open> + bsc::event<open_close> / close_drawer = bsc::state<Empty>,
    bsc::state<Empty> + bsc::event<open_close> / open_drawer = bsc::state<Open>,
    bsc::state<Pause> + bsc::event<open_close> / stop_and_open = bsc::state<Open>,
    bsc::state<Stopped> + bsc::event<open_close> / open_drawer = bsc::state<Open>,
    bsc::state<Playing> + bsc::event<open_close> / stop_and_open = bsc::state<Open>,
    bsc::state<Playing> + bsc::event<pause> / pause_playback = bsc::state<Pause>,
    bsc::state<Playing> + bsc::event<stop> / stop_playback = bsc::state<Stopped>,
    bsc::state<Pause> + bsc::event<stop> / stop_playback = bsc::state<Stopped>,
    bsc::state<Empty> + bsc::event<cd_detected> / store_cd_info = bsc::state<Stopped>,
    bsc::state<Stopped> + bsc::event<stop> / stopped_again = bsc::state<Stopped>);
}  // namespace

int main() {
    bsc::machine<bsc::chart_ref<player>> machine{player};
    probe_driver::time_loop([&] {
        for (int i = 0; i < 1'000'000; ++i) {
            machine.dispatch(open_close{});
            machine.dispatch(open_close{});
            machine.dispatch(cd_detected{});
            machine.dispatch(play{});
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
