// Fault injection: every guard and action of a chart is made to throw in turn (inside.hpp's
// with_faults), on both back ends, while the machine is driven by random events, context
// changes and cycles. After every dispatch and cycle, whether it threw or not, the states
// the observer saw entered and not exited must be exactly the active configuration (so every
// entry and exit ran once, and the configuration is one the chart can reach), and the machine
// must go on working. Charts: the MCS, the manufacturing cell controller, the production cell's
// robot controller and generated charts.

#include <doctest/doctest.h>

#include <chrono>
#include <cstdint>
#include <exception>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <string_view>

#include "../../examples/production_cell/controllers.hpp"
#include "backends.hpp"
#include "differential_examples.hpp"
#include "generated_charts.hpp"
#include "inside.hpp"

namespace faults {

struct injected : std::exception {
    char const* what() const noexcept override { return "injected fault"; }
};

// Counts the calls of guards and actions; the armed one throws.
struct injector {
    static inline long calls = 0;
    static inline long throw_at = -1;  // the call that throws, counted from 1; -1: none
    static void point() {
        if (++calls == throw_at) throw injected{};
    }
};

// Tracks what entries and exits say is active, and counts what cannot happen.
struct ledger {
    std::set<std::string_view>* entered;
    long* violations;
    void on_entry(auto state) const {
        if (!entered->insert(state.name).second) ++*violations;  // entered twice
    }
    void on_exit(auto state) const {
        if (entered->erase(state.name) != 1) ++*violations;  // exited while not entered
    }
};

template <class Machine>
bool ledger_matches(Machine const& m, std::set<std::string_view> const& entered) {
    auto const active = m.active_states();
    if (active.size() != entered.size()) return false;
    for (auto name : active)
        if (entered.count(name) != 1) return false;
    return true;
}

template <class Machine, std::size_t I = 0>
void dispatch_event(Machine& m, std::size_t which) {
    using events = typename Machine::event_types;
    if constexpr (I < events::size) {
        if (which != I) return dispatch_event<Machine, I + 1>(m, which);
        using E = inside::at<I, events>;
        if constexpr (requires { E{1}; } && !std::is_empty_v<E>)
            m.dispatch(E{1});
        else
            m.dispatch(E{});
    }
}

struct totals {
    long sites = 0;        // guard and action calls of the fault-free run
    long thrown = 0;       // runs in which the injected fault reached the caller
    long violations = 0;
    long stuck = 0;        // runs after which the machine no longer worked
};

// Runs `steps` random steps on a fresh machine with the call `throw_at` failing.
template <class Backend, class Fixture, class Chart>
totals run_once(Chart const& chart, long throw_at, int steps, std::uint32_t seed) {
    using machine = bsc_test::machine_t<Backend, Chart, typename Fixture::policy, ledger>;
    totals t;
    std::set<std::string_view> entered;
    injector::calls = 0;
    injector::throw_at = throw_at;
    std::mt19937 random{seed};
    auto const check = [&](machine const& m) {
        if (!ledger_matches(m, entered)) ++t.violations;
    };
    std::optional<machine> m;
    try {
        m.emplace(chart, Fixture::initial(), ledger{&entered, &t.violations});
    } catch (injected const&) {
        ++t.thrown;
        return t;  // a constructor that throws leaves no machine behind
    }
    check(*m);
    auto now = bsc::duration::zero();
    for (int i = 0; i < steps; ++i) {
        std::uint32_t const r = random();
        try {
            switch (r % 4) {
                case 0:
                    if constexpr (machine::event_types::size > 0)
                        dispatch_event(*m, (r >> 2) % machine::event_types::size);
                    break;
                case 1: Fixture::perturb(m->context(), r >> 2); break;
                default:
                    now += std::chrono::milliseconds{(r >> 2) % 700};
                    m->step(now);
                    break;
            }
        } catch (injected const&) {
            ++t.thrown;
        }
        check(*m);
    }
    t.sites = injector::calls;  // the call sites of the random steps (the ones a fault is put in)
    // It goes on working: more steps with no fault run as they would.
    injector::throw_at = -1;
    for (int i = 0; i < 20; ++i) {
        std::uint32_t const r = random();
        now += std::chrono::milliseconds{(r >> 2) % 700};
        if constexpr (machine::event_types::size > 0)
            if (r % 2 == 0) {
                dispatch_event(*m, (r >> 1) % machine::event_types::size);
                check(*m);
                continue;
            }
        m->step(now);
        check(*m);
    }
    return t;
}

// Every call site of a fault-free run of `steps` steps is made to fail, one per run.
template <class Backend, class Fixture>
totals inject_everywhere(int steps, std::uint32_t seed) {
    static constexpr auto chart = inside::with_faults<injector>(Fixture::chart);
    totals const clean = run_once<Backend, Fixture>(chart, -1, steps, seed);
    totals all;
    all.sites = clean.sites;
    all.violations = clean.violations;
    for (long site = 1; site <= clean.sites; ++site) {
        totals const t = run_once<Backend, Fixture>(chart, site, steps, seed);
        all.thrown += t.thrown;
        all.violations += t.violations;
    }
    return all;
}

// The production cell's robot controller (two arms on a turret), its sensors and the other
// actors' signals written at random by the environment.
struct robot_fixture {
    using policy = bsc::scan_policy;
    static constexpr auto const& chart = pcell::robot_chart;
    static pcell::robot_ctl initial() { return {}; }
    static void perturb(pcell::robot_ctl& c, std::uint32_t r) {
        bsc::input<bool>* const flags[] = {&c.on, &c.table_ready, &c.press_load_ready, &c.press_unload_ready,
                                           &c.belt_ready};
        bsc::input<std::uint8_t>* const sensors[] = {&c.angle, &c.ext1, &c.ext2};
        if (r % 2 == 0) {
            auto& flag = *flags[(r >> 1) % 5];
            flag.set(!flag.pending());
        } else {
            sensors[(r >> 1) % 3]->set(static_cast<std::uint8_t>((r >> 3) % 8));
        }
    }
};

// Every call site of an example controller: each fault reaches the caller (no row of these
// charts takes bsc::action_failed) and no run breaks the ledger.
template <class Backend, class Fixture>
void check_every_site(std::string const& name, int steps, std::uint32_t seed) {
    auto const t = inject_everywhere<Backend, Fixture>(steps, seed);
    MESSAGE(name << ": " << t.sites << " call sites, " << t.thrown << " faults reached the caller");
    CHECK(t.sites > 50);
    CHECK(t.thrown == t.sites);
    CHECK(t.violations == 0);
}

}  // namespace faults

TEST_CASE_TEMPLATE("a fault at any guard or action of the production cell's robot controller leaves a configuration "
                   "it can reach",
                   Backend, bsc_test::compiled, bsc_test::table) {
    faults::check_every_site<Backend, faults::robot_fixture>("robot", 120, 4);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of the MCS leaves a configuration it can reach", Backend,
                   bsc_test::compiled, bsc_test::table) {
    faults::check_every_site<Backend, bsc_diff::mcs_fixture>("MCS", 400, 1);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of the manufacturing cell leaves a configuration it can reach",
                   Backend, bsc_test::compiled, bsc_test::table) {
    faults::check_every_site<Backend, bsc_diff::cell_fixture>("cell", 120, 2);
}

TEST_CASE_TEMPLATE("a fault at any guard or action of generated charts leaves a configuration they can reach",
                   Backend, bsc_test::compiled, bsc_test::table) {
    long sites = 0, thrown = 0, violations = 0;
    auto const run = [&]<class Fixture>() {
        auto const t = faults::inject_everywhere<Backend, Fixture>(80, 3);
        sites += t.sites;
        thrown += t.thrown;
        violations += t.violations;
    };
    run.template operator()<gen::generated<1>>();
    run.template operator()<gen::generated<2>>();
    run.template operator()<gen::generated<3>>();
    run.template operator()<gen::generated_scan<5>>();
    MESSAGE("generated charts: " << sites << " call sites");
    CHECK(sites > 20);
    CHECK(thrown == sites);
    CHECK(violations == 0);
}
