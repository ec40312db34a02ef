#pragma once
// The paper's requirements on the manufacturing cell, checked on every execution cycle of a
// closed-loop run (controller.hpp with plant.hpp), and the closed loop itself.
//
// Requirements (the Basic Statechart paper [BSC], section IV; see docs/references.md):
//   constraint 1   each device works at most once between two table turns
//   constraint 2   no device starts without a piece at its position (the belt: without a piece
//                  in the input buffer and P1 free)
//   constraint 3   the table turns only with a piece at P1, P2 or P3
//   synchronisation  the table turns only when every device has finished: no device on, the
//                  piece at P2 drilled, the piece at P3 tested, P4 cleared by the robot, no piece
//                  left on the belt; and no device runs while the valve is on
//   timing         drill, test and robot stay on for exactly expected_on_cycles(Tn, period)
//   plant          no physical fault (plant::faults)
//   at the end     every piece that entered was drilled once, tested once and stored

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "controller.hpp"
#include "plant.hpp"

namespace cell {

/// The number of consecutive cycles after which a device's output is published on, for a timer
/// limit and a fixed scan period (docs/semantics.md, "Timers"). The device starts in cycle k:
/// its output is published on at the end of k and its timer starts timing at cycle k+1, at
/// t(k+1). The timer expires at the first cycle j with t(j) - t(k+1) >= limit, that is
/// j = k + 1 + ceil(limit / period), and that cycle's action switches the output off. The
/// output is therefore published on after cycles k, k+1, ..., j-1: 1 + ceil(limit / period).
constexpr int expected_on_cycles(bsc::duration limit, bsc::duration period) {
    return 1 + static_cast<int>((limit.count() + period.count() - 1) / period.count());
}

/// The devices that the table synchronises.
enum class device : std::size_t { belt, drill, test, robot };
inline constexpr std::array<char const*, 4> device_names{"belt", "drill", "test", "robot"};

class monitor {
public:
    explicit monitor(bsc::duration period)
        : expected_{0, expected_on_cycles(drill_time, period), expected_on_cycles(test_time, period),
                    expected_on_cycles(robot_time, period)} {}

    /// Checks one cycle: `latched` are the sensor values the controller latched at its start,
    /// `out` the actuators it published at its end, `p` the plant once it has reacted to them.
    void check(bsc::duration now, sensors const& latched, actuators const& out, plant const& p) {
        now_ = now;
        std::array<bool, 4> const on{out.belt, out.drill, out.test, out.robot};
        std::array<bool, 4> const was{last_.belt, last_.drill, last_.test, last_.robot};
        std::array<bool, 4> const piece_there{latched.IN && !latched.P1, latched.P2, latched.P3, latched.P4};
        char const* const position[4] = {"a piece in the input buffer and P1 free", "a piece at P2", "a piece at P3",
                                         "a piece at P4"};
        for (std::size_t d = 0; d < 4; ++d) {
            auto& t = track_[d];
            if (on[d] && !was[d]) {  // the device starts
                ++t.starts;
                if (!piece_there[d])
                    violation(std::string("constraint 2: ") + device_names[d] + " started without " + position[d]);
                if (++t.starts_since_turn > 1)
                    violation(std::string("constraint 1: ") + device_names[d] + " started twice between two turns");
            }
            if (on[d]) {
                ++t.run;
            } else if (was[d]) {  // the device stops
                t.runs.push_back(t.run);
                if (d != 0 && t.run != expected_[d])
                    violation(std::string("timing: ") + device_names[d] + " was on for " + std::to_string(t.run) +
                              " cycles, expected " + std::to_string(expected_[d]));
                t.run = 0;
            }
        }
        if (out.valve && (out.belt || out.drill || out.test || out.robot))
            violation("synchronisation: a device is on while the valve is on");
        if (out.valve && !last_.valve) {  // the table starts to turn
            ++turns_started_;
            if (!(latched.P1 || latched.P2 || latched.P3))
                violation("constraint 3: the table turns without a piece at P1, P2 or P3");
            for (auto& t : track_) t.starts_since_turn = 0;
        }
        // Every device has finished when the table actually turns (at the full advance).
        for (; turns_seen_ < p.turn_log().size(); ++turns_seen_) {
            turn_record const& turn = p.turn_log()[turns_seen_];
            auto const piece_at = [&](std::size_t i) { return p.pieces()[static_cast<std::size_t>(turn.before[i])]; };
            if (turn.before[1] != plant::none && piece_at(1).drilled == 0)
                violation("synchronisation: the table turned before the piece at P2 was drilled");
            if (turn.before[2] != plant::none && piece_at(2).tested == 0)
                violation("synchronisation: the table turned before the piece at P3 was tested");
            if (turn.before[3] != plant::none)
                violation("synchronisation: the table turned before the robot had cleared P4");
            if (turn.on_belt != plant::none) violation("synchronisation: the table turned with a piece on the belt");
        }
        for (; faults_seen_ < p.faults().size(); ++faults_seen_) violation("plant fault: " + p.faults()[faults_seen_]);
        last_ = out;
    }

    /// Checks the end of a run: every piece that entered was drilled once, tested once, stored.
    void check_end(plant const& p) {
        for (piece const& x : p.pieces()) {
            std::string const name = "piece " + std::to_string(x.id);
            if (!x.stored) violation(name + " was not stored");
            if (x.drilled != 1) violation(name + " was drilled " + std::to_string(x.drilled) + " times");
            if (x.tested != 1) violation(name + " was tested " + std::to_string(x.tested) + " times");
        }
    }

    std::vector<std::string> const& violations() const { return violations_; }
    bool ok() const { return violations_.empty(); }
    /// How many times the device started.
    int starts(device d) const { return track_[static_cast<std::size_t>(d)].starts; }
    /// The length, in cycles, of each completed run of the device, in order.
    std::vector<int> const& runs(device d) const { return track_[static_cast<std::size_t>(d)].runs; }
    /// The expected length of a run of drill, test or robot (0 for the belt: no timer).
    int expected_run(device d) const { return expected_[static_cast<std::size_t>(d)]; }
    int turns_started() const { return turns_started_; }

private:
    void violation(std::string what) {
        violations_.push_back(std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(now_).count()) +
                              " ms: " + std::move(what));
    }

    struct track {
        int starts = 0;
        int starts_since_turn = 0;
        int run = 0;  // cycles on so far in the current run
        std::vector<int> runs;
    };
    std::array<int, 4> expected_;
    std::array<track, 4> track_{};
    actuators last_{};
    int turns_started_ = 0;
    std::size_t faults_seen_ = 0;
    std::size_t turns_seen_ = 0;
    bsc::duration now_{};
    std::vector<std::string> violations_;
};

/// One execution cycle of a closed-loop run.
struct cycle_record {
    long cycle = 0;
    bsc::duration time{};
    sensors latched;  ///< what the controller latched at the start of the cycle
    actuators out;    ///< what it published at the end
    bsc::step_report report;
};

/// The controller (a cell::machine, or a machine over cell::data with an observer) and the
/// plant in closed loop at a fixed scan period, checked by a monitor on every cycle. Cycle k
/// runs at time k * period: arrivals up to then enter the buffer, the plant's sensors are
/// written to the input channels, the machine steps, and the plant moves on by one period with
/// the published outputs.
template <class Machine>
class closed_loop {
public:
    closed_loop(Machine& m, std::vector<bsc::duration> arrivals, bsc::duration period, plant_timing timing = {})
        : m_(m), plant_(std::move(arrivals), timing), monitor_(period), period_(period) {}

    cycle_record cycle() {
        cycle_record r;
        r.cycle = cycle_;
        r.time = cycle_ * period_;
        plant_.arrive(r.time);
        r.latched = plant_.sense();
        write_inputs(m_.context(), r.latched);
        r.report = m_.step(r.time);
        r.out = read_outputs(m_.context());
        plant_.advance(r.out, period_, r.time);
        monitor_.check(r.time, r.latched, r.out, plant_);
        ++cycle_;
        return r;
    }

    /// Every scheduled piece has arrived and been stored.
    bool done() const { return plant_.all_arrived() && plant_.stored() == plant_.scheduled(); }

    /// Runs until done() (then checks the end of the run) or until `max_cycles` have run;
    /// returns done().
    bool run(long max_cycles) {
        while (!done() && cycle_ < max_cycles) cycle();
        if (done()) monitor_.check_end(plant_);
        return done();
    }

    Machine& machine() { return m_; }
    cell::plant const& plant() const { return plant_; }
    cell::monitor const& monitor() const { return monitor_; }
    cell::monitor& monitor() { return monitor_; }
    long cycles() const { return cycle_; }
    bsc::duration period() const { return period_; }

private:
    Machine& m_;
    cell::plant plant_;
    cell::monitor monitor_;
    bsc::duration period_;
    long cycle_ = 0;
};

}  // namespace cell
