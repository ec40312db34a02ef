// Workload sml_simple, bsc: the chart of sml_simple_workload.hpp on the compiled back end.

#include <bsc/bsc.hpp>

#include "../bsc_variant.hpp"
#include "sml_simple_workload.hpp"

namespace {

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

// The actions of Boost.SML's benchmark: they do nothing. (noexcept: bench/bsc_variant.hpp.)
inline constexpr auto nothing = []() noexcept(BENCH_NOEXCEPT_ACTIONS) {};

inline constexpr auto chart = bsc::make_chart<none>(
    bsc::composite<Player>(bsc::initial<Empty>, bsc::state<Open>, bsc::state<Stopped>, bsc::state<Playing>,
                           bsc::state<Pause>),
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
}  // namespace cd

class cd_player_machine {
public:
    void on(std::uint8_t e) {
        switch (e) {
        case sml_simple_bench::play_e: m_.dispatch(cd::play{}); break;
        case sml_simple_bench::end_pause_e: m_.dispatch(cd::end_pause{}); break;
        case sml_simple_bench::stop_e: m_.dispatch(cd::stop{}); break;
        case sml_simple_bench::pause_e: m_.dispatch(cd::pause{}); break;
        case sml_simple_bench::open_close_e: m_.dispatch(cd::open_close{}); break;
        case sml_simple_bench::cd_detected_e: m_.dispatch(cd::cd_detected{}); break;
        default: break;
        }
    }
    sml_simple_bench::workload::observation observe() const {
        using namespace sml_simple_bench;
        if (m_.is<cd::Open>()) return {open_s};
        if (m_.is<cd::Stopped>()) return {stopped_s};
        if (m_.is<cd::Playing>()) return {playing_s};
        if (m_.is<cd::Pause>()) return {pause_s};
        return {empty_s};
    }

private:
    bsc::machine<bsc::chart_ref<cd::chart>, bench::bsc_policy> m_{cd::chart};
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "bsc_compiled", cd_player_machine);
