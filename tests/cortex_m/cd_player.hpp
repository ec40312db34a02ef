#pragma once
// The CD player of Boost.SML's benchmark (bench/sml_simple/sml_simple_workload.hpp describes
// it): five states, Empty (initial), Open, Stopped, Playing, Pause; six events; twelve
// transitions, each with an action that does nothing. bench/sml_simple's chart and hand-written
// switch, with the workload both run on the host and the Cortex-M4.

#include <cstdint>

#include <bsc/bsc.hpp>

#include "../../bench/sml_simple/cd_player_chart.hpp"
#include "../../bench/sml_simple/cd_player_switch.hpp"
#include "driver.hpp"

namespace cd {

using sml_simple_bench::state;
using namespace sml_simple_bench;  // the numbered states and events

struct workload {
    // Boost.SML's loop body, eleven events every one of which fires a transition, repeated.
    static void record(std::uint8_t (&sequence)[cm::sequence_length]) {
        static constexpr std::uint8_t loop[] = {open_close_e, open_close_e, cd_detected_e, play_e,
                                                pause_e,      end_pause_e,  pause_e,       stop_e,
                                                stop_e,       open_close_e, open_close_e};
        for (std::size_t i = 0; i < cm::sequence_length; ++i) sequence[i] = loop[i % sizeof loop];
    }
    static constexpr std::size_t trace_events = 110;
    static void print(cm::line& out, state s) {
        static constexpr char const* names[] = {"Empty", "Open", "Stopped", "Playing", "Pause"};
        out << names[s];
    }
    static std::uint32_t checksum(state s) { return s; }
};

// ---- bsc --------------------------------------------------------------------------------------

inline constexpr auto nothing = []() noexcept {};
inline constexpr auto chart = make_player(nothing);

/// The driver's adapter for a bsc machine of the chart, the global `subject`.
template <auto& subject>
struct bsc_adapter {
    static void on(std::uint8_t e) {
        switch (e) {
            case play_e: subject.dispatch(play{}); break;
            case end_pause_e: subject.dispatch(end_pause{}); break;
            case stop_e: subject.dispatch(stop{}); break;
            case pause_e: subject.dispatch(pause{}); break;
            case open_close_e: subject.dispatch(open_close{}); break;
            case cd_detected_e: subject.dispatch(cd_detected{}); break;
            default: break;
        }
    }
    static state observe() {
        if (subject.template is<Open>()) return open_s;
        if (subject.template is<Stopped>()) return stopped_s;
        if (subject.template is<Playing>()) return playing_s;
        if (subject.template is<Pause>()) return pause_s;
        return empty_s;
    }
};

// ---- By hand ----------------------------------------------------------------------------------

/// bench/sml_simple's switch, observed as the driver observes.
class hand_written {
public:
    void on(std::uint8_t e) { player_.on(e); }
    state observe() const { return player_.current(); }

private:
    cd_player_switch player_;
};

/// The floor the report measures the others from: the driver and a subject that keeps the last
/// event, so that the sequence and the printing stay in the image.
class floor {
public:
    void on(std::uint8_t e) { last_ = e; }
    state observe() const { return static_cast<state>(last_ & 3); }

private:
    std::uint8_t last_ = 0;
};

/// The driver's adapter for a hand-written player (or the floor), the global `subject`.
template <auto& subject>
struct hand_adapter {
    static void on(std::uint8_t e) { subject.on(e); }
    static state observe() { return subject.observe(); }
};

}  // namespace cd
