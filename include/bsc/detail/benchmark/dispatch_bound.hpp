#pragma once
// The most work one run to completion of a machine (a dispatch, or a cycle) can do, read from
// its chart and its policy alone: what bsc::latency_report::bound holds (bsc/benchmark.hpp).

#include <cstddef>
#include <string>
#include <type_traits>

#include <bsc/detail/model/chart_model.hpp>
#include <bsc/detail/model/layout.hpp>

namespace bsc {

/// A static bound on the work of one run to completion of a machine, from its chart and policy.
struct dispatch_bound {
    /// The most states active at once.
    std::size_t states_at_once = 0;
    /// The most states one transition exits plus enters: every active state below its domain
    /// exits, and as many enter (the SCXML exit and entry sets).
    std::size_t states_per_transition = 0;
    /// A transition that reaches that figure, "Source -> Target".
    std::string widest_transition;
    /// The most transitions that fire in one microstep: one per active basic state in a
    /// dispatch; in a cycle, one per BSC component (the root and each child of a parallel
    /// state) active at once.
    std::size_t transitions_per_microstep = 0;
    /// The most microsteps of one run: the dispatched event or the cycle, then the internal
    /// events (raised, done, retried deferred events) up to the policy's max_internal_events;
    /// in a dispatch whose policy settles eventless transitions and whose chart has any, each
    /// followed by up to max_eventless_steps + 1 of them (the last one reports the livelock).
    std::size_t microsteps = 0;
    /// How `microsteps` is made up, in words.
    std::string microsteps_from;
    /// The most states one run can exit and enter: per microstep, the transitions' exit and
    /// entry sets (at most every active state out and as many in), and where the chart can
    /// halt (a final child of the root), every active state's exit when it does.
    std::size_t states_per_run = 0;
};

}  // namespace bsc

namespace bsc::detail {

// `stepped`: the run is a cycle (step), not a dispatch.
template <class Machine>
dispatch_bound bound_of(bool stepped) {
    using chart_type = typename Machine::chart_type;
    using policy = typename Machine::policy_type;
    using model = chart_model<std::remove_cv_t<chart_type>>;
    constexpr auto const& tree = model::tree;
    constexpr auto const& rows = model::rows;
    constexpr int n = model::N;
    constexpr int root = 1;  // index 0 is the implicit top above the root
    // In s's subtree, s included, at once: span, the most states active; leaves, the most
    // basic states active; regions, the most children of parallel states active. Children
    // follow their parents in the numbering, so a backward pass sees every child first.
    std::size_t span[static_cast<std::size_t>(n)] = {};
    std::size_t leaves[static_cast<std::size_t>(n)] = {};
    std::size_t regions[static_cast<std::size_t>(n)] = {};
    for (int s = n - 1; s >= 0; --s) {
        auto const i = static_cast<std::size_t>(s);
        if (tree.kinds[i] == kind::history) continue;  // a marker, never active itself
        bool const parallel = tree.kinds[i] == kind::parallel;
        std::size_t all_span = 0, most_span = 0, all_leaves = 0, most_leaves = 0, all_regions = 0, most_regions = 0;
        for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)]) {
            auto const k = static_cast<std::size_t>(c);
            if (tree.kinds[k] == kind::history) continue;
            all_span += span[k];
            most_span = span[k] > most_span ? span[k] : most_span;
            all_leaves += leaves[k];
            most_leaves = leaves[k] > most_leaves ? leaves[k] : most_leaves;
            all_regions += 1 + regions[k];
            most_regions = regions[k] > most_regions ? regions[k] : most_regions;
        }
        span[i] = 1 + (parallel ? all_span : most_span);
        leaves[i] = parallel ? all_leaves : most_leaves;
        if (leaves[i] == 0) leaves[i] = 1;
        regions[i] = parallel ? all_regions : most_regions;
    }
    dispatch_bound b;
    b.states_at_once = span[root];
    b.transitions_per_microstep = stepped ? 1 + regions[root] : leaves[root];
    constexpr auto const& names = state_names_of<model>;
    for (std::size_t r = 0; r < rows.kinds.size(); ++r) {
        if (rows.kinds[r] != row_kind::transition) continue;
        if (rows.target[r] < 0 || rows.domain[r] < 0) continue;  // internal: nothing exits or enters
        std::size_t const moved = 2 * (span[static_cast<std::size_t>(rows.domain[r])] - 1);
        if (moved > b.states_per_transition) {
            b.states_per_transition = moved;
            b.widest_transition = std::string(names[static_cast<std::size_t>(rows.source[r])]) + " -> " +
                                  std::string(names[static_cast<std::size_t>(rows.target[r])]);
        }
    }
    using layout = chart_layout<model>;
    bool const eventless = layout::has_trigger(eventless_id);

    // Raised and done events, and deferred events retried, count against one limit.
    std::size_t const internal = Machine::queue_capacity > 0 || model::has_deferral ? policy::max_internal_events : 0;
    std::string from = stepped ? "1 cycle" : "1 dispatched event";
    if (internal > 0) from += " + " + std::to_string(internal) + " internal events (max_internal_events)";
    // A cycle leaves eventless transitions to the components; a dispatch settles them where
    // the policy says so.
    std::size_t each = 1;
    if (!stepped && eventless && policy::settle_eventless) {
        each += policy::max_eventless_steps + 1;
        from = "(" + from + ") x (1 + " + std::to_string(policy::max_eventless_steps + 1) +
               " eventless transitions (max_eventless_steps + 1))";
    }
    b.microsteps = (1 + internal) * each;
    b.microsteps_from = from;
    // One microstep moves at most its transitions' sets, and never more than every active
    // state out and as many in.
    std::size_t const per_microstep = b.transitions_per_microstep * b.states_per_transition < 2 * b.states_at_once
                                          ? b.transitions_per_microstep * b.states_per_transition
                                          : 2 * b.states_at_once;
    b.states_per_run = b.microsteps * per_microstep + (layout::can_halt ? b.states_at_once : 0);
    return b;
}

}  // namespace bsc::detail
