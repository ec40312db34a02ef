// Workload sml_simple, Boost.MSM: back::state_machine with the functor front end, one Row per
// transition of the chart, each with the action `nothing` (a functor that does nothing, as in
// Boost.SML's benchmark). no_exception_thrown and no_message_queue are set. C++17
// (bench/CMakeLists.txt).

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>

#include "sml_simple_workload.hpp"

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

struct Empty : msm::front::state<> {};
struct Open : msm::front::state<> {};
struct Stopped : msm::front::state<> {};
struct Playing : msm::front::state<> {};
struct Pause : msm::front::state<> {};

struct nothing {
    template <class E, class F, class S, class T>
    void operator()(E const&, F&, S&, T&) const {}
};

struct player_ : msm::front::state_machine_def<player_> {
    using no_exception_thrown = int;
    using no_message_queue = int;
    using initial_state = Empty;
    using transition_table =
        mpl::vector<Row<Stopped, play, Playing, nothing, none>, Row<Pause, end_pause, Playing, nothing, none>,
                    Row<Open, open_close, Empty, nothing, none>, Row<Empty, open_close, Open, nothing, none>,
                    Row<Pause, open_close, Open, nothing, none>, Row<Stopped, open_close, Open, nothing, none>,
                    Row<Playing, open_close, Open, nothing, none>, Row<Playing, pause, Pause, nothing, none>,
                    Row<Playing, stop, Stopped, nothing, none>, Row<Pause, stop, Stopped, nothing, none>,
                    Row<Empty, cd_detected, Stopped, nothing, none>, Row<Stopped, stop, Stopped, nothing, none>>;
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
};
using player = msm::back::state_machine<player_>;

class cd_player_machine {
public:
    cd_player_machine() { m_.start(); }
    cd_player_machine(cd_player_machine const&) = delete;
    cd_player_machine& operator=(cd_player_machine const&) = delete;

    void on(std::uint8_t e) {
        using namespace sml_simple_bench;
        switch (e) {
        case play_e: m_.process_event(play{}); break;
        case end_pause_e: m_.process_event(end_pause{}); break;
        case stop_e: m_.process_event(stop{}); break;
        case pause_e: m_.process_event(pause{}); break;
        case open_close_e: m_.process_event(open_close{}); break;
        case cd_detected_e: m_.process_event(cd_detected{}); break;
        default: break;
        }
    }

    sml_simple_bench::workload::observation observe() const {
        using namespace sml_simple_bench;
        int const id = m_.current_state()[0];
        if (id == state_id<Open>) return {open_s};
        if (id == state_id<Stopped>) return {stopped_s};
        if (id == state_id<Playing>) return {playing_s};
        if (id == state_id<Pause>) return {pause_s};
        return {empty_s};
    }

private:
    template <class S>
    static constexpr int state_id = msm::back::get_state_id<player::stt, S>::value;

    player m_;
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "boost_msm", cd_player_machine);
