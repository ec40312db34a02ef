// Workload mcs, Boost.Statechart: sc::state_machine with one sc::state per state of the chart
// (sc::state rather than sc::simple_state so that the entry action, the constructor, can reach
// the panel through outermost_context()); the exit action is exit(). On has deep history
// (sc::has_deep_history, entered through sc::deep_history<Auto>); the guard cond is a custom
// reaction. The machine uses Statechart's defaults (states allocated with std::allocator).

#include <boost/mpl/list.hpp>
#include <boost/statechart/custom_reaction.hpp>
#include <boost/statechart/deep_history.hpp>
#include <boost/statechart/event.hpp>
#include <boost/statechart/state.hpp>
#include <boost/statechart/state_machine.hpp>
#include <boost/statechart/transition.hpp>
#include <tuple>

#include "mcs_workload.hpp"

namespace {

namespace sc = boost::statechart;
namespace mpl = boost::mpl;
using namespace mcs_bench;

struct on_p : sc::event<on_p> {};
struct off_p : sc::event<off_p> {};
struct estop_p : sc::event<estop_p> {};
struct reset_p : sc::event<reset_p> {};
struct mem_p : sc::event<mem_p> {};
struct mdi_p : sc::event<mdi_p> {};
struct tape_p : sc::event<tape_p> {};
struct hnd_p : sc::event<hnd_p> {};
struct jog_p : sc::event<jog_p> {};
struct rpd_p : sc::event<rpd_p> {};
struct zrn_p : sc::event<zrn_p> {};
struct edit_p : sc::event<edit_p> {};
struct setup_p : sc::event<setup_p> {};

struct MCS;
struct Off;
struct Estop;
struct On;
struct Auto;
struct Manual;
struct Edit;
struct Setup;
struct Mem;
struct Mdi;
struct Tape;
struct Handle;
struct Jog;
struct Rpd;
struct Zrn;

struct Machine : sc::state_machine<Machine, MCS> {
    panel p;
    void set_error0(reset_p const&) { p.error = 0; }
    void set_error1(estop_p const&) { p.error = 1; }
};

// A state whose entry and exit actions are Show.
template <class Self, class Context, class Inner = mpl::list<>, sc::history_mode History = sc::has_no_history>
struct shown : sc::state<Self, Context, Inner, History> {
    using base = sc::state<Self, Context, Inner, History>;
    explicit shown(typename base::my_context ctx) : base(ctx) {
        this->outermost_context().p.display.show(Self::name, true);
    }
    void exit() { this->outermost_context().p.display.show(Self::name, false); }
};

struct MCS : shown<MCS, Machine, Off> {
    using shown::shown;
    static constexpr std::string_view name = "MCS";
};
struct Off : shown<Off, MCS> {
    using shown::shown;
    static constexpr std::string_view name = "Off";
    using reactions = mpl::list<sc::transition<on_p, sc::deep_history<Auto>>,
                                sc::transition<estop_p, Estop, Machine, &Machine::set_error1>>;
};
struct Estop : shown<Estop, MCS> {
    using shown::shown;
    static constexpr std::string_view name = "Estop";
    using reactions =
        mpl::list<sc::transition<reset_p, Estop, Machine, &Machine::set_error0>, sc::custom_reaction<off_p>,
                  sc::transition<estop_p, Estop, Machine, &Machine::set_error1>>;
    sc::result react(off_p const&) {
        if (outermost_context().p.error == 0)  // cond
            return transit<Off>();
        return discard_event();
    }
};
struct On : shown<On, MCS, Auto, sc::has_deep_history> {
    using shown::shown;
    static constexpr std::string_view name = "On";
    using reactions =
        mpl::list<sc::transition<off_p, Off>, sc::transition<estop_p, Estop, Machine, &Machine::set_error1>>;
};
struct Auto : shown<Auto, On, Mem> {
    using shown::shown;
    static constexpr std::string_view name = "Auto";
    using reactions =
        mpl::list<sc::transition<hnd_p, Handle>, sc::transition<jog_p, Jog>, sc::transition<rpd_p, Rpd>,
                  sc::transition<zrn_p, Zrn>, sc::transition<edit_p, Edit>, sc::transition<setup_p, Setup>>;
};
struct Manual : shown<Manual, On, Handle> {
    using shown::shown;
    static constexpr std::string_view name = "Manual";
    using reactions = mpl::list<sc::transition<mem_p, Mem>, sc::transition<mdi_p, Mdi>, sc::transition<tape_p, Tape>,
                                sc::transition<edit_p, Edit>, sc::transition<setup_p, Setup>>;
};
struct Edit : shown<Edit, On> {
    using shown::shown;
    static constexpr std::string_view name = "Edit";
    using reactions = mpl::list<sc::transition<mem_p, Mem>, sc::transition<mdi_p, Mdi>, sc::transition<tape_p, Tape>,
                                sc::transition<hnd_p, Handle>, sc::transition<jog_p, Jog>, sc::transition<rpd_p, Rpd>,
                                sc::transition<zrn_p, Zrn>, sc::transition<setup_p, Setup>>;
};
struct Setup : shown<Setup, On> {
    using shown::shown;
    static constexpr std::string_view name = "Setup";
    using reactions = mpl::list<sc::transition<mem_p, Mem>, sc::transition<mdi_p, Mdi>, sc::transition<tape_p, Tape>,
                                sc::transition<hnd_p, Handle>, sc::transition<jog_p, Jog>, sc::transition<rpd_p, Rpd>,
                                sc::transition<zrn_p, Zrn>, sc::transition<edit_p, Edit>>;
};
struct Mem : shown<Mem, Auto> {
    using shown::shown;
    static constexpr std::string_view name = "Mem";
    using reactions = mpl::list<sc::transition<mdi_p, Mdi>, sc::transition<tape_p, Tape>>;
};
struct Mdi : shown<Mdi, Auto> {
    using shown::shown;
    static constexpr std::string_view name = "Mdi";
    using reactions = mpl::list<sc::transition<mem_p, Mem>, sc::transition<tape_p, Tape>>;
};
struct Tape : shown<Tape, Auto> {
    using shown::shown;
    static constexpr std::string_view name = "Tape";
    using reactions = mpl::list<sc::transition<mem_p, Mem>, sc::transition<mdi_p, Mdi>>;
};
struct Handle : shown<Handle, Manual> {
    using shown::shown;
    static constexpr std::string_view name = "Handle";
    using reactions = mpl::list<sc::transition<jog_p, Jog>, sc::transition<rpd_p, Rpd>, sc::transition<zrn_p, Zrn>>;
};
struct Jog : shown<Jog, Manual> {
    using shown::shown;
    static constexpr std::string_view name = "Jog";
    using reactions = mpl::list<sc::transition<hnd_p, Handle>, sc::transition<rpd_p, Rpd>, sc::transition<zrn_p, Zrn>>;
};
struct Rpd : shown<Rpd, Manual> {
    using shown::shown;
    static constexpr std::string_view name = "Rpd";
    using reactions = mpl::list<sc::transition<hnd_p, Handle>, sc::transition<jog_p, Jog>, sc::transition<zrn_p, Zrn>>;
};
struct Zrn : shown<Zrn, Manual> {
    using shown::shown;
    static constexpr std::string_view name = "Zrn";
    using reactions = mpl::list<sc::transition<hnd_p, Handle>, sc::transition<jog_p, Jog>, sc::transition<rpd_p, Rpd>>;
};

class supervisor {
public:
    supervisor() { m_.initiate(); }
    supervisor(supervisor const&) = delete;
    supervisor& operator=(supervisor const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<event_count>(event, [&](auto i) { m_.process_event(std::get<decltype(i)::value>(events_)); });
    }

    workload::observation observe() const { return workload::observe(active(), m_.p.error, m_.p.display); }

private:
    template <class S>
    bool is() const {
        return m_.state_cast<S const*>() != nullptr;
    }
    leaf active() const {
        if (is<Off>()) return leaf::Off;
        if (is<Estop>()) return leaf::Estop;
        if (is<Mem>()) return leaf::Mem;
        if (is<Mdi>()) return leaf::Mdi;
        if (is<Tape>()) return leaf::Tape;
        if (is<Handle>()) return leaf::Handle;
        if (is<Jog>()) return leaf::Jog;
        if (is<Rpd>()) return leaf::Rpd;
        if (is<Zrn>()) return leaf::Zrn;
        if (is<Edit>()) return leaf::Edit;
        return leaf::Setup;
    }

    Machine m_;
    // Statechart events are reference-counted objects: built once, dispatched by reference.
    std::tuple<on_p, off_p, estop_p, reset_p, mem_p, mdi_p, tape_p, hnd_p, jog_p, rpd_p, zrn_p, edit_p, setup_p>
        events_;
};

}  // namespace

BENCH_IMPL(mcs_bench::workload, "boost_statechart", supervisor);
