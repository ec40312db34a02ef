// The production cell in closed loop: five controller actors and five plant models, stepped
// every 100 ms. The operator offers five bricks at fixed times; the run prints one line per step
// in which a controller's state or a brick's place changes, then a summary, and fails (exit
// status 1) if a plant model reaches Damage, a brick is lost, or a brick leaves unforged or not
// at all within the time limit.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "operation.hpp"

namespace {

using namespace std::chrono_literals;

/// A controller's active states without the root and the states that only contain others.
template <class Machine>
std::string states(Machine const& m) {
    constexpr std::string_view containers[] = {"On", "RobotWork", "Turret", "Arm1Job", "Arm2Job"};
    std::string out;
    auto const names = m.active_states();
    for (std::size_t i = 1; i < names.size(); ++i) {
        bool skip = false;
        for (auto c : containers) skip = skip || names[i] == c;
        if (skip) continue;
        if (!out.empty()) out += ' ';
        out += names[i];
    }
    return out;
}

std::string line(pcell::cell const& s) {
    auto const& a = s.actors;
    return "feed " + states(a.feed_belt) + " | table " + states(a.table) + " | robot " + states(a.robot) + " | press " +
           states(a.press) + " | deposit " + states(a.deposit_belt) + " || " + pcell::picture(s);
}

double seconds(bsc::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

int main() {
    // Two bricks at once, one shortly after, then two more later.
    std::vector<bsc::duration> const offers{0s, 0s, 2s, 15s, 16s};
    constexpr auto time_limit = 90s;

    pcell::run<pcell::cell> r{offers};
    std::string previous;
    bool conserved = true;
    while (!r.done() && r.now() <= time_limit && pcell::no_damage(r.cell)) {
        auto const t = r.now();
        r.step();
        conserved = conserved && r.bricks_conserved();
        auto const now = line(r.cell);
        if (now != previous) std::printf("%6.1f s  %s\n", seconds(t), now.c_str());
        previous = now;
    }

    bsc::duration longest{};
    for (std::size_t k = 0; k < r.offered(); ++k)
        if (r.left_at(k) != r.never) longest = std::max(longest, r.left_at(k) - r.put_at(k));
    auto const damage = pcell::damaged(r.cell);
    auto const unforged = r.cell.actors.env_deposit_belt.context().unforged;

    std::printf("\nbricks offered %zu, fed %zu, forged %zu, deposited %zu (unforged %d)\n", r.offered(), r.fed(),
                r.forged(), r.delivered(), unforged);
    std::printf("steps %zu, time %.1f s, longest stay in the cell %.1f s\n", r.steps(), seconds(r.now()),
                seconds(longest));
    bool ok = true;
    if (!damage.empty()) {
        std::printf("FAILED: Damage in %s\n", damage.c_str());
        ok = false;
    }
    if (!conserved) {
        std::printf("FAILED: a brick was lost or seen twice\n");
        ok = false;
    }
    if (!r.done() || unforged != 0) {
        std::printf("FAILED: not every brick left the cell forged\n");
        ok = false;
    }
    if (ok) std::printf("ok: every brick forged and deposited, no Damage\n");
    return ok ? 0 : 1;
}
