// Workload sml_simple, bsc: the chart of sml_simple_workload.hpp on the compiled back end.

#include <bsc/bsc.hpp>

#include "../bsc_variant.hpp"
#include "cd_player_chart.hpp"
#include "sml_simple_workload.hpp"

namespace {

// (In this file's own namespace, as the other workloads' charts: the machine's functions are
// then internal, which the instruction counts were measured with.)
namespace player {
// The actions of Boost.SML's benchmark: they do nothing. (noexcept: bench/bsc_variant.hpp.)
inline constexpr auto nothing = []() noexcept(BENCH_NOEXCEPT_ACTIONS) {};
inline constexpr auto chart = cd::make_player(nothing);
}  // namespace player

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
    bsc::machine<bsc::chart_ref<player::chart>, bench::bsc_policy> m_{player::chart};
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "bsc_compiled", cd_player_machine);
