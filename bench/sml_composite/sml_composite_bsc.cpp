// Workload sml_composite, bsc: the chart of sml_composite_workload.hpp on the compiled back end.

#include <bsc/bsc.hpp>

#include "../bsc_variant.hpp"
#include "sml_composite_workload.hpp"

namespace {

namespace cd {
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

// The actions of Boost.SML's benchmark: they do nothing. (noexcept: bench/bsc_variant.hpp.)
inline constexpr auto nothing = []() noexcept(BENCH_NOEXCEPT_ACTIONS) {};

inline constexpr auto chart = bsc::make_chart<none>(
    bsc::composite<Player>(bsc::initial<Empty>, bsc::state<Open>, bsc::state<Stopped>,
                           bsc::composite<Playing>(bsc::initial<Song1>, bsc::state<Song2>, bsc::state<Song3>),
                           bsc::state<Paused>),
    bsc::state<Stopped> + bsc::event<play> / nothing = bsc::state<Playing>,
    bsc::state<Paused> + bsc::event<end_pause> / nothing = bsc::state<Playing>,
    bsc::state<Open> + bsc::event<open_close> / nothing = bsc::state<Empty>,
    bsc::state<Empty> + bsc::event<open_close> / nothing = bsc::state<Open>,
    bsc::state<Paused> + bsc::event<open_close> / nothing = bsc::state<Open>,
    bsc::state<Stopped> + bsc::event<open_close> / nothing = bsc::state<Open>,
    bsc::state<Playing> + bsc::event<open_close> / nothing = bsc::state<Open>,
    bsc::state<Playing> + bsc::event<pause> / nothing = bsc::state<Paused>,
    bsc::state<Playing> + bsc::event<stop> / nothing = bsc::state<Stopped>,
    bsc::state<Paused> + bsc::event<stop> / nothing = bsc::state<Stopped>,
    bsc::state<Empty> + bsc::event<cd_detected> / nothing = bsc::state<Stopped>,
    bsc::state<Stopped> + bsc::event<stop> / nothing = bsc::state<Stopped>,
    bsc::state<Song1> + bsc::event<next_song> / nothing = bsc::state<Song2>,
    bsc::state<Song2> + bsc::event<previous_song> / nothing = bsc::state<Song1>,
    bsc::state<Song2> + bsc::event<next_song> / nothing = bsc::state<Song3>,
    bsc::state<Song3> + bsc::event<previous_song> / nothing = bsc::state<Song2>);
}  // namespace cd

class cd_player_machine {
public:
    void on(std::uint8_t e) {
        using namespace sml_composite_bench;
        switch (e) {
        case play_e: m_.dispatch(cd::play{}); break;
        case end_pause_e: m_.dispatch(cd::end_pause{}); break;
        case stop_e: m_.dispatch(cd::stop{}); break;
        case pause_e: m_.dispatch(cd::pause{}); break;
        case open_close_e: m_.dispatch(cd::open_close{}); break;
        case cd_detected_e: m_.dispatch(cd::cd_detected{}); break;
        case next_song_e: m_.dispatch(cd::next_song{}); break;
        case previous_song_e: m_.dispatch(cd::previous_song{}); break;
        default: break;
        }
    }
    sml_composite_bench::workload::observation observe() const {
        using namespace sml_composite_bench;
        if (m_.is<cd::Open>()) return {open_s, 0};
        if (m_.is<cd::Stopped>()) return {stopped_s, 0};
        if (m_.is<cd::Paused>()) return {paused_s, 0};
        if (m_.is<cd::Song1>()) return {playing_s, 1};
        if (m_.is<cd::Song2>()) return {playing_s, 2};
        if (m_.is<cd::Song3>()) return {playing_s, 3};
        return {empty_s, 0};
    }

private:
    bsc::machine<bsc::chart_ref<cd::chart>, bench::bsc_policy> m_{cd::chart};
};

}  // namespace

BENCH_IMPL(sml_composite_bench::workload, "bsc_compiled", cd_player_machine);
