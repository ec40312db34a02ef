// Workload mcs, hand-written: the supervisor as an engineer would write it without a library:
// one enum per composite (which also keeps On's deep history, since nothing resets it when On
// is left), a switch on the event, then on the state, Show called explicitly in the order the
// chart prescribes (exits innermost first, the action, entries outermost first).

#include "mcs_workload.hpp"

namespace {

using namespace mcs_bench;

class supervisor {
public:
    supervisor() {
        show("MCS", true);
        show("Off", true);
    }

    void on(std::uint8_t event) {
        switch (event) {
        case 0:  // ON_P
            if (top_ == top::off) {
                show("Off", false);
                enter_on();
            }
            break;
        case 1:  // OFF_P
            if (top_ == top::estop) {
                if (p_.error == 0) {  // cond
                    show("Estop", false);
                    top_ = top::off;
                    show("Off", true);
                }
            } else if (top_ == top::on) {
                exit_on();
                top_ = top::off;
                show("Off", true);
            }
            break;
        case 2:  // ESTOP_P: Set_Error1 from every top-level state
            if (top_ == top::on)
                exit_on();
            else
                show(top_ == top::off ? "Off" : "Estop", false);
            p_.error = 1;
            top_ = top::estop;
            show("Estop", true);
            break;
        case 3:  // RESET_P
            if (top_ == top::estop) {
                show("Estop", false);
                p_.error = 0;
                show("Estop", true);
            }
            break;
        case 4: select_auto(automode::mem); break;
        case 5: select_auto(automode::mdi); break;
        case 6: select_auto(automode::tape); break;
        case 7: select_manual(manualmode::handle); break;
        case 8: select_manual(manualmode::jog); break;
        case 9: select_manual(manualmode::rpd); break;
        case 10: select_manual(manualmode::zrn); break;
        case 11: select_group(group::edit); break;
        case 12: select_group(group::setup); break;
        default: break;
        }
    }

    workload::observation observe() const { return workload::observe(active(), p_.error, p_.display); }

private:
    enum class top : std::uint8_t { off, estop, on };
    enum class group : std::uint8_t { automatic, manual, edit, setup };
    enum class automode : std::uint8_t { mem, mdi, tape };
    enum class manualmode : std::uint8_t { handle, jog, rpd, zrn };

    static constexpr std::string_view group_name[] = {"Auto", "Manual", "Edit", "Setup"};
    static constexpr std::string_view auto_name[] = {"Mem", "Mdi", "Tape"};
    static constexpr std::string_view manual_name[] = {"Handle", "Jog", "Rpd", "Zrn"};

    void show(std::string_view s, bool entered) { p_.display.show(s, entered); }

    // Deep history: group_, auto_ and manual_ keep their values while On is inactive.
    void enter_on() {
        top_ = top::on;
        show("On", true);
        show(group_name[static_cast<int>(group_)], true);
        if (group_ == group::automatic)
            show(auto_name[static_cast<int>(auto_)], true);
        else if (group_ == group::manual)
            show(manual_name[static_cast<int>(manual_)], true);
    }
    void exit_group() {
        if (group_ == group::automatic)
            show(auto_name[static_cast<int>(auto_)], false);
        else if (group_ == group::manual)
            show(manual_name[static_cast<int>(manual_)], false);
        show(group_name[static_cast<int>(group_)], false);
    }
    void exit_on() {
        exit_group();
        show("On", false);
    }

    // A mode button of Auto: within Auto it changes the mode only; from another group it
    // leaves that group and enters Auto in the mode named.
    void select_auto(automode m) {
        if (top_ != top::on) return;
        if (group_ == group::automatic) {
            if (auto_ == m) return;
            show(auto_name[static_cast<int>(auto_)], false);
        } else {
            exit_group();
            group_ = group::automatic;
            show("Auto", true);
        }
        auto_ = m;
        show(auto_name[static_cast<int>(m)], true);
    }
    void select_manual(manualmode m) {
        if (top_ != top::on) return;
        if (group_ == group::manual) {
            if (manual_ == m) return;
            show(manual_name[static_cast<int>(manual_)], false);
        } else {
            exit_group();
            group_ = group::manual;
            show("Manual", true);
        }
        manual_ = m;
        show(manual_name[static_cast<int>(m)], true);
    }
    // EDIT_P and SETUP_P, from the other groups.
    void select_group(group g) {
        if (top_ != top::on || group_ == g) return;
        exit_group();
        group_ = g;
        show(group_name[static_cast<int>(g)], true);
    }

    leaf active() const {
        switch (top_) {
        case top::off: return leaf::Off;
        case top::estop: return leaf::Estop;
        case top::on: break;
        }
        switch (group_) {
        case group::automatic: return static_cast<leaf>(static_cast<int>(leaf::Mem) + static_cast<int>(auto_));
        case group::manual: return static_cast<leaf>(static_cast<int>(leaf::Handle) + static_cast<int>(manual_));
        case group::edit: return leaf::Edit;
        case group::setup: return leaf::Setup;
        }
        return leaf::Off;
    }

    panel p_;
    top top_ = top::off;
    group group_ = group::automatic;
    automode auto_ = automode::mem;
    manualmode manual_ = manualmode::handle;
};

}  // namespace

BENCH_IMPL(mcs_bench::workload, "hand_written", supervisor);
