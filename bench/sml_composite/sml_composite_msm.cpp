// Workload sml_composite, Boost.MSM: back::state_machine with the functor front end; Playing is a
// submachine (a back::state_machine of its own, without history, so every entry starts at
// Song1) holding the four song transitions, the top machine the twelve others. Every Row has the
// action `nothing` (a functor that does nothing, as in Boost.SML's benchmark). Both machines set
// no_exception_thrown and no_message_queue. C++17 (bench/CMakeLists.txt).

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>

#include "sml_composite_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;

struct play {};
struct end_pause {};
struct stop {};
struct pause {};
struct open_close {};
struct cd_detected {};
struct next_song {};
struct previous_song {};

struct nothing {
    template <class E, class F, class S, class T>
    void operator()(E const&, F&, S&, T&) const {}
};

template <class Self>
struct machine_base : msm::front::state_machine_def<Self> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
};

// ---- Playing ----------------------------------------------------------------------------------
struct Song1 : msm::front::state<> {};
struct Song2 : msm::front::state<> {};
struct Song3 : msm::front::state<> {};
struct Playing_ : machine_base<Playing_> {
    using initial_state = Song1;
    using transition_table =
        mpl::vector<Row<Song1, next_song, Song2, nothing, none>, Row<Song2, next_song, Song3, nothing, none>,
                    Row<Song3, previous_song, Song2, nothing, none>, Row<Song2, previous_song, Song1, nothing, none>>;
};
using Playing = msm::back::state_machine<Playing_>;

// ---- Player -----------------------------------------------------------------------------------
struct Empty : msm::front::state<> {};
struct Open : msm::front::state<> {};
struct Stopped : msm::front::state<> {};
struct Paused : msm::front::state<> {};
struct player_ : machine_base<player_> {
    using initial_state = Empty;
    using transition_table =
        mpl::vector<Row<Stopped, play, Playing, nothing, none>, Row<Paused, end_pause, Playing, nothing, none>,
                    Row<Open, open_close, Empty, nothing, none>, Row<Empty, open_close, Open, nothing, none>,
                    Row<Paused, open_close, Open, nothing, none>, Row<Stopped, open_close, Open, nothing, none>,
                    Row<Playing, open_close, Open, nothing, none>, Row<Playing, pause, Paused, nothing, none>,
                    Row<Playing, stop, Stopped, nothing, none>, Row<Paused, stop, Stopped, nothing, none>,
                    Row<Empty, cd_detected, Stopped, nothing, none>, Row<Stopped, stop, Stopped, nothing, none>>;
};
using player = msm::back::state_machine<player_>;

class cd_player_machine {
public:
    cd_player_machine() { m_.start(); }
    cd_player_machine(cd_player_machine const&) = delete;
    cd_player_machine& operator=(cd_player_machine const&) = delete;

    void on(std::uint8_t e) {
        using namespace sml_composite_bench;
        switch (e) {
        case play_e: m_.process_event(play{}); break;
        case end_pause_e: m_.process_event(end_pause{}); break;
        case stop_e: m_.process_event(stop{}); break;
        case pause_e: m_.process_event(pause{}); break;
        case open_close_e: m_.process_event(open_close{}); break;
        case cd_detected_e: m_.process_event(cd_detected{}); break;
        case next_song_e: m_.process_event(next_song{}); break;
        case previous_song_e: m_.process_event(previous_song{}); break;
        default: break;
        }
    }

    sml_composite_bench::workload::observation observe() const {
        using namespace sml_composite_bench;
        int const id = m_.current_state()[0];
        if (id == state_id<player, Open>) return {open_s, 0};
        if (id == state_id<player, Stopped>) return {stopped_s, 0};
        if (id == state_id<player, Paused>) return {paused_s, 0};
        if (id == state_id<player, Playing>) {
            int const song = m_.get_state<Playing const&>().current_state()[0];
            return {playing_s, song == state_id<Playing, Song1>   ? std::uint8_t{1}
                               : song == state_id<Playing, Song2> ? std::uint8_t{2}
                                                                  : std::uint8_t{3}};
        }
        return {empty_s, 0};
    }

private:
    template <class SM, class S>
    static constexpr int state_id = msm::back::get_state_id<typename SM::stt, S>::value;

    player m_;
};

}  // namespace

BENCH_IMPL(sml_composite_bench::workload, "boost_msm", cd_player_machine);
