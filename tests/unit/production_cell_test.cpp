// The production cell example (examples/production_cell): closed-loop runs of the five
// controller actors with their plant models, checking the paper's requirements in every step —
// R1 (bricks kept apart), R2 (no collision), R3 (no plant model in Damage), liveness (every brick
// forged and deposited within a bound) and the efficiency question (a brick on each arm at once)
// — a broken press controller that drives the press into Damage, and an exploration of the cell
// with bsc::verify::system_model.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <bsc/verify.hpp>

#include "../../examples/production_cell/operation.hpp"

using namespace std::chrono_literals;

namespace {

// ---- The liveness bound -------------------------------------------------------------------------
// The robot and the press serve one brick at a time (the press holds one brick), so a brick waits
// for at most one robot cycle per brick ahead of it. A robot cycle is four jobs (pick at the
// table, load the press, unload it, deposit on the belt); each job turns the robot by at most
// three stops, moves the arm out and back, and grips or releases. The press moves four levels per
// brick (up one to forge, down two, up one), which the robot may have to wait for. Every
// transition of a controller on the brick's way (fewer than 60, handshakes included) costs at most
// one period of reaction. None of these durations is assumed to overlap another, so the sum is an
// upper bound; the runs below measure about half of it (7.4 s per brick when the cell is
// saturated, 11 to 13 s for a brick alone).
constexpr bsc::duration job(int arm_units, bsc::duration hold) {
    return 3 * pcell::robot_turn_time + 2 * arm_units * pcell::arm_step_time + hold;
}
constexpr bsc::duration reaction = 60 * pcell::period;
constexpr bsc::duration robot_cycle = job(pcell::arm1_reach_table, pcell::grip_time) +
                                      job(pcell::arm1_reach_press, pcell::release_time) +
                                      job(pcell::arm2_reach_press, pcell::grip_time) +
                                      job(pcell::arm2_reach_belt, pcell::release_time) + 4 * pcell::press_step_time +
                                      reaction;
/// A brick alone: to the end of the feed belt and off it, up and round on the table, one robot
/// cycle, and along the deposit belt until it falls off its end.
constexpr bsc::duration alone = (pcell::feed_slots + 1) * pcell::belt_slot_time +
                                (pcell::table_top + pcell::table_unload) * pcell::table_step_time + robot_cycle +
                                (pcell::deposit_slots + 1) * pcell::belt_slot_time;
/// The bound for a brick put on the feed belt while `ahead` bricks are still in the cell.
constexpr bsc::duration bound(std::size_t ahead) { return alone + static_cast<int>(ahead) * robot_cycle; }

static_assert(robot_cycle == 14400ms && alone == 17900ms);

// ---- A checked run ------------------------------------------------------------------------------

struct findings {
    std::string violation;   // the first requirement violated, with the step, or empty
    bool done = false;       // every brick left the cell
    bool both_arms = false;  // some step had a brick on arm1 and another on arm2
    bool all_off = false;    // some step had every controller in Off
    bsc::duration longest_stay{};
    bsc::duration worst_margin = bsc::duration::max();  // bound minus stay, the smallest over the bricks
};

double seconds(bsc::duration d) { return std::chrono::duration<double>(d).count(); }

/// Runs the cell with the given offers until every brick has left (or the last bound has
/// passed), checking R1, R2 and R3 after every step, then liveness for every brick. If `off_at`
/// is given, every controller (or only controller `only`, 0 to 4 in the order feed belt, table,
/// robot, press, deposit belt) is switched off at that time for `off_for`.
template <class System = pcell::cell>
findings run_checked(std::vector<bsc::duration> const& offers, bsc::duration off_at = bsc::duration::max(),
                     bsc::duration off_for = {}, int only = -1) {
    pcell::run<System> r{offers};
    findings f;
    // The operator may have to wait before putting the last brick on the belt, hence the 10 s.
    auto const give_up = offers.back() + bound(offers.size()) + off_for + 10s;
    auto fail = [&](std::string what) {
        auto const t = std::to_string(seconds(r.now() - pcell::period));
        f.violation = what + " at " + t + " s: " + pcell::picture(r.cell);
    };
    while (!r.done() && r.now() <= give_up) {
        if (r.now() == off_at || r.now() == off_at + off_for) {
            bool const on = r.now() != off_at;
            auto& a = r.cell.actors;
            if (only < 0) r.switch_all(on);
            if (only == 0) a.feed_belt.context().on.set(on);
            if (only == 1) a.table.context().on.set(on);
            if (only == 2) a.robot.context().on.set(on);
            if (only == 3) a.press.context().on.set(on);
            if (only == 4) a.deposit_belt.context().on.set(on);
        }
        r.step();
        // R1: at most one brick on the table, in the press, on each arm; none lost or doubled.
        std::array<int, 6> at{};
        pcell::for_each_brick(r.cell, [&](pcell::brick, pcell::place p) { ++at[static_cast<std::size_t>(p)]; });
        for (auto p : {pcell::place::table, pcell::place::arm1, pcell::place::press, pcell::place::arm2}) {
            auto const i = static_cast<std::size_t>(p);
            if (at[i] > 1) fail("R1: two bricks on the " + std::string(pcell::place_names[i]));
        }
        if (!r.bricks_conserved()) fail("R1: a brick lost or seen twice");
        // R2: no arm in the press area while the plate moves.
        if (pcell::press_moving(r.cell) && pcell::arm_in_press_area(r.cell, 1)) fail("R2: arm1 in the moving press");
        if (pcell::press_moving(r.cell) && pcell::arm_in_press_area(r.cell, 2)) fail("R2: arm2 in the moving press");
        // R3 (and every Damage): A[] not Env_X.Damage.
        if (!pcell::no_damage(r.cell)) fail("Damage in " + pcell::damaged(r.cell));
        if (!f.violation.empty()) return f;
        auto const& robot = r.cell.actors.env_robot.context();
        f.both_arms = f.both_arms || (robot.held1 && robot.held2);
        auto const& a = r.cell.actors;
        f.all_off = f.all_off || (a.feed_belt.template is<pcell::Off>() && a.table.template is<pcell::Off>() &&
                                  a.robot.template is<pcell::Off>() && a.press.template is<pcell::Off>() &&
                                  a.deposit_belt.template is<pcell::Off>());
    }
    f.done = r.done();
    // Liveness: every brick left the cell, forged, within its bound.
    if (r.cell.actors.env_deposit_belt.context().unforged != 0) f.violation = "a brick left unforged";
    for (std::size_t k = 0; k < r.offered(); ++k) {
        if (r.put_at(k) == r.never || r.left_at(k) == r.never) {
            f.violation = "brick " + std::to_string(k + 1) + " did not leave the cell";
            break;
        }
        std::size_t ahead = 0;
        for (std::size_t j = 0; j < k; ++j) ahead += r.left_at(j) > r.put_at(k) ? 1 : 0;
        auto const stay = r.left_at(k) - r.put_at(k);
        // A brick in the cell while the cell is switched off stays longer by that time.
        bool const paused = off_at != bsc::duration::max() && r.put_at(k) < off_at + off_for && r.left_at(k) > off_at;
        auto const limit = bound(ahead) + (paused ? off_for : bsc::duration{});
        f.longest_stay = std::max(f.longest_stay, stay);
        f.worst_margin = std::min(f.worst_margin, limit - stay);
        if (stay > limit)
            f.violation = "brick " + std::to_string(k + 1) + " stayed " + std::to_string(seconds(stay)) + " s";
    }
    return f;
}

void check(findings const& f) {
    INFO(f.violation);
    CHECK(f.violation.empty());
    CHECK(f.done);
    CHECK(f.worst_margin > 0s);
    MESSAGE("longest stay " << seconds(f.longest_stay) << " s, smallest margin to the bound " << seconds(f.worst_margin)
                            << " s");
}

/// `n` offers with gaps drawn from [0, max_gap) in steps of one period, from a fixed seed.
std::vector<bsc::duration> random_offers(std::uint32_t seed, int n, int max_gap_periods) {
    std::mt19937 gen(seed);  // the raw engine's output is the same on every platform
    std::vector<bsc::duration> offers;
    bsc::duration t{};
    for (int i = 0; i < n; ++i) {
        offers.push_back(t);
        t += static_cast<int>(gen() % static_cast<std::uint32_t>(max_gap_periods)) * pcell::period;
    }
    return offers;
}

}  // namespace

TEST_CASE("production cell: one brick is forged and deposited, R1-R3 hold in every step") {
    auto const f = run_checked({0s});
    check(f);
    CHECK_FALSE(f.both_arms);  // one brick cannot be on both arms
}

TEST_CASE("production cell: bricks back to back") {
    auto const f = run_checked(std::vector<bsc::duration>(8, 0s));
    check(f);
    // The efficiency question of section V: a brick moves with arm1 while another moves with arm2.
    CHECK(f.both_arms);
}

TEST_CASE("production cell: bursts of three bricks") {
    auto const f = run_checked({0s, 0s, 0s, 30s, 30s, 30s, 60s, 60s, 60s});
    check(f);
    CHECK(f.both_arms);
}

TEST_CASE("production cell: random gaps between bricks") {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        CAPTURE(seed);
        check(run_checked(random_offers(seed, 6, 120)));
    }
}

TEST_CASE("production cell: switched off and on again in the middle of the work, the cell resumes") {
    // All controllers go to Off (motors off) for 3 s while bricks are on every machine; On's
    // history brings each back where it was.
    for (bsc::duration off_at : {bsc::duration{5s}, bsc::duration{9s}, bsc::duration{10500ms}, bsc::duration{13s}}) {
        CAPTURE(seconds(off_at));
        auto const f = run_checked(std::vector<bsc::duration>(4, 0s), off_at, 3s);
        check(f);
        CHECK(f.all_off);
    }
}

TEST_CASE(
    "production cell: any one controller switched off and on again at any moment, the cell stays safe and resumes") {
    // Off stops a controller's motors and leaves its handshake signals as they are: a partner
    // waits for it rather than reading a lowered signal as the handshake's next phase. (A
    // distributed cell switches a controller off whenever it loses its supervisor.)
    std::array<std::string, 5> const names{"feed belt", "table", "robot", "press", "deposit belt"};
    int runs = 0;
    for (int which = 0; which < 5; ++which) {
        for (auto off_at = 0ms; off_at < 40s; off_at += 700ms) {
            CAPTURE(names[static_cast<std::size_t>(which)]);
            CAPTURE(seconds(off_at));
            auto const f = run_checked(std::vector<bsc::duration>(4, 0s), off_at, 1500ms, which);
            INFO(f.violation);
            REQUIRE(f.violation.empty());
            REQUIRE(f.done);
            ++runs;
        }
    }
    CHECK(runs == 5 * 58);
}

TEST_CASE("production cell: a press controller that does not wait for arm1 to retract breaks the press") {
    // The variant differs from press_chart in one guard: it starts forging when arm1 has let the
    // brick go, without waiting for arm1's extension sensor to read 0.
    using broken = pcell::system_of<pcell::basic_actors<false>>;
    pcell::run<broken> r{{0s}};
    bool arm1_inside = false;
    while (pcell::no_damage(r.cell) && r.now() < 30s) {
        r.step();
        arm1_inside = arm1_inside || pcell::arm_in_press_area(r.cell, 1);
    }
    CHECK(pcell::damaged(r.cell) == "press");
    CHECK(r.cell.actors.env_press.is<pcell::Damage>());
    CHECK(pcell::arm_in_press_area(r.cell, 1));  // the plate started with arm1 still inside
    CHECK(r.cell.actors.press.is<pcell::PsForge>());
    CHECK(r.cell.actors.env_press.halted());
    // The same run with the cell's own press controller ends well.
    check(run_checked({0s}));
}

TEST_CASE("production cell: exploration with bsc::verify::system_model, the arrival of bricks as the choice") {
    // Each step the operator may put the next brick on the feed belt (choice 1), if the start of
    // the belt is free and fewer than `bricks` were put, or not (choice 0). Every arrival pattern
    // is explored.
    constexpr std::uint8_t bricks = 2;
    auto step = [](pcell::cell& s, std::size_t choice, bsc::duration now) {
        auto& belt = s.actors.env_feed_belt.context();
        bool const put = choice == 1 && belt.fed < bricks && belt.start_free.get();
        belt.put.set(put ? pcell::brick{static_cast<std::uint8_t>(belt.fed + 1), false} : pcell::brick{});
        s.step(now);
    };
    auto describe = [](pcell::cell const& s) {
        return s.actors.robot.active_states().joined() + " | " + pcell::picture(s);
    };
    auto label = [](std::uint16_t c) { return std::string(c == 1 ? "put a brick" : "wait"); };
    pcell::cell initial{};
    initial.actors.feed_belt.context().on.set(true);
    initial.actors.table.context().on.set(true);
    initial.actors.robot.context().on.set(true);
    initial.actors.press.context().on.set(true);
    initial.actors.deposit_belt.context().on.set(true);
    bsc::verify::system_model model{initial, pcell::period, 2, step, describe, label};
    bsc::verify::explorer ex{model, bsc::verify::limits{300'000, std::size_t{1} << 30}};
    auto const& st = ex.run();
    MESSAGE("states " << st.states << ", transitions " << st.transitions << ", depth " << st.depth << ", " << st.seconds
                      << " s, " << st.key_bytes << " bytes per state");
    REQUIRE(st.complete);

    auto const r1 = bsc::verify::always(ex, "R1: one brick per place, none lost", [](pcell::cell const& s) {
        std::array<int, bricks + 1> seen{};
        bool ok = true;
        pcell::for_each_brick(s, [&](pcell::brick b, pcell::place) { ok = ok && b.id <= bricks && ++seen[b.id] == 1; });
        auto const& out = s.actors.env_deposit_belt.context();
        int in_cell = 0;
        for (int k = 1; k <= bricks; ++k) in_cell += seen[static_cast<std::size_t>(k)];
        return ok && in_cell + out.delivered == s.actors.env_feed_belt.context().fed;
    });
    auto const r2 = bsc::verify::always(
        ex, "R2: no arm in the press area while the plate moves", [](pcell::cell const& s) {
            return !(pcell::press_moving(s) && (pcell::arm_in_press_area(s, 1) || pcell::arm_in_press_area(s, 2)));
        });
    auto const r3 = bsc::verify::always(ex, "R3: not Env_FeedBelt/Table/Robot/Press/DepositBelt.Damage",
                                        [](pcell::cell const& s) { return pcell::no_damage(s); });
    CHECK_MESSAGE(r1.holds(), r1.to_string());
    CHECK_MESSAGE(r2.holds(), r2.to_string());
    CHECK_MESSAGE(r3.holds(), r3.to_string());
    // Liveness, without fairness: once a brick is in the cell, every path leads to its delivery,
    // forged.
    auto const live = bsc::verify::leads_to(
        ex, "a brick in the cell --> it leaves forged",
        [](pcell::cell const& s) {
            return s.actors.env_feed_belt.context().fed > s.actors.env_deposit_belt.context().delivered;
        },
        [](pcell::cell const& s) {
            auto const& out = s.actors.env_deposit_belt.context();
            return out.delivered == s.actors.env_feed_belt.context().fed && out.unforged == 0;
        });
    CHECK_MESSAGE(live.holds(), live.to_string());
    auto const efficient = bsc::verify::reachable(ex, "a brick on arm1 and another on arm2", [](pcell::cell const& s) {
        auto const& r = s.actors.env_robot.context();
        return r.held1 && r.held2;
    });
    CHECK(efficient.holds());
}

namespace {
// The closed model of the exploration above, for any system built from the cell's parts.
template <class System>
void put_or_wait(System& s, std::size_t choice, bsc::duration now, std::uint8_t bricks) {
    auto& belt = s.actors.env_feed_belt.context();
    bool const put = choice == 1 && belt.fed < bricks && belt.start_free.get();
    belt.put.set(put ? pcell::brick{static_cast<std::uint8_t>(belt.fed + 1), false} : pcell::brick{});
    s.step(now);
}
template <class System>
System switched_on() {
    System s{};
    s.actors.feed_belt.context().on.set(true);
    s.actors.table.context().on.set(true);
    s.actors.robot.context().on.set(true);
    s.actors.press.context().on.set(true);
    s.actors.deposit_belt.context().on.set(true);
    return s;
}
}  // namespace

TEST_CASE("production cell: exploring the broken press controller finds the damage, and the trace replays it") {
    using broken = pcell::system_of<pcell::basic_actors<false>>;
    auto step = [](broken& s, std::size_t choice, bsc::duration now) { put_or_wait(s, choice, now, 1); };
    auto describe = [](broken const& s) { return s.actors.press.active_states().joined(); };
    auto label = [](std::uint16_t c) { return std::string(c == 1 ? "put a brick" : "wait"); };
    bsc::verify::explorer ex{bsc::verify::system_model{switched_on<broken>(), pcell::period, 2, step, describe, label}};
    auto const r3 = bsc::verify::always(ex, "R3: no plant model in Damage", [](broken const& s) {
        return s.actors.env_press.template is<pcell::Damage>() == false;
    });
    REQUIRE(r3.fails());
    CHECK(r3.trace.size() > 2);
    // Replay the counterexample's choices on a fresh system: it must end in the press's Damage.
    broken s = switched_on<broken>();
    bsc::duration now{};
    for (std::size_t i = 1; i < r3.trace.size(); ++i) {
        now += pcell::period;
        put_or_wait(s, r3.trace[i].label == "put a brick" ? 1 : 0, now, 1);
    }
    CHECK(s.actors.env_press.is<pcell::Damage>());
    CHECK(s.actors.press.is<pcell::PsForge>());
}
