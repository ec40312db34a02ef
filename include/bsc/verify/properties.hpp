#pragma once
// Properties checked on an explored state graph, each with a verdict and, when it fails, a
// shortest counterexample in the chart's own names: deadlock freedom, invariants (A[] p),
// reachability (E<> p), reinitiability and leads-to (p --> q).

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <bsc/detail/delay_label.hpp>
#include <bsc/duration.hpp>
#include <bsc/verify/explorer.hpp>

namespace bsc::detail {
// `now` as written, except that when every word of it is name=value (the inputs of a cycle),
// only the words not in `before` are kept: what changed ("(inputs unchanged)" if nothing did).
inline std::string changed_words(std::string const& before, std::string const& now) {
    auto const words = [](std::string const& text) {
        std::vector<std::string> out;
        for (std::size_t at = 0; at < text.size();) {
            std::size_t const end = std::min(text.find(' ', at), text.size());
            if (end > at) out.push_back(text.substr(at, end - at));
            at = end + 1;
        }
        return out;
    };
    auto const new_words = words(now);
    auto const assignment = [](std::string const& w) {
        auto const eq = w.find('=');
        return eq != std::string::npos && eq > 0 && eq + 1 < w.size();
    };
    if (new_words.empty() || !std::all_of(new_words.begin(), new_words.end(), assignment)) return now;
    auto const old_words = words(before);
    std::string out;
    for (auto const& w : new_words)
        if (std::find(old_words.begin(), old_words.end(), w) == old_words.end()) out += (out.empty() ? "" : " ") + w;
    return out.empty() ? "(inputs unchanged)" : out;
}
}  // namespace bsc::detail

namespace bsc::verify {

/// One step of a trace: what was applied (an event, an input choice) and the configuration after;
/// for a model stepped with a period (cycle_model, system_model), the time of the step from the
/// initial state (step k at k periods).
struct trace_step {
    std::string label;
    std::string configuration;
    std::optional<duration> time;
};

/// The outcome of one property.
struct verdict {
    enum class status { holds, fails, inconclusive };
    std::string property;
    status result = status::inconclusive;
    std::vector<trace_step> trace;  ///< counterexample (or witness, for reachability)
    std::string detail;             ///< e.g. where a leads-to counterexample starts to loop

    bool holds() const { return result == status::holds; }
    bool fails() const { return result == status::fails; }

    /// A readable report: the verdict, then the trace one step per line, with its time when the
    /// model has one. A label made of `name=value` words only (the inputs of a cycle) shows the
    /// words that changed since the step before. A run of steps that repeat the one before them
    /// (the same label, the same configuration; variables and timers may still change) is one
    /// line: "5-16. [500ms-1600ms] 12 steps, same inputs and configuration".
    std::string to_string() const {
        std::string out = property + ": " +
                          (result == status::holds   ? "holds"
                           : result == status::fails ? "FAILS"
                                                     : "inconclusive");
        if (!detail.empty()) out += " (" + detail + ")";
        out += '\n';
        auto const repeats = [&](std::size_t k) {
            return k > 0 && trace[k].label == trace[k - 1].label &&
                   trace[k].configuration == trace[k - 1].configuration;
        };
        for (std::size_t i = 0; i < trace.size();) {
            std::size_t end = i + 1;
            while (repeats(i) && end < trace.size() && repeats(end)) ++end;
            if (end - i >= 2) {
                out += "  " + std::to_string(i) + "-" + std::to_string(end - 1) + ". ";
                if (trace[i].time && trace[end - 1].time)
                    out += "[" + bsc::detail::delay_label(*trace[i].time) + "-" +
                           bsc::detail::delay_label(*trace[end - 1].time) + "] ";
                out += std::to_string(end - i) + " steps, same inputs and configuration\n";
            } else {
                out += "  " + std::to_string(i) + ". ";
                if (trace[i].time) out += "[" + bsc::detail::delay_label(*trace[i].time) + "] ";
                out += bsc::detail::changed_words(i > 0 ? trace[i - 1].label : std::string{}, trace[i].label) + " -> " +
                       trace[i].configuration + '\n';
            }
            i = end;
        }
        return out;
    }
};

}  // namespace bsc::verify

namespace bsc::detail {

// An argument a property cannot work with: thrown, or printed before aborting where exceptions
// are disabled.
[[noreturn]] inline void refuse_argument(char const* why) {
#if defined(__cpp_exceptions)
    throw std::invalid_argument(why);
#else
    std::fputs(why, stderr);
    std::fputs("\n", stderr);
    std::abort();
#endif
}

// Whether the model is stepped with a fixed period, which gives its traces their times.
template <class Model>
concept timed_model = requires(Model const& m) {
    { m.period() } -> std::convertible_to<duration>;
};

template <class Model>
void append_step(verify::explorer<Model> const& ex, std::vector<verify::trace_step>& out, std::string label,
                 std::size_t i) {
    std::optional<duration> time;
    if constexpr (timed_model<Model>) time = static_cast<duration::rep>(out.size()) * ex.model().period();
    out.push_back({std::move(label), ex.model().describe(ex.at(i)), time});
}

// The shortest path from the initial state to state i (breadth-first tree).
template <class Model>
std::vector<verify::trace_step> path_to(verify::explorer<Model> const& ex, std::size_t i) {
    std::vector<std::size_t> chain;
    for (std::size_t s = i; s != verify::explorer<Model>::none; s = ex.parent(s)) chain.push_back(s);
    std::vector<verify::trace_step> out;
    for (std::size_t k = chain.size(); k-- > 0;) {
        std::size_t const s = chain[k];
        append_step(ex, out, k + 1 == chain.size() ? "(initial)" : ex.model().label(ex.parent_label(s)), s);
    }
    return out;
}

template <class Model>
verify::verdict incomplete(verify::explorer<Model> const& ex, std::string property) {
    std::string why = "exploration stopped by " + ex.stats().stopped_by;
    if (!ex.stats().widest.empty())
        why += "; the parts of the state with the most distinct values: " + ex.stats().widest_text();
    verify::verdict v{std::move(property), verify::verdict::status::inconclusive, {}, std::move(why)};
    return v;
}

}  // namespace bsc::detail

namespace bsc::verify {

/// A[] p: p holds in every reachable state. `p` takes the model's state.
template <class Model, class Pred>
verdict always(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    for (std::size_t i = 0; i < ex.count(); ++i)
        if (!p(ex.at(i))) return {"A[] " + name, verdict::status::fails, detail::path_to(ex, i), {}};
    if (!ex.stats().complete) return detail::incomplete(ex, "A[] " + name);
    return {"A[] " + name, verdict::status::holds, {}, {}};
}

/// E<> p: some reachable state satisfies p; the trace is a shortest witness.
template <class Model, class Pred>
verdict reachable(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    for (std::size_t i = 0; i < ex.count(); ++i)
        if (p(ex.at(i))) return {"E<> " + name, verdict::status::holds, detail::path_to(ex, i), {}};
    if (!ex.stats().complete) return detail::incomplete(ex, "E<> " + name);
    return {"E<> " + name, verdict::status::fails, {}, {}};
}

/// Every reachable state has a successor other than itself, unless `is_final` holds in it.
template <class Model, class Final>
verdict deadlock_free(explorer<Model>& ex, Final is_final) {
    ex.run();
    std::string const name = "deadlock freedom";
    for (std::size_t i = 0; i < ex.count(); ++i) {
        bool moves = false;
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i) && !moves; ++e) moves = ex.edge_target(e) != i;
        if (!moves && !is_final(ex.at(i)) && (ex.stats().complete || ex.edges_end(i) > ex.edges_begin(i)))
            return {name, verdict::status::fails, detail::path_to(ex, i), "no successor but itself"};
    }
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    return {name, verdict::status::holds, {}, {}};
}

template <class Model>
verdict deadlock_free(explorer<Model>& ex) {
    return deadlock_free(ex, [](auto const&) { return false; });
}

}  // namespace bsc::verify

namespace bsc::detail {
// The graph's edges reversed, as adjacency arrays: the predecessors of i are
// from[begin[i]] .. from[begin[i + 1] - 1] (one entry per edge).
struct reverse_graph {
    std::vector<std::uint32_t> begin, from;
};
template <class Model>
reverse_graph reversed(verify::explorer<Model> const& ex) {
    std::size_t const n = ex.count();
    reverse_graph g{std::vector<std::uint32_t>(n + 1, 0), std::vector<std::uint32_t>(ex.stats().transitions)};
    for (std::size_t i = 0; i < n; ++i)
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i); ++e) ++g.begin[ex.edge_target(e) + 1];
    for (std::size_t i = 0; i < n; ++i) g.begin[i + 1] += g.begin[i];
    std::vector<std::uint32_t> fill(g.begin.begin(), g.begin.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        for (auto e = ex.edges_begin(i); e < ex.edges_end(i); ++e)
            g.from[fill[ex.edge_target(e)]++] = static_cast<std::uint32_t>(i);
    return g;
}

// The first state (in breadth-first order, so with a shortest path to it) from which no
// state marked in `goal` can be reached, or none.
template <class Model>
std::size_t first_cut_off(verify::explorer<Model> const& ex, std::vector<char> const& goal) {
    std::size_t const n = ex.count();
    reverse_graph const g = reversed(ex);
    std::vector<char> back(n, 0);
    std::vector<std::uint32_t> queue;
    for (std::size_t i = 0; i < n; ++i)
        if (goal[i]) {
            back[i] = 1;
            queue.push_back(static_cast<std::uint32_t>(i));
        }
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (auto e = g.begin[queue[k]]; e < g.begin[queue[k] + 1]; ++e)
            if (!back[g.from[e]]) {
                back[g.from[e]] = 1;
                queue.push_back(g.from[e]);
            }
    for (std::size_t i = 0; i < n; ++i)
        if (!back[i]) return i;
    return verify::explorer<Model>::none;
}

// No path bound: a state from which some path never reaches q (a cycle or a dead end without q).
inline constexpr std::size_t never = static_cast<std::size_t>(-1);

// For each state, the most steps a path from it can take before it reaches a state marked in
// `is_q` (0 for those), or `never`. The least fixpoint, by a backward worklist from q: a state
// with successors is settled when its last successor is, one step beyond the slowest of them.
template <class Model>
std::vector<std::size_t> steps_to(verify::explorer<Model> const& ex, std::vector<char> const& is_q) {
    std::size_t const n = ex.count();
    std::vector<std::size_t> slowest(n, never);
    std::vector<std::uint32_t> unsettled(n), queue;
    for (std::size_t i = 0; i < n; ++i) {
        unsettled[i] = ex.edges_end(i) - ex.edges_begin(i);
        if (is_q[i]) {
            slowest[i] = 0;
            queue.push_back(static_cast<std::uint32_t>(i));
        }
    }
    reverse_graph const g = reversed(ex);
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (auto e = g.begin[queue[k]]; e < g.begin[queue[k] + 1]; ++e) {
            std::uint32_t const i = g.from[e];
            if (slowest[i] != never || --unsettled[i] != 0) continue;
            std::size_t most = 0;  // every successor is settled, so finite
            for (auto f = ex.edges_begin(i); f < ex.edges_end(i); ++f)
                most = std::max(most, slowest[ex.edge_target(f)]);
            slowest[i] = most + 1;
            queue.push_back(i);
        }
    return slowest;
}
}  // namespace bsc::detail

namespace bsc::verify {

/// AG EF p: from every reachable state, some path reaches a p-state (the vivacity of the Basic
/// Statechart paper [BSC], docs/references.md, for p = "the device operates"). Fails with a path
/// to a state from which p is out of reach.
template <class Model, class Pred>
verdict always_reachable(explorer<Model>& ex, std::string name, Pred p) {
    ex.run();
    name = "AG EF " + name;
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::vector<char> goal(ex.count());
    for (std::size_t i = 0; i < ex.count(); ++i) goal[i] = p(ex.at(i));
    std::size_t const cut = detail::first_cut_off(ex, goal);
    if (cut != explorer<Model>::none)
        return {name, verdict::status::fails, detail::path_to(ex, cut), "unreachable from the last state"};
    return {name, verdict::status::holds, {}, {}};
}

/// The initial state is reachable from every reachable state (the reinitiability of [BSC]).
template <class Model>
verdict reinitiable(explorer<Model>& ex) {
    ex.run();
    std::string const name = "reinitiability";
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::vector<char> goal(ex.count(), 0);
    goal[0] = 1;
    std::size_t const cut = detail::first_cut_off(ex, goal);
    if (cut != explorer<Model>::none)
        return {name, verdict::status::fails, detail::path_to(ex, cut),
                "the initial state is unreachable from the last state"};
    return {name, verdict::status::holds, {}, {}};
}

/// Reinitiability up to an equivalence: from every reachable state, a state `equivalent` to the
/// initial one can be reached, e.g. the same active configuration whatever the variables
/// (the reachability tree of [BSC] is over configurations). `equivalent(state, initial)`.
template <class Model, class Equivalent>
verdict reinitiable(explorer<Model>& ex, Equivalent equivalent) {
    ex.run();
    auto const initial = ex.at(0);
    verdict v = always_reachable(ex, "", [&](auto const& s) { return equivalent(s, initial); });
    v.property = "reinitiability (up to equivalence)";
    return v;
}

/// p --> q: from every reachable p-state, every path reaches a q-state. No fairness is
/// assumed: a cycle of non-q states, or a deadlock, after a p-state is a counterexample
/// (the trace ends where the loop closes).
template <class Model, class P, class Q>
verdict leads_to(explorer<Model>& ex, std::string name, P p, Q q) {
    ex.run();
    name = name.empty() ? "p --> q" : name;
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::size_t const n = ex.count();
    std::vector<char> is_q(n), is_p(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto const s = ex.at(i);
        is_q[i] = q(s);
        is_p[i] = p(s);
    }
    // sure[i]: every path from i reaches q.
    std::vector<std::size_t> const slowest = detail::steps_to(ex, is_q);
    auto const sure = [&](std::size_t i) { return slowest[i] != detail::never; };
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_p[i] || sure(i)) continue;
        auto trace = detail::path_to(ex, i);
        // Continue through states that can avoid q until one repeats or nothing follows.
        std::vector<char> seen(n, 0);
        std::size_t s = i;
        seen[s] = 1;
        std::string how = "no successor";
        for (;;) {
            std::size_t next = n;
            std::uint16_t label = 0;
            for (auto e = ex.edges_begin(s); e < ex.edges_end(s); ++e)
                if (!sure(ex.edge_target(e))) {
                    next = ex.edge_target(e);
                    label = ex.edge_label(e);
                    break;
                }
            if (next == n) break;
            detail::append_step(ex, trace, ex.model().label(label), next);
            if (seen[next]) {
                how = "loops without reaching q";
                break;
            }
            seen[next] = 1;
            s = next;
        }
        return {name, verdict::status::fails, std::move(trace),
                "from step " + std::to_string(detail::path_to(ex, i).size() - 1) + ": " + how};
    }
    return {name, verdict::status::holds, {}, {}};
}

/// p --> q within `bound`: from every reachable p-state, every path reaches a q-state within
/// `bound` (a q-state reached `bound` after p counts; so does q holding in the p-state itself).
/// What a safety engineer asks of a controller: "the press stops within 200 ms of the guard
/// opening". Time is the model's steps: the model is stepped with a period (cycle_model,
/// system_model), and `bound` covers floor(bound / period) steps. A deadlock or a cycle of non-q
/// states after a p-state also fails it. The counterexample runs to the p-state by a shortest
/// path, then along the slowest way to q for one step more than the bound allows.
template <class Model, class P, class Q>
verdict leads_to_within(explorer<Model>& ex, std::string name, P p, Q q, duration bound) {
    static_assert(detail::timed_model<Model>,
                  "bsc::verify::leads_to_within needs a model stepped with a period (cycle_model, system_model): "
                  "a bound in time has no meaning for an event_model");
    if (bound < duration::zero()) detail::refuse_argument("bsc::verify::leads_to_within: the bound is negative");
    if (ex.model().period() <= duration::zero())
        detail::refuse_argument("bsc::verify::leads_to_within: the model's period is not positive");
    ex.run();
    name = (name.empty() ? "p --> q" : name) + " within " + bsc::detail::delay_label(bound);
    if (!ex.stats().complete) return detail::incomplete(ex, name);
    std::size_t const n = ex.count();
    auto const steps = static_cast<std::size_t>(bound / ex.model().period());
    std::vector<char> is_p(n), is_q(n);
    for (std::size_t i = 0; i < n; ++i) {
        auto const s = ex.at(i);
        is_p[i] = p(s);
        is_q[i] = q(s);
    }
    std::vector<std::size_t> const slowest = detail::steps_to(ex, is_q);
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_p[i] || slowest[i] <= steps) continue;
        auto trace = detail::path_to(ex, i);
        std::size_t const start = trace.size() - 1;
        // Follow the slowest successor until the bound is passed, or a deadlock or a loop; among
        // equally slow ones, an unseen state, then the choice of the step before (so that a run
        // of the same choice folds into one line of the report).
        std::vector<char> seen(n, 0);
        std::size_t s = i;
        seen[s] = 1;
        std::uint16_t previous = i == 0 ? std::uint16_t{0} : ex.parent_label(i);
        std::string how = "q does not hold " + bsc::detail::delay_label(bound) + " later";
        for (std::size_t taken = 0; taken <= steps; ++taken) {
            std::size_t next = n;
            std::uint16_t label = 0;
            auto const better = [&](std::size_t t, std::uint16_t l) {
                if (next == n || slowest[t] != slowest[next]) return next == n || slowest[t] > slowest[next];
                if (seen[t] != seen[next]) return !seen[t];
                return l == previous && label != previous;
            };
            for (auto e = ex.edges_begin(s); e < ex.edges_end(s); ++e)
                if (better(ex.edge_target(e), ex.edge_label(e))) {
                    next = ex.edge_target(e);
                    label = ex.edge_label(e);
                }
            if (next == n) {
                how = "no successor, q never holds";
                break;
            }
            detail::append_step(ex, trace, ex.model().label(label), next);
            if (seen[next] && taken < steps) {
                how = "loops without reaching q";
                break;
            }
            seen[next] = 1;
            s = next;
            previous = label;
        }
        return {name, verdict::status::fails, std::move(trace),
                "p holds at step " + std::to_string(start) + "; " + how};
    }
    return {name, verdict::status::holds, {}, {}};
}

}  // namespace bsc::verify
