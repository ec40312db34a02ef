#pragma once
// Fault injection: every guard and action of a chart is made to throw in turn (inside.hpp's
// with_faults), on one back end, while the machine is driven by random events, context
// changes and cycles. After every dispatch and cycle, whether it threw or not,
//   - the configuration is legal: the root is active, the parent of every active state is
//     active, an active composite has exactly one active child and an active parallel state
//     all of its children;
//   - the states the observer saw entered and not exited are exactly the active ones, so no
//     entry or exit ran twice and none was skipped;
// and after the faulty run the machine goes on working under more random steps.

#include <doctest/doctest.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>

#include "backends.hpp"
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

// The configuration's legality, read against the chart's topology table.
template <class Machine>
bool legal(Machine const& m) {
    using tables = bsc::table::tables<typename Machine::chart_type, typename Machine::policy_type>;
    using bsc::table::state_kind;
    constexpr std::size_t n = tables::state_count;
    std::array<bool, n> on{};
    for (auto name : m.active_states()) {
        std::size_t s = 1;
        while (s < n && tables::names[s] != name) ++s;
        if (s == n) return false;
        on[s] = true;
    }
    if (!on[tables::root]) return false;
    for (std::size_t s = 1; s < n; ++s) {
        auto const& row = tables::states[s];
        if (on[s] && s != tables::root && !on[row.parent]) return false;
        if (!on[s] || (row.status.kind != state_kind::composite && row.status.kind != state_kind::parallel)) continue;
        std::size_t children = 0, active_children = 0;
        for (auto c = row.first_child; c != bsc::table::no_state; c = tables::states[c].next_sibling) {
            ++children;
            active_children += on[c];
        }
        if (row.status.kind == state_kind::composite ? active_children != 1 : active_children != children) return false;
    }
    return true;
}

// The events the environment may send (the chart's, without the done events, bsc::action_failed
// and bsc::any_event, which dispatch refuses).
template <class Machine>
using sendable_events = inside::sendable_events<typename Machine::event_types>;

template <class Machine, std::size_t I = 0>
void dispatch_event(Machine& m, std::size_t which) {
    using events = sendable_events<Machine>;
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
    long sites = 0;       // guard and action calls of the fault-free run
    long thrown = 0;      // runs in which the injected fault reached the caller
    long violations = 0;  // ledger breaches and illegal configurations
    totals& operator+=(totals const& t) {
        sites += t.sites;
        thrown += t.thrown;
        violations += t.violations;
        return *this;
    }
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
        if (!legal(m)) ++t.violations;
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
                    if constexpr (sendable_events<machine>::size > 0)
                        dispatch_event(*m, (r >> 2) % sendable_events<machine>::size);
                    break;
                case 1: Fixture::perturb(inside::context(*m), r >> 2); break;
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
        if constexpr (sendable_events<machine>::size > 0)
            if (r % 2 == 0) {
                dispatch_event(*m, (r >> 1) % sendable_events<machine>::size);
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

}  // namespace faults
