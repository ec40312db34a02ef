// Workload mcs, Boost.MSM: back::state_machine with the functor front end. Each composite of
// the chart is a submachine (On, Auto, Manual); On's deep history is AlwaysHistory on On and on
// the two submachines below it (every entry into them is a history entry or names its target
// explicitly, so this restores exactly the deep history of the chart). Transitions into a mode
// of another group use MSM's direct entry (Auto::direct<Mem>). The machines declare
// no_exception_thrown and no_message_queue, MSM's documented options for speed.
//
// MSM's states are given the panel through a pointer held by every machine front end, set
// before start(); Show, Set_Error0/1 and cond are functors.

// MSM's transition tables are MPL vectors, 20 entries by default; On's has 27 rows. As MSM's
// documentation says, raise the limits before including any MSM header.
#define BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS
#define BOOST_MPL_LIMIT_VECTOR_SIZE 30
#define BOOST_MPL_LIMIT_MAP_SIZE 30

#include <boost/msm/back/state_machine.hpp>
#include <boost/msm/front/functor_row.hpp>
#include <boost/msm/front/state_machine_def.hpp>

#include "mcs_workload.hpp"

namespace {

namespace msm = boost::msm;
namespace mpl = boost::mpl;
using msm::front::none;
using msm::front::Row;
using namespace mcs_bench;

// The 13 buttons.
struct on_p {};
struct off_p {};
struct estop_p {};
struct reset_p {};
struct mem_p {};
struct mdi_p {};
struct tape_p {};
struct hnd_p {};
struct jog_p {};
struct rpd_p {};
struct zrn_p {};
struct edit_p {};
struct setup_p {};

struct with_panel {
    panel* p = nullptr;
};

// A basic state whose entry and exit actions are Show.
template <class Self>
struct shown : msm::front::state<> {
    template <class E, class F>
    void on_entry(E const&, F& fsm) {
        fsm.p->display.show(Self::name, true);
    }
    template <class E, class F>
    void on_exit(E const&, F& fsm) {
        fsm.p->display.show(Self::name, false);
    }
};

// The machine front ends: Show on entry and exit, the panel pointer, the speed options.
template <class Self>
struct shown_machine : msm::front::state_machine_def<Self>, with_panel {
    using no_exception_thrown = int;
    using no_message_queue = int;
    template <class E, class F>
    void on_entry(E const&, F&) {
        p->display.show(Self::name, true);
    }
    template <class E, class F>
    void on_exit(E const&, F&) {
        p->display.show(Self::name, false);
    }
    template <class E, class F>
    void no_transition(E const&, F&, int) {}
};

struct set_error0 {
    template <class E, class F, class S, class T>
    void operator()(E const&, F& fsm, S&, T&) const {
        fsm.p->error = 0;
    }
};
struct set_error1 {
    template <class E, class F, class S, class T>
    void operator()(E const&, F& fsm, S&, T&) const {
        fsm.p->error = 1;
    }
};
struct cond {
    template <class E, class F, class S, class T>
    bool operator()(E const&, F& fsm, S&, T&) const {
        return fsm.p->error == 0;
    }
};

// ---- Auto -------------------------------------------------------------------------------------
struct Mem : shown<Mem>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Mem";
};
struct Mdi : shown<Mdi>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Mdi";
};
struct Tape : shown<Tape>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Tape";
};
struct Auto_ : shown_machine<Auto_> {
    static constexpr std::string_view name = "Auto";
    using initial_state = Mem;
    using transition_table = mpl::vector<Row<Mdi, mem_p, Mem>, Row<Tape, mem_p, Mem>, Row<Mem, mdi_p, Mdi>,
                                         Row<Tape, mdi_p, Mdi>, Row<Mem, tape_p, Tape>, Row<Mdi, tape_p, Tape>>;
};
using Auto = msm::back::state_machine<Auto_, msm::back::AlwaysHistory>;

// ---- Manual -----------------------------------------------------------------------------------
struct Handle : shown<Handle>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Handle";
};
struct Jog : shown<Jog>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Jog";
};
struct Rpd : shown<Rpd>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Rpd";
};
struct Zrn : shown<Zrn>, msm::front::explicit_entry<0> {
    static constexpr std::string_view name = "Zrn";
};
struct Manual_ : shown_machine<Manual_> {
    static constexpr std::string_view name = "Manual";
    using initial_state = Handle;
    using transition_table =
        mpl::vector<Row<Jog, hnd_p, Handle>, Row<Rpd, hnd_p, Handle>, Row<Zrn, hnd_p, Handle>, Row<Handle, jog_p, Jog>,
                    Row<Rpd, jog_p, Jog>, Row<Zrn, jog_p, Jog>, Row<Handle, rpd_p, Rpd>, Row<Jog, rpd_p, Rpd>,
                    Row<Zrn, rpd_p, Rpd>, Row<Handle, zrn_p, Zrn>, Row<Jog, zrn_p, Zrn>, Row<Rpd, zrn_p, Zrn>>;
};
using Manual = msm::back::state_machine<Manual_, msm::back::AlwaysHistory>;

// ---- On ---------------------------------------------------------------------------------------
struct Edit : shown<Edit> {
    static constexpr std::string_view name = "Edit";
};
struct Setup : shown<Setup> {
    static constexpr std::string_view name = "Setup";
};
struct On_ : shown_machine<On_> {
    static constexpr std::string_view name = "On";
    using initial_state = Auto;
    using transition_table = mpl::vector<
        Row<Manual, mem_p, Auto::direct<Mem>>, Row<Edit, mem_p, Auto::direct<Mem>>,
        Row<Setup, mem_p, Auto::direct<Mem>>, Row<Manual, mdi_p, Auto::direct<Mdi>>,
        Row<Edit, mdi_p, Auto::direct<Mdi>>, Row<Setup, mdi_p, Auto::direct<Mdi>>,
        Row<Manual, tape_p, Auto::direct<Tape>>, Row<Edit, tape_p, Auto::direct<Tape>>,
        Row<Setup, tape_p, Auto::direct<Tape>>, Row<Auto, hnd_p, Manual::direct<Handle>>,
        Row<Edit, hnd_p, Manual::direct<Handle>>, Row<Setup, hnd_p, Manual::direct<Handle>>,
        Row<Auto, jog_p, Manual::direct<Jog>>, Row<Edit, jog_p, Manual::direct<Jog>>,
        Row<Setup, jog_p, Manual::direct<Jog>>, Row<Auto, rpd_p, Manual::direct<Rpd>>,
        Row<Edit, rpd_p, Manual::direct<Rpd>>, Row<Setup, rpd_p, Manual::direct<Rpd>>,
        Row<Auto, zrn_p, Manual::direct<Zrn>>, Row<Edit, zrn_p, Manual::direct<Zrn>>,
        Row<Setup, zrn_p, Manual::direct<Zrn>>, Row<Auto, edit_p, Edit>, Row<Manual, edit_p, Edit>,
        Row<Setup, edit_p, Edit>, Row<Auto, setup_p, Setup>, Row<Manual, setup_p, Setup>, Row<Edit, setup_p, Setup>>;
};
using On = msm::back::state_machine<On_, msm::back::AlwaysHistory>;

// ---- MCS --------------------------------------------------------------------------------------
struct Off : shown<Off> {
    static constexpr std::string_view name = "Off";
};
struct Estop : shown<Estop> {
    static constexpr std::string_view name = "Estop";
};
struct MCS_ : shown_machine<MCS_> {
    static constexpr std::string_view name = "MCS";
    using initial_state = Off;
    using transition_table =
        mpl::vector<Row<Off, on_p, On>, Row<Estop, reset_p, Estop, set_error0>, Row<Estop, off_p, Off, none, cond>,
                    Row<On, off_p, Off>, Row<On, estop_p, Estop, set_error1>, Row<Off, estop_p, Estop, set_error1>,
                    Row<Estop, estop_p, Estop, set_error1>>;
};
using MCS = msm::back::state_machine<MCS_>;

using buttons =
    mpl::vector<on_p, off_p, estop_p, reset_p, mem_p, mdi_p, tape_p, hnd_p, jog_p, rpd_p, zrn_p, edit_p, setup_p>;

class supervisor {
public:
    supervisor() {
        m_.p = &panel_;
        auto& on = m_.get_state<On&>();
        on.p = &panel_;
        on.get_state<Auto&>().p = &panel_;
        on.get_state<Manual&>().p = &panel_;
        m_.start();
    }
    supervisor(supervisor const&) = delete;
    supervisor& operator=(supervisor const&) = delete;

    void on(std::uint8_t event) {
        bench::with_index<event_count>(
            event, [&](auto i) { m_.process_event(typename mpl::at_c<buttons, decltype(i)::value>::type{}); });
    }

    workload::observation observe() const { return workload::observe(active(), panel_.error, panel_.display); }

private:
    template <class SM, class S>
    static constexpr int id = msm::back::get_state_id<typename SM::stt, S>::type::value;

    leaf active() const {
        int const top = m_.current_state()[0];
        if (top == id<MCS, Off>) return leaf::Off;
        if (top == id<MCS, Estop>) return leaf::Estop;
        auto const& on = m_.get_state<On const&>();
        int const g = on.current_state()[0];
        if (g == id<On, Auto>) {
            int const a = on.get_state<Auto const&>().current_state()[0];
            return a == id<Auto, Mem> ? leaf::Mem : a == id<Auto, Mdi> ? leaf::Mdi : leaf::Tape;
        }
        if (g == id<On, Manual>) {
            int const h = on.get_state<Manual const&>().current_state()[0];
            return h == id<Manual, Handle> ? leaf::Handle
                   : h == id<Manual, Jog>  ? leaf::Jog
                   : h == id<Manual, Rpd>  ? leaf::Rpd
                                           : leaf::Zrn;
        }
        return g == id<On, Edit> ? leaf::Edit : leaf::Setup;
    }

    panel panel_;
    MCS m_;
};

}  // namespace

BENCH_IMPL(mcs_bench::workload, "boost_msm", supervisor);
