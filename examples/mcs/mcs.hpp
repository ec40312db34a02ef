#pragma once
// The Mode Control Supervisor (MCS) of a Mori Seiki GV503 5-axis machining center, from the
// case study (section 4) of a paper proposing a model-driven design of the discrete event
// control of machine tools. The MCS decides the work mode of the machine from the buttons the
// operator pushes.
//
// How the paper maps to this file:
//
//   Paper                                   Code
//   --------------------------------------  ----------------------------------------------------
//   states MCS, Off, On, Emergency stop     mcs::MCS, Off, On, Estop
//   groups Automatic, Manual, Program       mcs::Auto, Manual, Edit, Setup
//     Edit, Parameter Setup
//   modes MEM, MDI, TAPE                    mcs::Mem, Mdi, Tape
//   modes Handle, JOG, RPD, ZRN             mcs::Handle, Jog, Rpd, Zrn
//   Table 1 (work mode groups and modes)    the state tree, first argument of mcs::chart
//   Figure 12 (topology table)              the same state tree; its Status column (_Hist on On)
//                                           is bsc::deep_history; its Descend column gives the
//                                           initial children (MCS: Off, On: Auto, Auto: Mem)
//   Figure 12, Entry and Exit columns       the on_entry / on_exit rows, all calling Show
//   Show                                    mcs::show_entry<S> / mcs::show_exit<S>: they put "+S"
//                                           or "-S" on the panel's display (mcs::display)
//   Figure 13 (transition table)            mcs::figure13(cond): its rows one for one
//   the 13 events (button pushes)           mcs::on_p ... mcs::setup_p; Button::name is the
//                                           paper's name in capitals ("ON_P", "ESTOP_P"; the
//                                           paper does not name Handle's: "HND_P")
//   Set_Error0, Set_Error1                  mcs::set_error0, mcs::set_error1 (panel::error)
//   cond (guard of Estop + Off_P)           mcs::cond: the E-stop error has been reset
//   mode changes described in the prose     the "mode buttons" rows
//   verification (Figure 5: conflicting     bsc's compile-time checks: a chart with such a flaw
//     transitions, unreachable states,      does not compile
//     dead ends)
//   validation by simulation (Figure 11)    the scripted run of examples/mcs/main.cpp and
//                                           tests/unit/mcs_test.cpp
//   the virtual HMI of Figure 11            examples/mcs/main.cpp --interactive
//
// Where the paper is silent, the choices made are marked "Paper silent:" below and listed in
// docs/examples/mcs.md.

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/bsc.hpp>

namespace mcs {

// ---- The 13 events: one per button of the operator panel ----------------------------------------
// `name` is the paper's event name, which is also what the operator types in the virtual HMI.

struct on_p {
    static constexpr std::string_view name = "ON_P", label = "power on";
};
struct off_p {
    static constexpr std::string_view name = "OFF_P", label = "power off";
};
struct estop_p {
    static constexpr std::string_view name = "ESTOP_P", label = "emergency stop";
};
struct reset_p {
    static constexpr std::string_view name = "RESET_P", label = "reset (acknowledge the emergency stop)";
};
struct mem_p {
    static constexpr std::string_view name = "MEM_P", label = "Auto: MEM, run the program in memory";
};
struct mdi_p {
    static constexpr std::string_view name = "MDI_P", label = "Auto: MDI, manual data input";
};
struct tape_p {
    static constexpr std::string_view name = "TAPE_P", label = "Auto: TAPE, run a program fed by DNC";
};
struct hnd_p {
    static constexpr std::string_view name = "HND_P", label = "Manual: Handle, move an axis with the handwheel";
};
struct jog_p {
    static constexpr std::string_view name = "JOG_P", label = "Manual: JOG, jog an axis";
};
struct rpd_p {
    static constexpr std::string_view name = "RPD_P", label = "Manual: RPD, rapid traverse";
};
struct zrn_p {
    static constexpr std::string_view name = "ZRN_P", label = "Manual: ZRN, return to the home position";
};
struct edit_p {
    static constexpr std::string_view name = "EDIT_P", label = "Program Edit";
};
struct setup_p {
    static constexpr std::string_view name = "SETUP_P", label = "Parameter Setup";
};

/// The buttons of the panel, in the order the help text lists them.
template <class... Buttons>
struct button_list {};
using buttons =
    button_list<on_p, off_p, estop_p, reset_p, mem_p, mdi_p, tape_p, hnd_p, jog_p, rpd_p, zrn_p, edit_p, setup_p>;

// ---- The states of Table 1 and Figure 12 --------------------------------------------------------
// The modes are spelled as type names (Mem for the paper's MEM); the buttons keep the paper's
// capitals (MEM_P).

struct MCS;  // level 1
struct Off;  // level 2
struct On;
struct Estop;  // Emergency stop
struct Auto;   // level 3: the work mode groups
struct Manual;
struct Edit;   // Program Edit
struct Setup;  // Parameter Setup
struct Mem;    // level 4: the work modes of Auto
struct Mdi;
struct Tape;
struct Handle;  // level 4: the work modes of Manual
struct Jog;
struct Rpd;
struct Zrn;

// ---- The context: what the supervisor keeps besides its active states ---------------------------

/// The operator's display: what Show has put on it, most recent last. It has a fixed
/// capacity so that Show never allocates; older lines scroll away.
class display {
public:
    static constexpr std::size_t capacity = 16;
    struct line {
        std::string_view state;
        bool entered;  // true: "+state", false: "-state"
    };

    constexpr void show(std::string_view state, bool entered) {
        lines_[count_ % capacity] = {state, entered};
        ++count_;
    }
    constexpr void clear() { count_ = 0; }
    constexpr std::size_t size() const { return count_ < capacity ? count_ : capacity; }
    /// How many lines Show has put on the display, scrolled away or not: a mark from which
    /// text_since tells what came after (the display is the chart's; the operator reads it).
    constexpr std::size_t shown() const { return count_; }
    constexpr bool empty() const { return count_ == 0; }
    /// The i-th line still on the display, oldest first.
    constexpr line operator[](std::size_t i) const {
        std::size_t const first = count_ < capacity ? 0 : count_ - capacity;
        return lines_[(first + i) % capacity];
    }
    /// The lines on the display, e.g. "-Mem +Mdi" (for printing, outside the dispatch path).
    std::string text() const { return text_since(0); }
    /// The lines still on the display that Show put there after the first `mark` (shown()).
    std::string text_since(std::size_t mark) const {
        std::string out;
        std::size_t const first = count_ < capacity ? 0 : count_ - capacity;
        for (std::size_t i = mark > first ? mark - first : 0; i < size(); ++i) {
            if (!out.empty()) out += ' ';
            out += (*this)[i].entered ? '+' : '-';
            out += (*this)[i].state;
        }
        return out;
    }

private:
    std::array<line, capacity> lines_{};
    std::size_t count_ = 0;
};

/// The context of the chart: the operator panel.
struct panel {
    int error = 0;         ///< 1 after an emergency stop (Set_Error1), 0 once reset (Set_Error0)
    mcs::display display;  ///< what Show has displayed
};

// ---- Guard and actions of Figures 12 and 13 -----------------------------------------------------

// Each has the paper's name (bsc::named), which the diagrams of the chart show.

/// Figure 13's Set_Error0 and Set_Error1.
inline constexpr auto set_error0 = bsc::named<"Set_Error0">(bsc::action([](panel& p) { p.error = 0; }));
inline constexpr auto set_error1 = bsc::named<"Set_Error1">(bsc::action([](panel& p) { p.error = 1; }));

/// Figure 13's cond, guarding Estop + Off_P = Off. The paper does not define it.
/// Paper silent: cond holds once the emergency stop has been acknowledged with RESET_P
/// (error 0). An operator expects to acknowledge an E-stop before the machine can leave it:
/// Off leads straight back to On, so leaving Estop with the error still set would let the
/// machine be switched on again without anyone acknowledging the stop.
inline constexpr auto cond = bsc::named<"cond">(bsc::guard([](panel const& p) { return p.error == 0; }));

/// Figure 12's Show, the entry and the exit action of every state: it puts the state on the
/// display as entered ("+S") or left ("-S").
template <class S>
inline constexpr auto show_entry = bsc::named<"Show">([](panel& p) { p.display.show(bsc::name_of<S>, true); });
template <class S>
inline constexpr auto show_exit = bsc::named<"Show">([](panel& p) { p.display.show(bsc::name_of<S>, false); });

// ---- The chart ----------------------------------------------------------------------------------

// Table 1 and Figure 12: the topology, one level per indentation, siblings in Figure 12's
// order (Off, Estop, On).
inline constexpr auto tree = bsc::composite<MCS>(
    bsc::initial<Off>, bsc::state<Off>, bsc::state<Estop>,
    // _Hist (Figure 12): coming back On restores the work mode in use when On was left.
    // Deep history because the paper's engine (Figure 9, step 5) "searches the history
    // condition until an atomic state is finally reached", i.e. down to the mode itself.
    bsc::composite<On>(bsc::deep_history, bsc::initial<Auto>,
                       bsc::composite<Auto>(bsc::initial<Mem>, bsc::state<Mdi>, bsc::state<Tape>),
                       // Paper silent: Manual's default. Handle, listed first in Table 1 as MEM is for
                       // Auto, and the slowest way to move an axis. No row ever relies on it: every
                       // Manual button names its mode, and On's history names the mode it restores.
                       bsc::composite<Manual>(bsc::initial<Handle>, bsc::state<Jog>, bsc::state<Rpd>, bsc::state<Zrn>),
                       bsc::state<Edit>, bsc::state<Setup>));

// The chart's rows come in groups (bsc::rows), so that the verification tests can build
// deliberately broken variants from the same parts.
inline constexpr auto show_rows = bsc::rows(
    // Figure 12, columns Entry and Exit: every state calls Show when entered and when left.
    bsc::state<MCS> + bsc::on_entry / show_entry<MCS>, bsc::state<MCS> + bsc::on_exit / show_exit<MCS>,
    bsc::state<Off> + bsc::on_entry / show_entry<Off>, bsc::state<Off> + bsc::on_exit / show_exit<Off>,
    bsc::state<Estop> + bsc::on_entry / show_entry<Estop>, bsc::state<Estop> + bsc::on_exit / show_exit<Estop>,
    bsc::state<On> + bsc::on_entry / show_entry<On>, bsc::state<On> + bsc::on_exit / show_exit<On>,
    bsc::state<Auto> + bsc::on_entry / show_entry<Auto>, bsc::state<Auto> + bsc::on_exit / show_exit<Auto>,
    bsc::state<Manual> + bsc::on_entry / show_entry<Manual>, bsc::state<Manual> + bsc::on_exit / show_exit<Manual>,
    bsc::state<Edit> + bsc::on_entry / show_entry<Edit>, bsc::state<Edit> + bsc::on_exit / show_exit<Edit>,
    bsc::state<Setup> + bsc::on_entry / show_entry<Setup>, bsc::state<Setup> + bsc::on_exit / show_exit<Setup>,
    bsc::state<Mem> + bsc::on_entry / show_entry<Mem>, bsc::state<Mem> + bsc::on_exit / show_exit<Mem>,
    bsc::state<Mdi> + bsc::on_entry / show_entry<Mdi>, bsc::state<Mdi> + bsc::on_exit / show_exit<Mdi>,
    bsc::state<Tape> + bsc::on_entry / show_entry<Tape>, bsc::state<Tape> + bsc::on_exit / show_exit<Tape>,
    bsc::state<Handle> + bsc::on_entry / show_entry<Handle>, bsc::state<Handle> + bsc::on_exit / show_exit<Handle>,
    bsc::state<Jog> + bsc::on_entry / show_entry<Jog>, bsc::state<Jog> + bsc::on_exit / show_exit<Jog>,
    bsc::state<Rpd> + bsc::on_entry / show_entry<Rpd>, bsc::state<Rpd> + bsc::on_exit / show_exit<Rpd>,
    bsc::state<Zrn> + bsc::on_entry / show_entry<Zrn>, bsc::state<Zrn> + bsc::on_exit / show_exit<Zrn>);

/// Figure 13, with its guard `cond` as a parameter (the chart uses mcs::cond).
template <class Cond>
constexpr auto figure13(Cond c) {
    return bsc::rows(
        // Figure 13: origin state + event [guard] / action = destination state.
        bsc::state<Off> + bsc::event<on_p> = bsc::state<On>,
        bsc::state<Estop> + bsc::event<reset_p> / set_error0 = bsc::state<Estop>,  // external: Show -Estop +Estop
        bsc::state<Estop> + bsc::event<off_p>[c] = bsc::state<Off>,
        bsc::state<On> + bsc::event<off_p> = bsc::state<Off>,
        bsc::state<On> + bsc::event<estop_p> / set_error1 = bsc::state<Estop>);
}

inline constexpr auto estop_rows = bsc::rows(
    // Paper silent: the E-stop button acts in every state, not only in On. While Off it latches
    // the stop too, so the machine cannot be switched on before the stop is acknowledged; in
    // Estop after a reset it latches the stop again (without this row a second E-stop pushed
    // after RESET_P would be ignored and OFF_P would then pass cond).
    bsc::state<Off> + bsc::event<estop_p> / set_error1 = bsc::state<Estop>,
    bsc::state<Estop> + bsc::event<estop_p> / set_error1 = bsc::state<Estop>
    // Paper silent, and left without a row, so ignored: ON_P while On or in Estop (from Estop
    // the way back is RESET_P, OFF_P, ON_P), OFF_P while Off, RESET_P outside Estop (there is
    // nothing to reset: the error is 0 whenever the machine is not in Estop).
);

inline constexpr auto mode_rows = bsc::rows(
    // The mode buttons (section 4: "when the machine is working in MEM mode and the MDI mode
    // button is pushed, the machine will be changed to MDI mode"), for every mode: a mode button
    // selects its mode from any other mode of On. Within a group the row leaves the mode (Mem
    // -> Mdi exits Mem only); from another group it leaves that group (Manual -> Mdi exits the
    // Manual mode and Manual). One row On + MDI_P = Mdi would instead exit and re-enter On, as
    // every transition from a state to its descendant does.
    // Paper silent: the button of the mode already selected, and every mode button while Off or
    // in Estop, is ignored (the mode is chosen while the machine is On; switching On again
    // restores the last one through On's history).
    //   Auto
    bsc::state<Mdi> + bsc::event<mem_p> = bsc::state<Mem>, bsc::state<Tape> + bsc::event<mem_p> = bsc::state<Mem>,
    bsc::state<Manual> + bsc::event<mem_p> = bsc::state<Mem>, bsc::state<Edit> + bsc::event<mem_p> = bsc::state<Mem>,
    bsc::state<Setup> + bsc::event<mem_p> = bsc::state<Mem>,

    bsc::state<Mem> + bsc::event<mdi_p> = bsc::state<Mdi>, bsc::state<Tape> + bsc::event<mdi_p> = bsc::state<Mdi>,
    bsc::state<Manual> + bsc::event<mdi_p> = bsc::state<Mdi>, bsc::state<Edit> + bsc::event<mdi_p> = bsc::state<Mdi>,
    bsc::state<Setup> + bsc::event<mdi_p> = bsc::state<Mdi>,

    bsc::state<Mem> + bsc::event<tape_p> = bsc::state<Tape>, bsc::state<Mdi> + bsc::event<tape_p> = bsc::state<Tape>,
    bsc::state<Manual> + bsc::event<tape_p> = bsc::state<Tape>,
    bsc::state<Edit> + bsc::event<tape_p> = bsc::state<Tape>, bsc::state<Setup> + bsc::event<tape_p> = bsc::state<Tape>,
    //   Manual
    bsc::state<Jog> + bsc::event<hnd_p> = bsc::state<Handle>, bsc::state<Rpd> + bsc::event<hnd_p> = bsc::state<Handle>,
    bsc::state<Zrn> + bsc::event<hnd_p> = bsc::state<Handle>, bsc::state<Auto> + bsc::event<hnd_p> = bsc::state<Handle>,
    bsc::state<Edit> + bsc::event<hnd_p> = bsc::state<Handle>,
    bsc::state<Setup> + bsc::event<hnd_p> = bsc::state<Handle>,

    bsc::state<Handle> + bsc::event<jog_p> = bsc::state<Jog>, bsc::state<Rpd> + bsc::event<jog_p> = bsc::state<Jog>,
    bsc::state<Zrn> + bsc::event<jog_p> = bsc::state<Jog>, bsc::state<Auto> + bsc::event<jog_p> = bsc::state<Jog>,
    bsc::state<Edit> + bsc::event<jog_p> = bsc::state<Jog>, bsc::state<Setup> + bsc::event<jog_p> = bsc::state<Jog>,

    bsc::state<Handle> + bsc::event<rpd_p> = bsc::state<Rpd>, bsc::state<Jog> + bsc::event<rpd_p> = bsc::state<Rpd>,
    bsc::state<Zrn> + bsc::event<rpd_p> = bsc::state<Rpd>, bsc::state<Auto> + bsc::event<rpd_p> = bsc::state<Rpd>,
    bsc::state<Edit> + bsc::event<rpd_p> = bsc::state<Rpd>, bsc::state<Setup> + bsc::event<rpd_p> = bsc::state<Rpd>,

    bsc::state<Handle> + bsc::event<zrn_p> = bsc::state<Zrn>, bsc::state<Jog> + bsc::event<zrn_p> = bsc::state<Zrn>,
    bsc::state<Rpd> + bsc::event<zrn_p> = bsc::state<Zrn>, bsc::state<Auto> + bsc::event<zrn_p> = bsc::state<Zrn>,
    bsc::state<Edit> + bsc::event<zrn_p> = bsc::state<Zrn>, bsc::state<Setup> + bsc::event<zrn_p> = bsc::state<Zrn>,
    //   Program Edit and Parameter Setup
    bsc::state<Auto> + bsc::event<edit_p> = bsc::state<Edit>,
    bsc::state<Manual> + bsc::event<edit_p> = bsc::state<Edit>,
    bsc::state<Setup> + bsc::event<edit_p> = bsc::state<Edit>,

    bsc::state<Auto> + bsc::event<setup_p> = bsc::state<Setup>,
    bsc::state<Manual> + bsc::event<setup_p> = bsc::state<Setup>,
    bsc::state<Edit> + bsc::event<setup_p> = bsc::state<Setup>);

inline constexpr auto chart = bsc::make_chart<panel>(tree, show_rows, figure13(cond), estop_rows, mode_rows);

/// The supervisor: the chart running over a panel.
using machine = bsc::machine<bsc::chart_ref<chart>>;

}  // namespace mcs
