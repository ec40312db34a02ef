// Workload sml_composite, Boost.Statechart: sc::simple_state for every state; Playing is a
// composite one (inner initial state Song1, no history, so every entry starts at Song1) whose
// reactions are the transitions leaving it, the songs' those between songs. Every sc::transition
// has the action Machine::nothing (a member that does nothing, as in Boost.SML's benchmark).
// The machine uses Statechart's defaults.

#include <boost/mpl/list.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "sml_composite_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;

struct play : sc::event<play> {};
struct end_pause : sc::event<end_pause> {};
struct stop : sc::event<stop> {};
struct pause : sc::event<pause> {};
struct open_close : sc::event<open_close> {};
struct cd_detected : sc::event<cd_detected> {};
struct next_song : sc::event<next_song> {};
struct previous_song : sc::event<previous_song> {};

struct Empty;
struct Open;
struct Stopped;
struct Playing;
struct Paused;
struct Song1;
struct Song2;
struct Song3;

struct Machine : sc::state_machine<Machine, Empty> {
    template <class E>
    void nothing(E const&) {}
};

struct Empty : sc::simple_state<Empty, Machine> {
    using reactions = mpl::list<sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<cd_detected, Stopped, Machine, &Machine::nothing<cd_detected>>>;
};
struct Open : sc::simple_state<Open, Machine> {
    using reactions = sc::transition<open_close, Empty, Machine, &Machine::nothing<open_close>>;
};
struct Stopped : sc::simple_state<Stopped, Machine> {
    using reactions = mpl::list<sc::transition<play, Playing, Machine, &Machine::nothing<play>>,
                                sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<stop, Stopped, Machine, &Machine::nothing<stop>>>;
};
struct Playing : sc::simple_state<Playing, Machine, Song1> {
    using reactions = mpl::list<sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<pause, Paused, Machine, &Machine::nothing<pause>>,
                                sc::transition<stop, Stopped, Machine, &Machine::nothing<stop>>>;
};
struct Paused : sc::simple_state<Paused, Machine> {
    using reactions = mpl::list<sc::transition<end_pause, Playing, Machine, &Machine::nothing<end_pause>>,
                                sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<stop, Stopped, Machine, &Machine::nothing<stop>>>;
};
struct Song1 : sc::simple_state<Song1, Playing> {
    using reactions = sc::transition<next_song, Song2, Machine, &Machine::nothing<next_song>>;
};
struct Song2 : sc::simple_state<Song2, Playing> {
    using reactions = mpl::list<sc::transition<next_song, Song3, Machine, &Machine::nothing<next_song>>,
                                sc::transition<previous_song, Song1, Machine, &Machine::nothing<previous_song>>>;
};
struct Song3 : sc::simple_state<Song3, Playing> {
    using reactions = sc::transition<previous_song, Song2, Machine, &Machine::nothing<previous_song>>;
};

class cd_player_machine {
public:
    cd_player_machine() { m_.initiate(); }
    cd_player_machine(cd_player_machine const&) = delete;
    cd_player_machine& operator=(cd_player_machine const&) = delete;

    void on(std::uint8_t e) {
        using namespace sml_composite_bench;
        switch (e) {
        case play_e: m_.process_event(std::get<play>(events_)); break;
        case end_pause_e: m_.process_event(std::get<end_pause>(events_)); break;
        case stop_e: m_.process_event(std::get<stop>(events_)); break;
        case pause_e: m_.process_event(std::get<pause>(events_)); break;
        case open_close_e: m_.process_event(std::get<open_close>(events_)); break;
        case cd_detected_e: m_.process_event(std::get<cd_detected>(events_)); break;
        case next_song_e: m_.process_event(std::get<next_song>(events_)); break;
        case previous_song_e: m_.process_event(std::get<previous_song>(events_)); break;
        default: break;
        }
    }

    sml_composite_bench::workload::observation observe() const {
        using namespace sml_composite_bench;
        if (is<Open>()) return {open_s, 0};
        if (is<Stopped>()) return {stopped_s, 0};
        if (is<Paused>()) return {paused_s, 0};
        if (is<Song1>()) return {playing_s, 1};
        if (is<Song2>()) return {playing_s, 2};
        if (is<Song3>()) return {playing_s, 3};
        return {empty_s, 0};
    }

private:
    template <class S>
    bool is() const {
        return m_.state_cast<S const*>() != nullptr;
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    std::tuple<play, end_pause, stop, pause, open_close, cd_detected, next_song, previous_song> events_;
};

}  // namespace

BENCH_IMPL(sml_composite_bench::workload, "boost_statechart", cd_player_machine);
