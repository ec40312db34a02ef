#pragma once
// Drives the compiled back end (bsc::machine) and the table-driven one (bsc::table::machine)
// side by side with the same events and execution cycles (step(now) with the same times) and
// compares them after every step: the outcome (and a cycle's step_report), the clock, the
// active configuration's bytes, active_states(), is<S>() for every state, halted(), the
// queue, the context and the observer's full trace. Used by differential_test.cpp and by the
// fuzz target tests/fuzz/differential_fuzz.cpp. A fixture (see fixtures.hpp) provides chart,
// policy, initial() and perturb(context&, r), and same(a, b) if its context has no ==.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <bsc/bsc.hpp>
#include <bsc/table/machine.hpp>
#include "inside.hpp"

namespace bsc_diff {

/// An event type no chart handles: dispatched with bsc::allow_unhandled.
struct stray {};

/// One observer call: an entry (+), an exit (-), a transition (>) with the type of the event
/// it received and the event's data (if it has an `n`), or a transition's row (#, in `data`).
struct record {
    char what = '+';
    std::string_view state;   // the state entered or left, or the transition's source
    std::string_view target;  // a transition's target ("internal" for an internal transition)
    std::string_view event;   // the event type
    int data = 0;
    friend bool operator==(record const&, record const&) = default;
};

/// An observer that records what trace_observer records, and more: the event each transition
/// received. Records hold views of the names bsc keeps, so recording costs no string copy.
struct recorder {
    std::vector<record>* log;
    void on_entry(auto state) const { log->push_back({'+', state.name, {}, {}, 0}); }
    void on_exit(auto state) const { log->push_back({'-', state.name, {}, {}, 0}); }
    template <class E>
    void on_transition(auto source, auto target, E const& e) const {
        int data = 0;
        if constexpr (requires { e.n; }) data = e.n;
        log->push_back({'>', source.name, target.name, bsc::name_of<E>, data});
    }
    void on_row(int row) const { log->push_back({'#', {}, {}, {}, row}); }
};

/// A trace as text: "-A1 A1>A2(go:0) #3 +A2".
inline std::string text(std::vector<record> const& trace) {
    std::string out;
    for (auto const& r : trace) {
        if (!out.empty()) out += ' ';
        if (r.what == '#') {
            out += '#' + std::to_string(r.data);
        } else if (r.what == '>') {
            out.append(r.state).append(">").append(r.target).append("(").append(r.event);
            out.append(":").append(std::to_string(r.data)).append(")");
        } else {
            out += r.what;
            out.append(r.state);
        }
    }
    return out;
}

inline char const* name(bsc::outcome o) {
    switch (o) {
        case bsc::outcome::consumed: return "consumed";
        case bsc::outcome::ignored: return "ignored";
        case bsc::outcome::queue_overflow: return "queue_overflow";
        case bsc::outcome::livelock: return "livelock";
        case bsc::outcome::halted: return "halted";
        case bsc::outcome::reentrant: return "reentrant";
        case bsc::outcome::failed: return "failed";
        case bsc::outcome::unknown_event: return "unknown_event";
    }
    return "?";
}

/// How often each outcome was seen, how many cycles ran (with how many component transitions,
/// and how many with an earlier time), and how many restarts after a halt.
struct tally {
    std::size_t steps = 0;
    std::size_t outcomes[8] = {};
    std::size_t restarts = 0;
    std::size_t cycles = 0;
    std::size_t cycle_transitions = 0;
    std::size_t backwards = 0;
};

/// The time a cycle is run at, from the last cycle's `now` and a random byte (`arg`'s low
/// eight bits): the same time again (about 1 in 6), a step of 1 to 40 ms (most), a jump of
/// 0.25 to 4.75 s (1 in 13), or (1 in 256) a time before the last one, which the machines must
/// report and ignore. Returns the time and whether it goes backwards.
inline std::pair<bsc::duration, bool> next_time(bsc::duration now, std::uint32_t arg) {
    using std::chrono::milliseconds;
    std::uint32_t const k = arg & 0xffu;
    if (k == 0xffu) return {now - milliseconds{1 + (arg >> 8) % 50}, true};
    if (k < 40) return {now, false};
    if (k < 236) return {now + milliseconds{1 + (k - 40) % 40}, false};
    return {now + milliseconds{250} * (k - 235), false};
}

template <class Fixture>
class twin {
public:
    using chart_type = std::remove_cvref_t<decltype(Fixture::chart)>;
    using policy = typename Fixture::policy;
    using compiled_type = bsc::machine<chart_type, policy, recorder>;
    using table_type = bsc::table::machine<chart_type, policy, recorder>;
    using events = typename compiled_type::event_types;
    using tags = typename inside::model<chart_type>::tags;
    // What the twin dispatches: the chart's events the environment may send (not the done
    // events, bsc::action_failed or bsc::any_event, which dispatch refuses), and the fixture's
    // extra_events (events the chart does not name, which rows on their families take).
    template <class F>
    static auto extra_of(int) -> typename F::extra_events;
    template <class F>
    static auto extra_of(long) -> inside::type_list<>;
    using dispatched = inside::concat_t<inside::sendable_events<events>, decltype(extra_of<Fixture>(0))>;

    static_assert(std::is_same_v<typename compiled_type::configuration_type, typename table_type::configuration_type>);
    // The compiled machine drops the queue of a chart none of whose actions can raise.
    static_assert(compiled_type::queue_capacity == table_type::queue_capacity || compiled_type::queue_capacity == 0);
    static_assert(std::is_same_v<events, typename table_type::event_types>);

    /// Number of choices step() maps a random number onto: the dispatched events, an unhandled
    /// event, a write to the context by the environment, and as many (at least two) execution
    /// cycles as events, so that about half the steps are cycles.
    static constexpr std::uint32_t cycle_choices = dispatched::size > 2 ? static_cast<std::uint32_t>(dispatched::size)
                                                                        : 2;
    static constexpr std::uint32_t choices = static_cast<std::uint32_t>(dispatched::size) + 2 + cycle_choices;

    twin() = default;
    twin(twin const&) = delete;
    twin& operator=(twin const&) = delete;

    /// (Re)starts both machines; returns a description of the first difference, or "".
    std::string start() {
        compiled_trace_.clear();
        table_trace_.clear();
        compiled_.emplace(Fixture::chart, Fixture::initial(), recorder{&compiled_trace_});
        table_.emplace(Fixture::chart, Fixture::initial(), recorder{&table_trace_});
        now_ = {};
        return compare("construction", compiled_->last_outcome(), table_->last_outcome());
    }

    /// One step chosen by `choice` (below `choices`), with `arg` as the event's data or the
    /// environment's write. A halted pair is restarted one time in four instead.
    std::string step(std::uint32_t choice, std::uint32_t arg) {
        if (!compiled_) return start();
        ++tally_.steps;
        if (compiled_->halted() && table_->halted() && arg % 4 == 0) {
            ++tally_.restarts;
            return start();
        }
        if (choice < dispatched::size) return dispatch_at(choice, static_cast<int>(arg % 8));
        if (choice == dispatched::size) {
            auto const a = compiled_->dispatch(stray{}, bsc::allow_unhandled);
            auto const b = table_->dispatch(stray{}, bsc::allow_unhandled);
            return compare("stray", a, b);
        }
        if (choice == dispatched::size + 1) {
            Fixture::perturb(inside::context(*compiled_), arg);
            Fixture::perturb(inside::context(*table_), arg);
            return compare("environment write", compiled_->last_outcome(), table_->last_outcome());
        }
        return cycle(arg);
    }

    /// One execution cycle of both machines at the time next_time(now, arg) gives.
    std::string cycle(std::uint32_t arg) {
        auto const [t, backwards] = next_time(now_, arg);
        if (!backwards) now_ = t;
        ++tally_.cycles;
        tally_.backwards += backwards;
        bsc::step_report const a = compiled_->step(t);
        bsc::step_report const b = table_->step(t);
        tally_.cycle_transitions += static_cast<std::size_t>(a.transitions);
        std::string report;
        if (a.transitions != b.transitions)
            report += " transitions (" + std::to_string(a.transitions) + " against " + std::to_string(b.transitions) +
                      ")";
        if (a.clock_went_backwards != b.clock_went_backwards) report += " clock_went_backwards";
        return compare(
            "step(" + std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(t).count()) + "ms)",
            a.status, b.status, report);
    }

    compiled_type const& compiled() const { return *compiled_; }
    table_type const& table() const { return *table_; }
    tally const& counts() const { return tally_; }

private:
    template <class E>
    static E make_event(int n) {
        if constexpr (requires { E{n}; } && !std::is_empty_v<E>)
            return E{n};
        else
            return E{};
    }

    template <std::size_t I = 0>
    std::string dispatch_at(std::uint32_t choice, int n) {
        if constexpr (I < dispatched::size) {
            if (choice != I) return dispatch_at<I + 1>(choice, n);
            using E = inside::at<I, dispatched>;
            E const e = make_event<E>(n);
            auto const a = compiled_->dispatch(e);
            auto const b = table_->dispatch(e);
            return compare(bsc::name_of<E>, a, b);
        } else {
            return "no such event";
        }
    }

    // A fixture whose context has no operator== provides same(a, b).
    static bool same_context(typename compiled_type::context_type const& a,
                             typename compiled_type::context_type const& b) {
        if constexpr (requires { Fixture::same(a, b); })
            return Fixture::same(a, b);
        else
            return a == b;
    }

    template <class... Tags>
    std::string is_differences(inside::type_list<Tags...>) const {
        std::string out;
        (
            [&] {
                if (compiled_->template is<Tags>() != table_->template is<Tags>())
                    out += " is<" + std::string(bsc::name_of<Tags>) + ">";
            }(),
            ...);
        return out;
    }

    // `differences` lists what the caller found different already ("" if nothing).
    std::string compare(std::string_view what, bsc::outcome a, bsc::outcome b, std::string const& differences = {}) {
        ++tally_.outcomes[static_cast<std::size_t>(a)];
        auto const states_c = compiled_->active_states();
        auto const states_t = table_->active_states();
        bool const same_states = states_c == states_t;
        bool const same_is = is_differences(tags{}).empty();
        bool const same = differences.empty() && a == b && compiled_->last_outcome() == table_->last_outcome() &&
                          compiled_->now() == table_->now() &&
                          compiled_->active_configuration() == table_->active_configuration() && same_states &&
                          compiled_->halted() == table_->halted() &&
                          inside::queue(*compiled_).size() == inside::queue(*table_).size() &&
                          same_context(compiled_->context(), table_->context()) && compiled_trace_ == table_trace_ &&
                          same_is;
        std::string report;
        if (!same) {
            std::string diff = differences;
            if (a != b) diff += " outcome";
            if (compiled_->now() != table_->now()) diff += " now";
            if (compiled_->last_outcome() != table_->last_outcome()) diff += " last_outcome";
            if (!(compiled_->active_configuration() == table_->active_configuration())) diff += " configuration";
            if (!same_states) diff += " active_states";
            if (compiled_->halted() != table_->halted()) diff += " halted";
            if (inside::queue(*compiled_).size() != inside::queue(*table_).size()) diff += " queue";
            if (!same_context(compiled_->context(), table_->context())) diff += " context";
            if (compiled_trace_ != table_trace_) diff += " trace";
            diff += is_differences(tags{});
            report = "after " + std::string(what) + " (step " + std::to_string(tally_.steps) + "), differ:" + diff +
                     "\n  compiled: " + name(a) + " [" + states_c.joined() + "] " + text(compiled_trace_) +
                     "\n  table:    " + name(b) + " [" + states_t.joined() + "] " + text(table_trace_);
        }
        compiled_trace_.clear();
        table_trace_.clear();
        return report;
    }

    std::vector<record> compiled_trace_;
    std::vector<record> table_trace_;
    std::optional<compiled_type> compiled_;
    std::optional<table_type> table_;
    bsc::duration now_{};  // the time of the last cycle run forwards
    tally tally_;
};

}  // namespace bsc_diff
