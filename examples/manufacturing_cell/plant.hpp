#pragma once
// A plant model of the manufacturing cell of the Basic Statechart paper ([BSC] in
// docs/references.md, Fig. 4), to run the controller of controller.hpp in closed loop. It is
// plain C++, not a chart: between two execution cycles it reads the actuators the controller has
// published and moves time on by one scan period, then presents its sensors for the next cycle.
// Everything is deterministic: arrivals are a list of times, fixed or drawn from a seeded
// generator.
//
//   input buffer   pieces arrive at given times and queue; IN: the queue is not empty
//   belt           when the motor starts, it takes the first piece of the buffer; the piece
//                  reaches P1 after the motor has run for `belt_travel`
//   rotary table   four positions P1..P4; the cylinder arm advances while the valve is on and
//                  turns the table by 90 degrees on a full advance (`arm_advance`): the pieces
//                  move P1 -> P2 -> P3 -> P4 (and P4 -> P1); S1 is true at the full advance.
//                  While the table turns, the pieces are between positions and P1..P4 read
//                  false. With the valve off, the arm returns in `arm_return` (the table stays).
//   drill, test    a piece at P2 (P3) is drilled (tested) when the drill (test) has run for at
//                  least `drill_work` (`test_work`) and stops
//   robot          takes the piece at P4 and stores it when it stops after running for at
//                  least `robot_work`
//
// Physical faults (a piece delivered onto an occupied P1, the valve switched on before the arm
// has returned, a turn that would carry a piece from P4 back to P1, the valve switched off
// before the full advance) are recorded in `faults()`; the controller must never cause one.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include "controller.hpp"

namespace cell {

/// The plant's own times. Paper silent: the paper gives none.
struct plant_timing {
    bsc::duration belt_travel = 1500ms;  ///< motor-on time to carry a piece from the buffer to P1
    bsc::duration arm_advance = 1s;      ///< valve-on time for a full advance (a 90 degree turn)
    bsc::duration arm_return = 500ms;    ///< time for the arm to return with the valve off
    bsc::duration drill_work = 2500ms;   ///< drill-on time that drills a piece (T1 gives 3 s)
    bsc::duration test_work = 1500ms;    ///< test-on time that tests a piece (T2 gives 2 s)
    bsc::duration robot_work = 2s;       ///< robot-on time that stores a piece (T3 gives 2.5 s)
};

/// The cell as it was when the table turned.
struct turn_record {
    bsc::duration when{};
    std::array<int, 4> before{};  ///< the pieces at P1..P4 just before the turn (plant::none: empty)
    int on_belt = -1;             ///< the piece on the belt then, or plant::none
};

/// What happened to one piece.
struct piece {
    int id = 0;
    bsc::duration arrived{};    ///< when it entered the input buffer
    int drilled = 0;            ///< drilling operations it received
    int tested = 0;             ///< tests it received
    bool stored = false;        ///< the robot has stored it
    bsc::duration stored_at{};  ///< when
};

class plant {
public:
    static constexpr int none = -1;  ///< no piece

    explicit plant(std::vector<bsc::duration> arrivals, plant_timing timing = {})
        : timing_(timing), arrivals_(std::move(arrivals)) {}

    /// Pieces whose arrival time is at or before `now` enter the input buffer.
    void arrive(bsc::duration now) {
        for (; next_arrival_ < arrivals_.size() && arrivals_[next_arrival_] <= now; ++next_arrival_) {
            int const id = static_cast<int>(pieces_.size());
            pieces_.push_back(piece{id, arrivals_[next_arrival_]});
            buffer_.push_back(id);
        }
    }

    /// What the sensors read now.
    sensors sense() const {
        sensors s;
        s.IN = !buffer_.empty();
        s.P1 = occupied(0);
        s.P2 = occupied(1);
        s.P3 = occupied(2);
        s.P4 = occupied(3);
        s.S1 = arm_ == timing_.arm_advance;
        return s;
    }

    /// Moves time on by `dt` from `now` with the actuators as the controller published them.
    void advance(actuators const& out, bsc::duration dt, bsc::duration now) {
        bsc::duration const end = now + dt;
        // Belt: starting the motor takes the first piece of the buffer.
        if (out.belt && !last_.belt && on_belt_ == none && !buffer_.empty()) {
            on_belt_ = buffer_.front();
            buffer_.pop_front();
            belt_progress_ = {};
        }
        if (out.belt && on_belt_ != none) {
            belt_progress_ += dt;
            if (belt_progress_ >= timing_.belt_travel) {
                if (at_[0] != none || in_transit_) {
                    fault("piece " + std::to_string(on_belt_) + " delivered onto an occupied or moving P1", end);
                } else {
                    at_[0] = on_belt_;
                    on_belt_ = none;
                }
            }
        }
        // Drill, test and robot act on the piece at their position when they stop.
        work(out.drill, last_.drill, dt, drill_on_, timing_.drill_work, 1, [](piece& p) { ++p.drilled; });
        work(out.test, last_.test, dt, test_on_, timing_.test_work, 2, [](piece& p) { ++p.tested; });
        work(out.robot, last_.robot, dt, robot_on_, timing_.robot_work, 3, [&](piece& p) {
            p.stored = true;
            p.stored_at = end;
            at_[3] = none;
        });
        // The cylinder and the table.
        if (out.valve) {
            if (!last_.valve && arm_ != bsc::duration::zero())
                fault("valve switched on before the arm had returned", end);
            if (!turned_) {
                in_transit_ = true;
                arm_ = std::min(arm_ + dt, timing_.arm_advance);
                if (arm_ == timing_.arm_advance) turn(end);
            }
        } else if (arm_ > bsc::duration::zero()) {
            if (!turned_) {
                fault("valve switched off before the full advance", end);
                in_transit_ = false;
            }
            bsc::duration const back{dt.count() * timing_.arm_advance.count() / timing_.arm_return.count()};
            arm_ = std::max(arm_ - back, bsc::duration::zero());
            if (arm_ == bsc::duration::zero()) turned_ = false;
        }
        last_ = out;
    }

    // ---- what the plant holds, for traces and checks -------------------------------------
    std::vector<piece> const& pieces() const { return pieces_; }
    /// The piece at position P1..P4 (index 0..3), or `none`.
    int at(std::size_t position) const { return at_[position]; }
    int on_belt() const { return on_belt_; }
    std::size_t buffered() const { return buffer_.size(); }
    /// Pieces scheduled to arrive, including those still to come.
    std::size_t scheduled() const { return arrivals_.size(); }
    bool all_arrived() const { return next_arrival_ == arrivals_.size(); }
    std::size_t stored() const {
        std::size_t n = 0;
        for (piece const& p : pieces_) n += p.stored ? 1 : 0;
        return n;
    }
    /// Completed 90 degree turns of the table.
    int turns() const { return turns_; }
    /// Every turn, in order.
    std::vector<turn_record> const& turn_log() const { return turn_log_; }
    bool turning() const { return in_transit_; }
    std::vector<std::string> const& faults() const { return faults_; }
    plant_timing const& timing() const { return timing_; }

private:
    bool occupied(std::size_t position) const { return !in_transit_ && at_[position] != none; }

    // A device acts on the piece at its position when it stops, if it ran long enough.
    template <class F>
    void work(bool on, bool was_on, bsc::duration dt, bsc::duration& on_time, bsc::duration needed,
              std::size_t position, F&& done) {
        if (on) {
            on_time += dt;
            return;
        }
        if (was_on && on_time >= needed && !in_transit_ && at_[position] != none)
            done(pieces_[static_cast<std::size_t>(at_[position])]);
        on_time = {};
    }

    void turn(bsc::duration when) {
        if (at_[3] != none) fault("turn with piece " + std::to_string(at_[3]) + " still at P4", when);
        turn_log_.push_back({when, at_, on_belt_});
        at_ = {at_[3], at_[0], at_[1], at_[2]};
        turned_ = true;
        in_transit_ = false;
        ++turns_;
    }

    void fault(std::string what, bsc::duration when) {
        faults_.push_back(std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(when).count()) +
                          " ms: " + std::move(what));
    }

    plant_timing timing_;
    std::vector<bsc::duration> arrivals_;
    std::size_t next_arrival_ = 0;
    std::vector<piece> pieces_;
    std::deque<int> buffer_;
    int on_belt_ = none;
    bsc::duration belt_progress_{};
    std::array<int, 4> at_{none, none, none, none};
    bsc::duration arm_{};      // advance of the arm, 0 (returned) .. arm_advance (S1)
    bool turned_ = false;      // this stroke has turned the table
    bool in_transit_ = false;  // the table is between positions
    int turns_ = 0;
    std::vector<turn_record> turn_log_;
    bsc::duration drill_on_{}, test_on_{}, robot_on_{};  // how long each device has been on
    actuators last_{};
    std::vector<std::string> faults_;
};

// ---- Arrival patterns: the times at which pieces enter the input buffer -------------------------

namespace arrivals {

/// No piece at all.
inline std::vector<bsc::duration> none() { return {}; }

/// `count` pieces, the first at `first`, then one every `gap`.
inline std::vector<bsc::duration> steady(int count, bsc::duration first, bsc::duration gap) {
    std::vector<bsc::duration> times;
    for (int i = 0; i < count; ++i) times.push_back(first + i * gap);
    return times;
}

/// `bursts` groups of `size` pieces arriving together, one group every `gap`.
inline std::vector<bsc::duration> bursts(int bursts, int size, bsc::duration first, bsc::duration gap) {
    std::vector<bsc::duration> times;
    for (int b = 0; b < bursts; ++b)
        for (int i = 0; i < size; ++i) times.push_back(first + b * gap);
    return times;
}

/// `count` pieces with gaps drawn uniformly (to the millisecond) from [min_gap, max_gap] by a
/// generator seeded with `seed`. The same seed gives the same times with any compiler: only
/// std::mt19937's raw output, which the standard fixes, is used.
inline std::vector<bsc::duration> random(int count, std::uint32_t seed, bsc::duration min_gap, bsc::duration max_gap) {
    std::mt19937 gen{seed};
    auto const lo = std::chrono::duration_cast<std::chrono::milliseconds>(min_gap).count();
    auto const span = std::chrono::duration_cast<std::chrono::milliseconds>(max_gap).count() - lo + 1;
    std::vector<bsc::duration> times;
    bsc::duration t{};
    for (int i = 0; i < count; ++i) {
        times.push_back(t);
        t += std::chrono::milliseconds{lo + static_cast<long long>(gen() % static_cast<std::uint32_t>(span))};
    }
    return times;
}

}  // namespace arrivals

}  // namespace cell
