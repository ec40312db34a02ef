// Workload sml_simple, Boost.Statechart: five sc::simple_state, one sc::transition per transition
// of the chart, each with the action Machine::nothing (a member that does nothing, as in
// Boost.SML's benchmark). The machine uses Statechart's defaults.

#include <boost/mpl/list.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/simple_state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "sml_simple_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;

struct play : sc::event<play> {};
struct end_pause : sc::event<end_pause> {};
struct stop : sc::event<stop> {};
struct pause : sc::event<pause> {};
struct open_close : sc::event<open_close> {};
struct cd_detected : sc::event<cd_detected> {};

struct Empty;
struct Open;
struct Stopped;
struct Playing;
struct Pause;

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
struct Playing : sc::simple_state<Playing, Machine> {
    using reactions = mpl::list<sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<pause, Pause, Machine, &Machine::nothing<pause>>,
                                sc::transition<stop, Stopped, Machine, &Machine::nothing<stop>>>;
};
struct Pause : sc::simple_state<Pause, Machine> {
    using reactions = mpl::list<sc::transition<end_pause, Playing, Machine, &Machine::nothing<end_pause>>,
                                sc::transition<open_close, Open, Machine, &Machine::nothing<open_close>>,
                                sc::transition<stop, Stopped, Machine, &Machine::nothing<stop>>>;
};

class cd_player_machine {
public:
    cd_player_machine() { m_.initiate(); }
    cd_player_machine(cd_player_machine const&) = delete;
    cd_player_machine& operator=(cd_player_machine const&) = delete;

    void on(std::uint8_t e) {
        using namespace sml_simple_bench;
        switch (e) {
        case play_e: m_.process_event(std::get<play>(events_)); break;
        case end_pause_e: m_.process_event(std::get<end_pause>(events_)); break;
        case stop_e: m_.process_event(std::get<stop>(events_)); break;
        case pause_e: m_.process_event(std::get<pause>(events_)); break;
        case open_close_e: m_.process_event(std::get<open_close>(events_)); break;
        case cd_detected_e: m_.process_event(std::get<cd_detected>(events_)); break;
        default: break;
        }
    }

    sml_simple_bench::workload::observation observe() const {
        using namespace sml_simple_bench;
        if (is<Open>()) return {open_s};
        if (is<Stopped>()) return {stopped_s};
        if (is<Playing>()) return {playing_s};
        if (is<Pause>()) return {pause_s};
        return {empty_s};
    }

private:
    template <class S>
    bool is() const {
        return m_.state_cast<S const*>() != nullptr;
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    std::tuple<play, end_pause, stop, pause, open_close, cd_detected> events_;
};

}  // namespace

BENCH_IMPL(sml_simple_bench::workload, "boost_statechart", cd_player_machine);
