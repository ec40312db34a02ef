#pragma once
// Workload `mcs`: the Mode Control Supervisor of examples/mcs/mcs.hpp on a recorded random
// sequence of button presses (10,000 presses of the 13 buttons, uniform, seed 2024).
//
// Event indices follow mcs::buttons: 0 ON_P, 1 OFF_P, 2 ESTOP_P, 3 RESET_P, 4 MEM_P, 5 MDI_P,
// 6 TAPE_P, 7 HND_P, 8 JOG_P, 9 RPD_P, 10 ZRN_P, 11 EDIT_P, 12 SETUP_P.
//
// Every implementation does the chart's work: Show on every entry and exit (a line on a
// 16-line display), Set_Error0/Set_Error1, the guard cond, and On's deep history. The
// observation after each event is the active leaf, the error flag and the whole display.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "../harness.hpp"
#include "mcs_display.hpp"

namespace mcs_bench {

inline constexpr std::size_t event_count = 13;

enum class leaf : std::uint8_t { Off, Estop, Mem, Mdi, Tape, Handle, Jog, Rpd, Zrn, Edit, Setup };

struct panel {
    int error = 0;
    mcs_bench::display display;
};

struct workload {
    static constexpr char const* name = "mcs";

    struct observation {
        leaf active = leaf::Off;
        int error = 0;
        std::size_t lines = 0;
        std::array<display::line, display::capacity> shown{};
        bool operator==(observation const& o) const {
            return active == o.active && error == o.error && lines == o.lines && shown == o.shown;
        }
    };

    /// Observes any display with size() and operator[] returning {state, entered}.
    template <class Display>
    static observation observe(leaf active, int error, Display const& d) {
        observation o{active, error, d.size(), {}};
        for (std::size_t i = 0; i < d.size(); ++i) o.shown[i] = {d[i].state, d[i].entered};
        return o;
    }

    static std::string describe(observation const& o) {
        static constexpr char const* names[] = {"Off", "Estop", "Mem", "Mdi",  "Tape", "Handle",
                                                "Jog", "Rpd",   "Zrn", "Edit", "Setup"};
        std::string s = std::string("leaf ") + names[static_cast<int>(o.active)] + " error " + std::to_string(o.error) +
                        " display";
        for (std::size_t i = 0; i < o.lines; ++i) {
            s += o.shown[i].entered ? " +" : " -";
            s += o.shown[i].state;
        }
        return s;
    }

    static bench::sequence record() {
        bench::rng r{2024};
        bench::sequence s(10000);
        for (auto& e : s) e = static_cast<std::uint8_t>(r.below(event_count));
        return s;
    }
};

}  // namespace mcs_bench
