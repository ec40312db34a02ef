#pragma once
// The controller of the manufacturing cell (examples/manufacturing_cell/controller.hpp), a scan
// chart driven by step(now), as a bsc machine and as a PLC programmer writes the scan by hand
// (the hand-written loop of bench/manufacturing_cell_bench.cpp, standing alone), both run on
// the host and the Cortex-M4 against a small plant model of their own.
//
// The examples' plant (plant.hpp) keeps its pieces in standard containers; the plant here keeps
// them in a few flags, so that the target image needs no heap: ten pieces arrive at fixed times;
// the belt carries one to P1 in 1.5 s of running; the cylinder turns the table by a quarter in
// 1 s of valve on (S1 at the full advance; the positions read empty while it turns) and returns
// in 0.5 s; the robot stores the piece at P4 after 2 s of running. The scan period is 100 ms.
//
//   PROGRAM      the closed loop until every piece is stored, one line per cycle: the
//                configuration (belt 0-2, drill, test, robot 0-1, table 0-2), the outputs
//                (belt, drill, test, robot, valve), E1..E4 and the sensors (IN, P1..P4, S1)
//   PROGRAM N    the first 512 cycles of the closed loop recorded with a copy of the controller,
//                then N of them (N <= 512) replayed on the controller: the instructions per
//                cycle are those of the controller alone, as bench/manufacturing_cell_bench.cpp
//                measures them on the host

#include <chrono>
#include <cstdint>

#include "../../examples/manufacturing_cell/controller.hpp"
#include "driver.hpp"

namespace scan {

using namespace std::chrono_literals;

constexpr bsc::duration period = 100ms;

/// What the trace shows of a controller after a cycle.
struct observation {
    std::uint8_t belt = 0, drill = 0, test = 0, robot = 0, table = 0;
    cell::actuators out;
    bool E1 = false, E2 = false, E3 = false, E4 = false;
};

inline std::uint32_t pack(cell::actuators const& a) {
    return std::uint32_t{a.belt} | std::uint32_t{a.drill} << 1 | std::uint32_t{a.test} << 2 |
           std::uint32_t{a.robot} << 3 | std::uint32_t{a.valve} << 4;
}

/// The cell's mechanics, in whole milliseconds.
class plant {
public:
    static constexpr int pieces = 10;

    cell::sensors sense() const {
        bool const turning = arm_ > 0 && !turned_;
        return {buffer_ > 0,        at_[0] && !turning, at_[1] && !turning,
                at_[2] && !turning, at_[3] && !turning, arm_ >= arm_advance};
    }

    /// One scan period with the actuators as the controller has published them.
    void advance(cell::actuators const& a) {
        now_ += step;
        for (; next_ < pieces && arrivals[next_] <= now_; ++next_) ++buffer_;
        if (a.belt) {
            if (!carrying_ && buffer_ > 0) {
                --buffer_;
                carrying_ = true;
                belt_run_ = 0;
            }
            if (carrying_ && (belt_run_ += step) >= belt_travel) {
                faults_ += at_[0];  // delivered onto a piece
                at_[0] = true;
                carrying_ = false;
            }
        }
        if (a.valve) {
            faults_ += turned_ && arm_ < arm_advance;  // switched on before the arm returned
            if (arm_ < arm_advance) arm_ += step;
            if (arm_ >= arm_advance && !turned_) {
                faults_ += at_[3];  // would carry a piece from P4 back to P1
                at_[3] = at_[2];
                at_[2] = at_[1];
                at_[1] = at_[0];
                at_[0] = false;
                turned_ = true;
            }
        } else if (arm_ > 0) {
            arm_ = arm_ > arm_speed_back ? arm_ - arm_speed_back : 0;
            if (arm_ == 0) turned_ = false;
        }
        robot_run_ = a.robot ? robot_run_ + step : 0;
        if (robot_run_ >= robot_work && at_[3]) {
            at_[3] = false;
            ++stored_;
        }
    }

    bool done() const { return stored_ == pieces; }
    std::uint32_t stored() const { return stored_; }
    std::uint32_t faults() const { return faults_; }

private:
    static constexpr std::uint32_t step = 100;
    static constexpr std::uint32_t belt_travel = 1500;
    static constexpr std::uint32_t arm_advance = 1000;
    static constexpr std::uint32_t arm_speed_back = arm_advance * step / 500;
    static constexpr std::uint32_t robot_work = 2000;
    static constexpr std::uint32_t arrivals[pieces] = {0, 300, 2000, 4500, 5000, 9000, 16000, 16500, 23000, 30000};

    std::uint32_t now_ = 0, belt_run_ = 0, arm_ = 0, robot_run_ = 0, stored_ = 0, faults_ = 0;
    int next_ = 0, buffer_ = 0;
    bool carrying_ = false, turned_ = false;
    bool at_[4] = {};  // a piece at P1..P4
};

inline constexpr std::uint32_t trace_cycles = 2000;  // a bound: the run ends when every piece is stored
inline constexpr std::uint32_t recording_length = 512;
inline cell::sensors recording[recording_length];

inline void print(cm::line& out, std::uint32_t cycle, observation const& o, cell::sensors const& s) {
    auto const bit = [](bool b) { return b ? '1' : '0'; };
    out << cycle << ' ' << static_cast<char>('0' + o.belt) << static_cast<char>('0' + o.drill)
        << static_cast<char>('0' + o.test) << static_cast<char>('0' + o.robot) << static_cast<char>('0' + o.table)
        << ' ' << bit(o.out.belt) << bit(o.out.drill) << bit(o.out.test) << bit(o.out.robot) << bit(o.out.valve) << ' '
        << bit(o.E1) << bit(o.E2) << bit(o.E3) << bit(o.E4) << ' ' << bit(s.IN) << bit(s.P1) << bit(s.P2) << bit(s.P3)
        << bit(s.P4) << bit(s.S1);
}

/// Runs the controller `subject` of Adapter (scan: one cycle with the sensors latched at the
/// given time; outputs; observe).
template <class Adapter>
int run(int argc, char** argv) {
    auto& subject = Adapter::subject;
    std::uint32_t n = 0;
    cm::line out;
    if (!cm::events_to_count(argc, argv, n)) {
        plant p;
        std::uint32_t cycle = 0;
        for (; cycle < trace_cycles && !p.done(); ++cycle) {
            cell::sensors const s = p.sense();
            Adapter::scan(subject, s, cycle * period);
            p.advance(Adapter::outputs(subject));
            print(out, cycle, Adapter::observe(subject), s);
            out.end();
        }
        out << "cycles " << cycle << " stored " << p.stored() << " faults " << p.faults();
        out.end();
        return p.done() && p.faults() == 0 ? 0 : 1;
    }
    if (n > recording_length) {
        out << "at most " << recording_length << " cycles";
        out.end();
        return 2;
    }
    {
        plant p;
        auto probe = subject;  // a copy, in the initial configuration
        for (std::uint32_t cycle = 0; cycle < recording_length; ++cycle) {
            recording[cycle] = p.sense();
            Adapter::scan(probe, recording[cycle], cycle * period);
            p.advance(Adapter::outputs(probe));
        }
    }
    std::uint32_t sum = 0;
    for (std::uint32_t cycle = 0; cycle < n; ++cycle) {
        Adapter::scan(subject, recording[cycle], cycle * period);
        sum += pack(Adapter::outputs(subject));
    }
    out << "cycles " << n << " checksum " << sum;
    out.end();
    return 0;
}

// ---- bsc --------------------------------------------------------------------------------------

/// The driver's adapter for a cell::machine, the global `Subject`.
template <auto& Subject>
struct bsc_adapter {
    static constexpr auto& subject = Subject;
    using controller = std::remove_reference_t<decltype(Subject)>;

    // Out of line, so that the image holds the cycle once for its two callers.
    [[gnu::noinline]] static void scan(controller& m, cell::sensors const& s, bsc::duration now) {
        cell::write_inputs(m.context(), s);
        m.step(now);
    }
    static cell::actuators outputs(controller const& m) { return cell::read_outputs(m.context()); }
    static observation observe(controller const& m) {
        auto const& d = m.context();
        return {std::uint8_t(m.template is<cell::BeltOn>()     ? 1
                             : m.template is<cell::BeltDone>() ? 2
                                                               : 0),
                std::uint8_t(m.template is<cell::DrillOn>()),
                std::uint8_t(m.template is<cell::TestOn>()),
                std::uint8_t(m.template is<cell::RobotOn>()),
                std::uint8_t(m.template is<cell::CylinderAdvancing>()   ? 1
                             : m.template is<cell::CylinderReturning>() ? 2
                                                                        : 0),
                cell::read_outputs(d),
                d.E1,
                d.E2,
                d.E3,
                d.E4};
    }
};

// ---- By hand ----------------------------------------------------------------------------------

/// A BSC timer as docs/semantics.md states it: started during cycle k, timing from cycle k+1,
/// tm at the first cycle at least `limit` after that.
struct timer {
    bsc::duration limit{};
    bsc::duration started{};
    std::uint8_t phase = 0;  // 0 idle, 1 started (timing from the next cycle), 2 timing
    bool tm = false;

    void start() {
        phase = 1;
        tm = false;
    }
    void reset() {
        phase = 0;
        tm = false;
    }
    void update(bsc::duration now) {
        if (phase == 1) {
            phase = 2;
            started = now;
        }
        if (phase == 2 && now - started >= limit) tm = true;
    }
};

/// The paper's Fig. 6 as a scan: an input image latched at the start, the components in the
/// paper's order, each taking at most one transition (the guards g1..g15 of Table I), an output
/// image published at the end.
struct hand_written {
    cell::sensors pending{};  // written by the plant between scans
    cell::sensors in{};
    cell::actuators next{};
    cell::actuators out{};
    bool E1 = false, E2 = false, E3 = false, E4 = false;
    timer T1{cell::drill_time}, T2{cell::test_time}, T3{cell::robot_time};
    std::uint8_t belt = 0;  // 0 off, 1 on, 2 done
    bool drill = false, test = false, robot = false;
    std::uint8_t table = 0;  // 0 returned, 1 advancing, 2 returning

    void scan(bsc::duration now) {
        T1.update(now);
        T2.update(now);
        T3.update(now);
        in = pending;

        if (belt == 0) {
            if (!in.P1 && !E1 && in.IN) {  // g1
                next.belt = true;
                belt = 1;
            } else if (!in.P1 && !E1 && !in.IN) {  // g3
                E1 = true;
                belt = 2;
            }
        } else if (belt == 1) {
            if (in.P1) {  // g2
                next.belt = false;
                E1 = true;
                belt = 2;
            }
        } else if (!E1) {  // a new phase
            belt = 0;
        }

        if (!drill) {
            if (in.P2 && !E2) {  // g4
                next.drill = true;
                T1.start();
                drill = true;
            } else if (!in.P2 && !E2) {  // g6
                E2 = true;
            }
        } else if (T1.tm) {  // g5
            next.drill = false;
            T1.reset();
            E2 = true;
            drill = false;
        }

        if (!test) {
            if (in.P3 && !E3) {  // g7
                next.test = true;
                T2.start();
                test = true;
            } else if (!in.P3 && !E3) {  // g9
                E3 = true;
            }
        } else if (T2.tm) {  // g8
            next.test = false;
            T2.reset();
            E3 = true;
            test = false;
        }

        if (!robot) {
            if (in.P4 && !E4) {  // g10
                next.robot = true;
                T3.start();
                robot = true;
            } else if (!in.P4 && !E4) {  // g12
                E4 = true;
            }
        } else if (T3.tm) {  // g11
            next.robot = false;
            T3.reset();
            E4 = true;
            robot = false;
        }

        bool const ended = E1 && E2 && E3 && E4;
        if (table == 0) {
            if (ended && (in.P1 || in.P2 || in.P3)) {  // g13
                next.valve = true;
                table = 1;
            } else if (ended) {  // g15
                E1 = E2 = E3 = E4 = false;
            }
        } else if (table == 1) {
            if (in.S1) {  // g14
                next.valve = false;
                table = 2;
            }
        } else if (!in.S1) {  // the arm has left its end position: a new phase
            E1 = E2 = E3 = E4 = false;
            table = 0;
        }

        out = next;
    }
};

/// The floor the report measures the others from: the driver and a controller that only
/// copies two sensors to two outputs, which keeps the plant and the printing in the image.
struct floor {
    cell::sensors in{};
    cell::actuators out{};
};

/// The driver's adapter for the hand-written controller (or the floor), the global `Subject`.
template <auto& Subject>
struct hand_adapter {
    static constexpr auto& subject = Subject;
    using controller = std::remove_reference_t<decltype(Subject)>;

    [[gnu::noinline]] static void scan(controller& c, cell::sensors const& s, bsc::duration now) {
        if constexpr (requires { c.scan(now); }) {
            c.pending = s;
            c.scan(now);
        } else {
            c.out.belt = s.IN;
            c.out.valve = s.P1;
        }
    }
    static cell::actuators outputs(controller const& c) { return c.out; }
    static observation observe(controller const& c) {
        if constexpr (requires { c.belt; }) {
            return {c.belt, c.drill, c.test, c.robot, c.table, c.out, c.E1, c.E2, c.E3, c.E4};
        } else {
            return {0, 0, 0, 0, 0, c.out, false, false, false, false};
        }
    }
};

}  // namespace scan
