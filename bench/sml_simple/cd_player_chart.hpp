#pragma once
// The CD player of Boost.SML's benchmark (sml_simple_workload.hpp describes it) as a bsc chart:
// its events, its states, and its twelve transitions, each with the action given (Boost.SML's
// does nothing). Shared by the workload (bench/sml_simple) and the Cortex-M4 programs
// (tests/cortex_m).

#include <bsc/bsc.hpp>

namespace cd {
struct play {};
struct end_pause {};
struct stop {};
struct pause {};
struct open_close {};
struct cd_detected {};
struct Player;
struct Empty;
struct Open;
struct Stopped;
struct Playing;
struct Pause;
struct none {};

template <class Action>
constexpr auto make_player(Action nothing) {
    return bsc::make_chart<none>(bsc::composite<Player>(bsc::initial<Empty>, bsc::state<Open>, bsc::state<Stopped>,
                                                        bsc::state<Playing>, bsc::state<Pause>),
                                 bsc::state<Stopped> + bsc::event<play> / nothing = bsc::state<Playing>,
                                 bsc::state<Pause> + bsc::event<end_pause> / nothing = bsc::state<Playing>,
                                 bsc::state<Open> + bsc::event<open_close> / nothing = bsc::state<Empty>,
                                 bsc::state<Empty> + bsc::event<open_close> / nothing = bsc::state<Open>,
                                 bsc::state<Pause> + bsc::event<open_close> / nothing = bsc::state<Open>,
                                 bsc::state<Stopped> + bsc::event<open_close> / nothing = bsc::state<Open>,
                                 bsc::state<Playing> + bsc::event<open_close> / nothing = bsc::state<Open>,
                                 bsc::state<Playing> + bsc::event<pause> / nothing = bsc::state<Pause>,
                                 bsc::state<Playing> + bsc::event<stop> / nothing = bsc::state<Stopped>,
                                 bsc::state<Pause> + bsc::event<stop> / nothing = bsc::state<Stopped>,
                                 bsc::state<Empty> + bsc::event<cd_detected> / nothing = bsc::state<Stopped>,
                                 bsc::state<Stopped> + bsc::event<stop> / nothing = bsc::state<Stopped>);
}
}  // namespace cd
