#pragma once
// Properties checked on an explored state graph, each with a verdict and, when it fails, a
// shortest counterexample in the chart's own names: deadlock freedom, invariants (A[] p),
// reachability (E<> p), reinitiability and leads-to (p --> q).

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <bsc/verify/explorer.hpp>

namespace bsc::verify {

/// One step of a trace: what was applied (an event, an input choice) and the configuration after.
struct trace_step {
    std::string label;
    std::string configuration;
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

    /// A readable report: the verdict, then the trace one step per line.
    std::string to_string() const {
        std::string out = property + ": " +
                          (result == status::holds ? "holds" : result == status::fails ? "FAILS" : "inconclusive");
        if (!detail.empty()) out += " (" + detail + ")";
        out += '\n';
        for (std::size_t i = 0; i < trace.size(); ++i)
            out += "  " + std::to_string(i) + ". " + trace[i].label + " -> " + trace[i].configuration + '\n';
        return out;
    }
};

}  // namespace bsc::verify

namespace bsc::detail {

template <class Model>
void append_step(verify::explorer<Model> const& ex, std::vector<verify::trace_step>& out, std::string label, std::size_t i) {
    out.push_back({std::move(label), ex.model().describe(ex.at(i))});
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
    verify::verdict v{std::move(property), verify::verdict::status::inconclusive, {}, "exploration stopped by " + ex.stats().stopped_by};
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
    std::vector<char> is_q(n), is_p(n), sure(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        auto const s = ex.at(i);
        is_q[i] = q(s);
        is_p[i] = p(s);
    }
    // sure[i]: every path from i reaches q. The least fixpoint, by a backward worklist: a
    // state with successors becomes sure when its last unsure successor does.
    detail::reverse_graph const g = detail::reversed(ex);
    std::vector<std::uint32_t> unsure_successors(n), queue;
    for (std::size_t i = 0; i < n; ++i) {
        unsure_successors[i] = ex.edges_end(i) - ex.edges_begin(i);
        if (is_q[i]) {
            sure[i] = 1;
            queue.push_back(static_cast<std::uint32_t>(i));
        }
    }
    for (std::size_t k = 0; k < queue.size(); ++k)
        for (auto e = g.begin[queue[k]]; e < g.begin[queue[k] + 1]; ++e) {
            std::uint32_t const i = g.from[e];
            if (!sure[i] && --unsure_successors[i] == 0) {
                sure[i] = 1;
                queue.push_back(i);
            }
        }
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_p[i] || sure[i]) continue;
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
                if (!sure[ex.edge_target(e)]) {
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

}  // namespace bsc::verify
