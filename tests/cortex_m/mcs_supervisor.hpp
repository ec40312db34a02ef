#pragma once
// The Mode Control Supervisor of examples/mcs/mcs.hpp on a recorded sequence of button presses,
// as a bsc machine of the example's chart and as an engineer writes it by hand (the
// hand-written supervisor of bench/mcs/mcs_hand.cpp, standing alone), both run on the host and
// the Cortex-M4.
//
// The sequence: 1024 presses drawn from a xorshift64* generator (seed 2024), weighted so that
// the machine spends much of its time On, changing modes, as at an operator's panel (drawn
// uniformly, as bench/mcs's sequence is, most presses would find it in Estop, which only
// RESET_P then OFF_P leave): of 64, ESTOP_P 1, RESET_P 6, OFF_P 3, ON_P 8, and
// the nine mode buttons the other 46. Button indices follow mcs::buttons: 0 ON_P, 1 OFF_P,
// 2 ESTOP_P, 3 RESET_P, 4 MEM_P, 5 MDI_P, 6 TAPE_P, 7 HND_P, 8 JOG_P, 9 RPD_P, 10 ZRN_P, 11 EDIT_P,
// 12 SETUP_P. The trace shows after each press the active leaf, the error flag, how many lines
// Show has written and the last of them.

#include <cstdint>
#include <string_view>

#include "../../bench/mcs/mcs_display.hpp"
#include "../../examples/mcs/mcs.hpp"
#include "driver.hpp"

namespace supervisor {

using namespace std::string_view_literals;

enum class leaf : std::uint8_t { Off, Estop, Mem, Mdi, Tape, Handle, Jog, Rpd, Zrn, Edit, Setup };

struct observation {
    leaf active = leaf::Off;
    int error = 0;
    std::size_t shown = 0;       // lines Show has written
    std::string_view last = {};  // the state of the last one
    bool entered = false;        // and whether it was entered or left
};

/// What the trace reads of a display with shown(), size() and operator[] as mcs::display's.
template <class Display>
observation observe(leaf active, int error, Display const& d) {
    observation o{active, error, d.shown(), {}, false};
    if (d.size() > 0) {
        auto const last = d[d.size() - 1];
        o.last = last.state;
        o.entered = last.entered;
    }
    return o;
}

struct workload {
    static void record(std::uint8_t (&sequence)[cm::sequence_length]) {
        std::uint64_t s = 2024 * 0x9E3779B97F4A7C15ull + 1;  // xorshift64*
        for (auto& e : sequence) {
            s ^= s >> 12;
            s ^= s << 25;
            s ^= s >> 27;
            auto const slot = static_cast<std::uint32_t>((s * 0x2545F4914F6CDD1Dull) >> 58);  // 0..63
            e = static_cast<std::uint8_t>(slot == 0   ? 2
                                          : slot < 7  ? 3
                                          : slot < 10 ? 1
                                          : slot < 18 ? 0
                                                      : 4 + (slot - 18) % 9);
        }
    }
    static constexpr std::size_t trace_events = 600;
    static void print(cm::line& out, observation const& o) {
        static constexpr char const* names[] = {"Off", "Estop", "Mem", "Mdi",  "Tape", "Handle",
                                                "Jog", "Rpd",   "Zrn", "Edit", "Setup"};
        out << names[static_cast<int>(o.active)] << ' ' << static_cast<std::uint32_t>(o.error) << ' '
            << static_cast<std::uint32_t>(o.shown) << ' ' << (o.entered ? '+' : '-') << o.last;
    }
    static std::uint32_t checksum(observation const& o) {
        return (static_cast<std::uint32_t>(o.shown) * 16 + static_cast<std::uint32_t>(o.active)) * 2 +
               static_cast<std::uint32_t>(o.error);
    }
};

// ---- bsc --------------------------------------------------------------------------------------

/// The driver's adapter for a bsc machine of mcs::chart, the global `subject`.
template <auto& subject>
struct bsc_adapter {
    static void on(std::uint8_t e) {
        switch (e) {
            case 0: subject.dispatch(mcs::on_p{}); break;
            case 1: subject.dispatch(mcs::off_p{}); break;
            case 2: subject.dispatch(mcs::estop_p{}); break;
            case 3: subject.dispatch(mcs::reset_p{}); break;
            case 4: subject.dispatch(mcs::mem_p{}); break;
            case 5: subject.dispatch(mcs::mdi_p{}); break;
            case 6: subject.dispatch(mcs::tape_p{}); break;
            case 7: subject.dispatch(mcs::hnd_p{}); break;
            case 8: subject.dispatch(mcs::jog_p{}); break;
            case 9: subject.dispatch(mcs::rpd_p{}); break;
            case 10: subject.dispatch(mcs::zrn_p{}); break;
            case 11: subject.dispatch(mcs::edit_p{}); break;
            case 12: subject.dispatch(mcs::setup_p{}); break;
            default: break;
        }
    }
    static observation observe() {
        auto const& p = subject.context();
        return supervisor::observe(active(), p.error, p.display);
    }
    static leaf active() {
        if (subject.template is<mcs::Off>()) return leaf::Off;
        if (subject.template is<mcs::Estop>()) return leaf::Estop;
        if (subject.template is<mcs::Mem>()) return leaf::Mem;
        if (subject.template is<mcs::Mdi>()) return leaf::Mdi;
        if (subject.template is<mcs::Tape>()) return leaf::Tape;
        if (subject.template is<mcs::Handle>()) return leaf::Handle;
        if (subject.template is<mcs::Jog>()) return leaf::Jog;
        if (subject.template is<mcs::Rpd>()) return leaf::Rpd;
        if (subject.template is<mcs::Zrn>()) return leaf::Zrn;
        if (subject.template is<mcs::Edit>()) return leaf::Edit;
        return leaf::Setup;
    }
};

// ---- By hand ----------------------------------------------------------------------------------

/// The last 16 lines Show wrote, as mcs::display keeps them (bench/mcs's).
using display = mcs_bench::display;

/// One enum per composite, which also keeps On's deep history (nothing resets them when On is
/// left); a switch on the button, then on the state; Show called in the chart's order (exits
/// innermost first, the action, entries outermost first). The names are string_view literals:
/// from a char pointer, -Os calls strlen.
class hand_written {
public:
    hand_written() {
        show("MCS"sv, true);
        show("Off"sv, true);
    }

    void on(std::uint8_t button) {
        switch (button) {
            case 0:  // ON_P
                if (top_ == top::off) {
                    show("Off"sv, false);
                    enter_on();
                }
                break;
            case 1:  // OFF_P
                if (top_ == top::on) {
                    exit_on();
                    top_ = top::off;
                    show("Off"sv, true);
                } else if (top_ == top::estop && error_ == 0) {  // cond
                    show("Estop"sv, false);
                    top_ = top::off;
                    show("Off"sv, true);
                }
                break;
            case 2:  // ESTOP_P, from every top-level state: Set_Error1
                if (top_ == top::on)
                    exit_on();
                else
                    show(top_ == top::off ? "Off"sv : "Estop"sv, false);
                error_ = 1;
                top_ = top::estop;
                show("Estop"sv, true);
                break;
            case 3:  // RESET_P: an external self-transition of Estop with Set_Error0
                if (top_ == top::estop) {
                    show("Estop"sv, false);
                    error_ = 0;
                    show("Estop"sv, true);
                }
                break;
            case 4: select_auto(automatic::mem); break;
            case 5: select_auto(automatic::mdi); break;
            case 6: select_auto(automatic::tape); break;
            case 7: select_manual(manual::handle); break;
            case 8: select_manual(manual::jog); break;
            case 9: select_manual(manual::rpd); break;
            case 10: select_manual(manual::zrn); break;
            case 11: select_group(group::edit); break;
            case 12: select_group(group::setup); break;
            default: break;
        }
    }

    observation observe() const { return supervisor::observe(active(), error_, display_); }

private:
    enum class top : std::uint8_t { off, estop, on };
    enum class group : std::uint8_t { automatic, manual, edit, setup };
    enum class automatic : std::uint8_t { mem, mdi, tape };
    enum class manual : std::uint8_t { handle, jog, rpd, zrn };

    static constexpr std::string_view group_names[] = {"Auto", "Manual", "Edit", "Setup"};
    static constexpr std::string_view auto_names[] = {"Mem", "Mdi", "Tape"};
    static constexpr std::string_view manual_names[] = {"Handle", "Jog", "Rpd", "Zrn"};

    void show(std::string_view state, bool entered) { display_.show(state, entered); }
    void show_mode(bool entered) {
        if (group_ == group::automatic)
            show(auto_names[static_cast<int>(auto_)], entered);
        else if (group_ == group::manual)
            show(manual_names[static_cast<int>(manual_)], entered);
    }

    void enter_on() {  // through the deep history: the group and mode On was left in
        top_ = top::on;
        show("On"sv, true);
        show(group_names[static_cast<int>(group_)], true);
        show_mode(true);
    }
    void exit_group() {
        show_mode(false);
        show(group_names[static_cast<int>(group_)], false);
    }
    void exit_on() {
        exit_group();
        show("On"sv, false);
    }

    // A mode button: within its group it changes the mode only; from another group it leaves
    // that group and enters its own in the mode named. Ignored unless On, and for the mode
    // already selected.
    void select_auto(automatic m) {
        if (top_ != top::on) return;
        if (group_ == group::automatic) {
            if (auto_ == m) return;
            show_mode(false);
        } else {
            exit_group();
            group_ = group::automatic;
            show("Auto"sv, true);
        }
        auto_ = m;
        show_mode(true);
    }
    void select_manual(manual m) {
        if (top_ != top::on) return;
        if (group_ == group::manual) {
            if (manual_ == m) return;
            show_mode(false);
        } else {
            exit_group();
            group_ = group::manual;
            show("Manual"sv, true);
        }
        manual_ = m;
        show_mode(true);
    }
    void select_group(group g) {  // EDIT_P and SETUP_P, from the other groups
        if (top_ != top::on || group_ == g) return;
        exit_group();
        group_ = g;
        show(group_names[static_cast<int>(g)], true);
    }

    leaf active() const {
        if (top_ == top::off) return leaf::Off;
        if (top_ == top::estop) return leaf::Estop;
        switch (group_) {
            case group::automatic: return static_cast<leaf>(static_cast<int>(leaf::Mem) + static_cast<int>(auto_));
            case group::manual: return static_cast<leaf>(static_cast<int>(leaf::Handle) + static_cast<int>(manual_));
            case group::edit: return leaf::Edit;
            case group::setup: break;
        }
        return leaf::Setup;
    }

    int error_ = 0;
    display display_;
    top top_ = top::off;
    group group_ = group::automatic;
    automatic auto_ = automatic::mem;
    manual manual_ = manual::handle;
};

/// The floor the report measures the others from: the driver and a subject that keeps the last
/// button, so that the sequence and the printing stay in the image.
class floor {
public:
    void on(std::uint8_t e) { last_ = e; }
    observation observe() const { return {static_cast<leaf>(last_ & 7), 0, last_, "Off", true}; }

private:
    std::uint8_t last_ = 0;
};

/// The driver's adapter for the hand-written supervisor (or the floor), the global `subject`.
template <auto& subject>
struct hand_adapter {
    static void on(std::uint8_t e) { subject.on(e); }
    static observation observe() { return subject.observe(); }
};

}  // namespace supervisor
