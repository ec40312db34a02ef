#pragma once
// bsc::measure_latency: the dispatch latency of a user's own machine, pair by pair. Every
// (state, event) pair the chart can meet — found by the explorer (bsc/verify.hpp) where the
// chart is small enough, or from states the user reached along scenarios of their own — is
// dispatched from a fresh copy of the state, repeatedly, and timed; the report gives the spread
// over the pairs (min, median, p99, max), the slowest pairs by name with what their dispatch
// did (states exited and entered, transitions fired), and a bound read from the chart itself.
// Under callgrind (valgrind --tool=callgrind) each pair's instructions are counted instead of
// timed: exact, and the same on every run.
//
//   bsc::verify::event_model<mcs::machine, mcs::on_p, mcs::off_p /* ... */> model{mcs::machine{mcs::chart}};
//   auto report = bsc::measure_latency(model);
//   std::fputs(report.to_string().c_str(), stdout);
//
// Opt-in: <bsc/bsc.hpp> does not include it. It uses the heap, the standard library's strings
// and Google Benchmark (link benchmark::benchmark): register_latency_benchmarks adds the
// slowest pairs to a Google Benchmark program.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <bsc/detail/access.hpp>
#include <bsc/detail/benchmark/callgrind_counter.hpp>
#include <bsc/detail/benchmark/dispatch_bound.hpp>
#include <bsc/detail/machine_base.hpp>
#include <bsc/logger.hpp>
#include <bsc/verify/explorer.hpp>
#include <bsc/verify/models.hpp>

namespace bsc {

/// How bsc::measure_latency measures.
struct latency_options {
    /// Timed batches per pair; the pair's figures are the min, median and max over them.
    std::size_t repetitions = 11;
    /// Dispatches per timed batch, each on its own copy of the state (so that the clock's own
    /// cost is shared out); the batch's time divided by this is one dispatch.
    std::size_t batch = 32;
    /// The slowest pairs the report names: of pairs with the same configuration and event by
    /// name (states that differ in their data), the slowest.
    std::size_t worst = 5;
    /// States explored at most; past it, the pairs of the states found (breadth first: those
    /// nearest the initial state) are measured and the report says it is not complete.
    std::size_t max_states = 20'000;
    /// measure_latency(model, starts): the given states are every state the chart can reach (the
    /// user explored them), which the report then says.
    bool starts_are_every_state = false;
    /// Under callgrind: count instructions (true) or time anyway (false).
    bool count_instructions = true;
    /// Under callgrind: its --callgrind-out-file, where %p is the process id.
    std::string callgrind_out_file = "callgrind.out.%p";
};

/// One (state, event) pair: its figures and what its dispatch did.
struct pair_latency {
    std::string configuration;  ///< the state, as the model describes it (the active states)
    std::string event;          ///< the event (or the cycle's inputs), as the model labels it
    double min = 0;             ///< per dispatch, over the repetitions (ns or instructions)
    double median = 0;
    double max = 0;
    /// What the dispatch did, as bsc::logger writes it: "exit A", "transition A -> B on e",
    /// "entry B" (filled for the pairs the report names, where the state is a machine).
    std::vector<std::string> account;
    std::size_t exited = 0;       ///< states exited
    std::size_t entered = 0;      ///< states entered
    std::size_t transitions = 0;  ///< transitions fired (deferrals included)
    bool explained = false;       ///< the account is filled (the pair was replayed with a logger)
};

/// What bsc::measure_latency found.
struct latency_report {
    std::string unit = "ns";         ///< "ns", or "instructions" under callgrind
    std::size_t states = 0;          ///< states measured from
    std::size_t labels = 0;          ///< events (or input choices) offered in each
    std::string offered = "events";  ///< what the labels are: "events", or "inputs" for a stepped model
    std::size_t pairs = 0;           ///< states x labels
    bool complete = false;           ///< every reachable state was measured from
    double min = 0;                  ///< over the pairs' medians
    double median = 0;
    double p99 = 0;
    double max = 0;
    std::vector<pair_latency> worst;      ///< the slowest pairs, slowest first
    std::optional<dispatch_bound> bound;  ///< from the chart and policy, where the state is a machine

    /// The report as text: the spread, the bound, then each named pair and its account.
    std::string to_string() const {
        auto const figure = [&](double v) {
            char text[32];
            std::snprintf(text, sizeof text, unit == "ns" ? "%.1f" : "%.0f", v);
            return std::string(text);
        };
        std::string out = "dispatch latency (" + unit + "), " + std::to_string(pairs) + " pairs (" +
                          std::to_string(states) + " states x " + std::to_string(labels) + " " + offered +
                          (complete ? ", every reachable state" : ", not every reachable state") + ")\n";
        out += "  min " + figure(min) + "  median " + figure(median) + "  p99 " + figure(p99) + "  max " + figure(max) +
               "\n";
        if (bound) {
            out += "  bound from the chart: " + std::to_string(bound->states_at_once) +
                   " states active at once; one transition exits and enters at most " +
                   std::to_string(bound->states_per_transition) +
                   (bound->widest_transition.empty() ? "" : " (" + bound->widest_transition + ")") + "; at most " +
                   std::to_string(bound->transitions_per_microstep) + " transition(s) per microstep, " +
                   std::to_string(bound->microsteps) + " microstep(s) (" + bound->microsteps_from + "), " +
                   std::to_string(bound->states_per_run) + " states exited and entered per run\n";
        }
        for (std::size_t k = 0; k < worst.size(); ++k) {
            auto const& p = worst[k];
            out += "  #" + std::to_string(k + 1) + " " + figure(p.median) + " " + unit + " (min " + figure(p.min) +
                   ", max " + figure(p.max) + "): " + p.event + " in " + p.configuration + "\n";
            if (!p.explained) continue;
            if (p.account.empty()) {
                out += "     nothing fired\n";
                continue;
            }
            out += "     exits " + std::to_string(p.exited) + ", enters " + std::to_string(p.entered) + ", " +
                   std::to_string(p.transitions) + " transition(s):";
            for (auto const& line : p.account) out += " " + line + ";";
            out.back() = '\n';
        }
        return out;
    }
};

namespace detail {

// The same machine type with another observer (both back ends: machine<Chart, Policy, Observer>);
// a state that is no machine stays itself.
template <class State, class Observer>
struct with_observer {
    using type = State;
};
template <template <class, class, class> class Machine, class C, class P, class O, class Observer>
struct with_observer<Machine<C, P, O>, Observer> {
    using type = Machine<C, P, Observer>;
};

// One batch: each copy set to `from`, then `label` taken on each, timed together (ns).
template <class Model, class State>
double timed_batch(Model const& model, std::vector<State>& copies, State const& from, std::uint16_t label) {
    std::fill(copies.begin(), copies.end(), from);
    auto const start = std::chrono::steady_clock::now();
    for (auto& s : copies) {
        model.advance(s, label);
        ::benchmark::DoNotOptimize(s);
    }
    auto const stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(stop - start).count();
}

// The alternatives a model offers, as the labels its advance takes (the explorer's are 16 bits).
template <class Model>
std::uint16_t label_count(Model const& model) {
    std::size_t const n = model.labels();
    if (n > 0xffff) throw std::length_error("bsc::measure_latency: more than 65,535 events or input choices");
    return static_cast<std::uint16_t>(n);
}

template <class Model>
class latency_run {
public:
    using state = typename Model::state;

    latency_run(Model const& model, latency_options const& options) : model_(model), options_(options) {}

    latency_report measure(std::vector<state> const& starts, bool complete) {
        latency_report report;
        std::uint16_t const labels = label_count(model_);
        report.states = starts.size();
        report.labels = labels;
        report.pairs = report.states * report.labels;
        report.complete = complete;
        if constexpr (stepped) report.offered = "inputs";
        if constexpr (is_machine<state>) report.bound = bound_of<state>(stepped);
        callgrind_counter counter{options_.callgrind_out_file};
        bool counting = options_.count_instructions && callgrind_counter::available();
        std::vector<pair_latency> pairs;
        std::vector<std::pair<std::size_t, std::uint16_t>> where;
        // Every pair counted, or every pair timed: where one count cannot be read (callgrind
        // writes its dumps elsewhere, or another valgrind tool runs), all are timed.
        for (bool again = true; again;) {
            again = false;
            pairs.clear();
            where.clear();
            for (std::size_t i = 0; i < starts.size() && !again; ++i) {
                for (std::uint16_t label = 0; label < labels; ++label) {
                    pair_latency p;
                    if (counting && !count(counter, starts[i], label, p)) {
                        counting = false;
                        again = true;
                        break;
                    }
                    if (!counting) time(starts[i], label, p);
                    pairs.push_back(std::move(p));
                    where.emplace_back(i, label);
                }
            }
        }
        report.unit = counting ? "instructions" : "ns";
        if (pairs.empty()) return report;
        std::vector<std::size_t> order(pairs.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t b) { return pairs[a].median > pairs[b].median; });
        // The pairs' medians at quantile q, nearest rank: q * (n - 1) places above the fastest.
        auto const at_rank = [&](double q) {
            auto const rank = static_cast<std::size_t>(q * static_cast<double>(order.size() - 1) + 0.5);
            return pairs[order[order.size() - 1 - rank]].median;
        };
        report.min = at_rank(0);
        report.median = at_rank(0.5);
        report.p99 = at_rank(0.99);
        report.max = at_rank(1);
        // The slowest pair of each (configuration, event) by name: states that differ only in
        // their data would otherwise fill the list with one pair.
        for (std::size_t k = 0; k < order.size() && report.worst.size() < options_.worst; ++k) {
            auto const& [i, label] = where[order[k]];
            std::string configuration = model_.describe(starts[i]);
            std::string event = model_.label(label);
            bool const named = std::any_of(report.worst.begin(), report.worst.end(), [&](pair_latency const& w) {
                return w.configuration == configuration && w.event == event;
            });
            if (named) continue;
            pair_latency p = std::move(pairs[order[k]]);
            p.configuration = std::move(configuration);
            p.event = std::move(event);
            explain(starts[i], label, p);
            report.worst.push_back(std::move(p));
        }
        return report;
    }

private:
    static constexpr bool stepped = requires(Model const& m) { m.period(); };

    bool count(callgrind_counter& counter, state const& from, std::uint16_t label, pair_latency& p) {
        state s = from;
        auto const n = counter.count([&] {
            model_.advance(s, label);
            ::benchmark::DoNotOptimize(s);
        });
        if (!n) return false;
        p.min = p.median = p.max = static_cast<double>(*n);
        return true;
    }

    // The time of the two clock reads around a batch, least of a few: taken off each batch.
    static double clock_cost() {
        double least = 1e300;
        for (int k = 0; k < 16; ++k) {
            auto const start = std::chrono::steady_clock::now();
            auto const stop = std::chrono::steady_clock::now();
            least = std::min(least, std::chrono::duration<double, std::nano>(stop - start).count());
        }
        return least;
    }

    void time(state const& from, std::uint16_t label, pair_latency& p) {
        std::size_t const batch = std::max<std::size_t>(options_.batch, 1);
        std::size_t const repetitions = std::max<std::size_t>(options_.repetitions, 1);
        if (clock_ < 0) clock_ = clock_cost();
        std::vector<state> copies(batch, from);
        std::vector<double> per_dispatch;
        // One batch untimed first: the code and the state's memory are then warm.
        for (std::size_t r = 0; r <= repetitions; ++r) {
            double const batch_ns = timed_batch(model_, copies, from, label) - clock_;
            if (r > 0) per_dispatch.push_back(std::max(batch_ns, 0.0) / static_cast<double>(batch));
        }
        std::sort(per_dispatch.begin(), per_dispatch.end());
        p.min = per_dispatch.front();
        p.median = per_dispatch[per_dispatch.size() / 2];
        p.max = per_dispatch.back();
    }

    // Replays the pair on the same machine with a bsc::logger: its state moved across through
    // the explorer's encoding (the observer is not part of it), its context copied whole (the
    // members the encoding leaves out included).
    void explain(state const& from, std::uint16_t label, pair_latency& p) {
        if constexpr (is_machine<state>) {
            using traced = typename with_observer<state, logger>::type;
            if constexpr (requires(traced & t) { model_.advance(t, label); }) {
                duration period{};
                if constexpr (stepped) period = model_.period();
                std::vector<std::byte> key(codec<state>::key_size);
                codec<state>{period}.encode(from, key.data());
                // The prototype's construction runs the chart's initial entry actions, on a copy
                // of the context: once per measurement.
                if (!prototype_)
                    prototype_.emplace(access::chart(from), from.context(), logger{[](log_record const&) {}});
                traced replay = codec<traced>{period}.decode(*prototype_, key.data());
                access::context(replay) = from.context();
                // (A record's views are valid during the callback only: it is written out there.)
                replay.observer() = logger{[&](log_record const& r) {
                    if (r.what == log_record::kind::dispatch) return;
                    p.exited += r.what == log_record::kind::exit;
                    p.entered += r.what == log_record::kind::entry;
                    p.transitions += r.what == log_record::kind::transition || r.what == log_record::kind::deferral;
                    std::string line = to_string(r);
                    // The record's time and cycle, which say nothing here, are left out.
                    if (auto const at = line.find("] "); line.front() == '[' && at != std::string::npos)
                        line.erase(0, at + 2);
                    p.account.push_back(std::move(line));
                }};
                model_.advance(replay, label);
                p.explained = true;
            }
        }
    }

    Model const& model_;
    latency_options const& options_;
    double clock_ = -1;
    // The machine a pair is replayed on, with a logger (for a model whose state is a machine).
    std::optional<typename with_observer<state, logger>::type> prototype_;
};

}  // namespace detail

/// Measures every (state, event) pair of the states `model` can reach (explored breadth first,
/// at most options.max_states of them). `Model` is a closed model of bsc/verify/models.hpp:
/// an event_model (each listed event dispatched), a cycle_model (each choice of inputs, then one
/// step) or a system_model.
template <class Model>
latency_report measure_latency(Model const& model, latency_options const& options = {}) {
    verify::explorer<Model> ex{model, verify::limits{.max_states = options.max_states}};
    auto const& stats = ex.run();
    std::vector<typename Model::state> starts;
    starts.reserve(ex.count());
    for (std::size_t i = 0; i < ex.count(); ++i) starts.push_back(ex.at(i));
    return detail::latency_run<Model>{model, options}.measure(starts, stats.complete);
}

/// Measures every (state, event) pair of the given states: for a chart too large to explore,
/// the states the user's own scenarios pass through (copies of a machine taken along a run).
/// Each is first brought to the explorer's clock through the explorer's encoding (its times
/// made relative, as an explored state's), so that a model that steps measures one period on
/// from it; the members the encoding leaves out (bsc::transient) take the model's initial
/// values, as in an explored state.
template <class Model>
latency_report measure_latency(Model const& model, std::span<typename Model::state const> starts,
                               latency_options const& options = {}) {
    std::vector<typename Model::state> relative;
    relative.reserve(starts.size());
    std::vector<std::byte> key(Model::key_size);
    for (auto const& s : starts) {
        model.encode(s, key.data());
        relative.push_back(model.decode(key.data()));
    }
    return detail::latency_run<Model>{model, options}.measure(relative, options.starts_are_every_state);
}

/// Registers one Google Benchmark per pair of `report.worst`, named
/// "<prefix>/<event> in <configuration>", which times that pair's dispatch by Google
/// Benchmark's own rules (its repetitions, statistics and output formats); the time reported
/// is that of one dispatch (manual time: each iteration times a batch of dispatches from fresh
/// copies, the copying left out). `report` comes from measure_latency(model) with the same
/// max_states: each pair is found again by name, from the first explored state of its
/// configuration.
template <class Model>
void register_latency_benchmarks(std::string const& prefix, Model const& model, latency_report const& report,
                                 std::size_t max_states = latency_options{}.max_states) {
    verify::explorer<Model> ex{model, verify::limits{.max_states = max_states}};
    ex.run();
    std::uint16_t const labels = detail::label_count(model);
    for (auto const& p : report.worst) {
        bool registered = false;
        for (std::size_t i = 0; i < ex.count() && !registered; ++i) {
            auto const s = ex.at(i);
            if (model.describe(s) != p.configuration) continue;
            for (std::uint16_t label = 0; label < labels && !registered; ++label) {
                if (model.label(label) != p.event) continue;
                registered = true;
                ::benchmark::RegisterBenchmark(
                    (prefix + "/" + p.event + " in " + p.configuration).c_str(),
                    [model, s, label](::benchmark::State& st) {
                        constexpr std::size_t batch = 32;
                        std::vector<typename Model::state> copies(batch, s);
                        for (auto _ : st)
                            st.SetIterationTime(detail::timed_batch(model, copies, s, label) * 1e-9 /
                                                static_cast<double>(batch));
                    })
                    ->UseManualTime();
            }
        }
    }
}

}  // namespace bsc
