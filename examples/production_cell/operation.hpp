#pragma once
// Running the production cell: the operator, who switches the controllers on and puts bricks
// on the feed belt, the clock that steps the cell every period, and what can be observed of the
// cell from outside (where the bricks are, Damage, the press area).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cell.hpp"

namespace pcell {

// ---- Observations -------------------------------------------------------------------------------

/// The places a brick can be in, in the order it passes them.
enum class place : std::uint8_t { feed_belt, table, arm1, press, arm2, deposit_belt };
inline constexpr std::array<std::string_view, 6> place_names{"feed belt", "table", "arm1",
                                                             "press",     "arm2",  "deposit belt"};

/// Calls f(brick, place) for every brick in the cell (not those that have left it).
template <class System, class F>
constexpr void for_each_brick(System const& s, F&& f) {
    auto const& a = s.actors;
    for (auto const b : a.env_feed_belt.context().slots)
        if (b) f(b, place::feed_belt);
    if (auto const b = a.env_table.context().load) f(b, place::table);
    if (auto const b = a.env_robot.context().held1) f(b, place::arm1);
    if (auto const b = a.env_press.context().load) f(b, place::press);
    if (auto const b = a.env_robot.context().held2) f(b, place::arm2);
    // The only transfer that takes a step: the robot's model steps before the press's, so it
    // receives the brick arm2 took from the press in the next step.
    if (auto const b = a.env_press.context().to_arm2.get()) f(b, place::arm2);
    for (auto const b : a.env_deposit_belt.context().slots)
        if (b) f(b, place::deposit_belt);
}

/// R3 (and the Damage of R1 and R2): no plant model has entered Damage.
template <class System>
constexpr bool no_damage(System const& s) {
    auto const& a = s.actors;
    return !a.env_feed_belt.template is<Damage>() && !a.env_table.template is<Damage>() &&
           !a.env_robot.template is<Damage>() && !a.env_press.template is<Damage>() &&
           !a.env_deposit_belt.template is<Damage>();
}

/// The plant models in Damage, e.g. "press", or "" if none.
template <class System>
std::string damaged(System const& s) {
    auto const& a = s.actors;
    std::string out;
    auto add = [&](bool d, std::string_view name) {
        if (!d) return;
        if (!out.empty()) out += ", ";
        out += name;
    };
    add(a.env_feed_belt.template is<Damage>(), "feed belt");
    add(a.env_table.template is<Damage>(), "table");
    add(a.env_robot.template is<Damage>(), "robot");
    add(a.env_press.template is<Damage>(), "press");
    add(a.env_deposit_belt.template is<Damage>(), "deposit belt");
    return out;
}

/// The press plate is moving.
template <class System>
constexpr bool press_moving(System const& s) {
    auto const& p = s.actors.env_press;
    return p.template is<PlateUp>() || p.template is<PlateDown>();
}

/// Arm 1 or 2 is extended into the press area (pointing at the press, not retracted).
template <class System>
constexpr bool arm_in_press_area(System const& s, int arm) {
    auto const& r = s.actors.env_robot.context();
    return arm == 1 ? r.angle == arm1_to_press && r.ext1 > 0 : r.angle == arm2_to_press && r.ext2 > 0;
}

/// The bricks in the cell at a glance, e.g. "feed[.1..] table:- arm1:2 press:3* arm2:- deposit[4*..]"
/// (a star marks a forged brick).
template <class System>
std::string picture(System const& s) {
    auto const& a = s.actors;
    auto one = [](brick b) {
        if (!b) return std::string(".");
        return std::to_string(b.id) + (b.forged ? "*" : "");
    };
    // Appended piece by piece: GCC 12's -Wrestrict misfires on chains of string + string.
    auto belt = [&](std::string& out, auto const& slots) {
        out += '[';
        for (std::size_t i = 0; i < slots.size(); ++i) {
            if (i) out += ' ';
            out += one(slots[i]);
        }
        out += ']';
    };
    auto held = [&](brick b) { return b ? one(b) : std::string("-"); };
    auto const& robot = a.env_robot.context();
    brick const arm2 = robot.held2 ? robot.held2 : a.env_press.context().to_arm2.get();  // see for_each_brick
    std::string out = "feed";
    belt(out, a.env_feed_belt.context().slots);
    out += " table:";
    out += held(a.env_table.context().load);
    out += " arm1:";
    out += held(robot.held1);
    out += " press:";
    out += held(a.env_press.context().load);
    out += " arm2:";
    out += held(arm2);
    out += " deposit";
    belt(out, a.env_deposit_belt.context().slots);
    return out;
}

// ---- The operator and the clock -----------------------------------------------------------------

/// A run of the cell. The operator switches every controller on before the first step, and puts
/// brick k (id k + 1) on the feed belt at the first step at or after `offers[k]` at which the start
/// of the belt is free (the operator waits otherwise; the offers are in increasing order). Step n
/// runs at time n * period.
template <class System>
class run {
public:
    explicit run(std::vector<bsc::duration> offers)
        : offers_(std::move(offers)), put_at_(offers_.size(), never), left_at_(offers_.size(), never) {
        switch_all(true);
    }

    static constexpr bsc::duration never = bsc::duration::max();

    System cell{};

    /// The manual on/off switch of every controller.
    void switch_all(bool on) {
        auto& a = cell.actors;
        a.feed_belt.context().on.set(on);
        a.table.context().on.set(on);
        a.robot.context().on.set(on);
        a.press.context().on.set(on);
        a.deposit_belt.context().on.set(on);
    }

    /// One step of the cell at now(), then the clock moves on by one period.
    bsc::system_report step() {
        auto& belt = cell.actors.env_feed_belt.context();
        brick put{};
        if (next_ < offers_.size() && offers_[next_] <= now_ && belt.start_free.get()) {
            put = brick{static_cast<std::uint8_t>(next_ + 1), false};
            put_at_[next_++] = now_;
        }
        belt.put.set(put);
        auto const& out = cell.actors.env_deposit_belt.context();
        auto const before = out.delivered;
        auto const report = cell.step(now_);
        if (out.delivered != before && out.last.id >= 1 && out.last.id <= left_at_.size())
            left_at_[out.last.id - 1u] = now_;
        now_ += period;
        ++steps_;
        return report;
    }

    bsc::duration now() const { return now_; }
    std::size_t steps() const { return steps_; }
    std::size_t offered() const { return offers_.size(); }
    std::size_t fed() const { return next_; }
    /// Bricks that have left the cell at the end of the deposit belt.
    std::size_t delivered() const { return cell.actors.env_deposit_belt.context().delivered; }
    /// Bricks forged so far: in the cell, or delivered.
    std::size_t forged() const {
        auto const& out = cell.actors.env_deposit_belt.context();
        std::size_t n = out.delivered - out.unforged;
        for_each_brick(cell, [&](brick b, place) { n += b.forged ? 1 : 0; });
        return n;
    }
    /// When brick k was put on the feed belt, and when it left the cell (`never` if not yet).
    bsc::duration put_at(std::size_t k) const { return put_at_[k]; }
    bsc::duration left_at(std::size_t k) const { return left_at_[k]; }
    /// Every brick offered has left the cell.
    bool done() const { return delivered() == offers_.size(); }

    /// Bricks conserved: every brick put on the belt is either in the cell, at exactly one place,
    /// or has left it; none is anywhere twice (R1: one brick per place) and none is lost.
    bool bricks_conserved() const {
        std::vector<int> seen(offers_.size() + 1, 0);
        bool ok = true;
        for_each_brick(cell, [&](brick b, place) {
            if (b.id > next_)
                ok = false;
            else
                ++seen[b.id];
        });
        for (std::size_t k = 0; k < next_; ++k) ok = ok && seen[k + 1] + (left_at_[k] != never ? 1 : 0) == 1;
        return ok;
    }

private:
    std::vector<bsc::duration> offers_;
    std::vector<bsc::duration> put_at_;
    std::vector<bsc::duration> left_at_;
    std::size_t next_ = 0;
    std::size_t steps_ = 0;
    bsc::duration now_{};
};

}  // namespace pcell
