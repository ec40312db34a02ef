#pragma once
// The most work one dispatch (or one cycle) of a machine can do, read from its chart and its
// policy alone: what bsc::latency_report::bound holds (bsc/benchmark.hpp).

#include <cstddef>
#include <string>
#include <type_traits>

#include <bsc/detail/model/chart_model.hpp>
#include <bsc/detail/type_name.hpp>

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
    /// The most transitions that fire together in one microstep: one per orthogonal component.
    std::size_t components = 0;
    /// The most microsteps of one run to completion: the dispatched event (or the cycle), then
    /// the internal events (raised, done, retried deferred events) up to the policy's
    /// max_internal_events, each followed, where the chart has eventless transitions and the
    /// policy settles them, by up to max_eventless_steps + 1 of them (the last one reports the
    /// livelock).
    std::size_t microsteps = 0;
    /// How `microsteps` is made up, in words.
    std::string microsteps_from;
};

}  // namespace bsc

namespace bsc::detail {

template <class Machine>
dispatch_bound bound_of() {
    using chart_type = typename Machine::chart_type;
    using policy = typename Machine::policy_type;
    using model = chart_model<std::remove_cv_t<chart_type>>;
    constexpr auto const& tree = model::tree;
    constexpr auto const& rows = model::rows;
    constexpr int n = model::N;
    // span[s]: the most states active at once in s's subtree, s included; leaves[s]: the most
    // leaves (orthogonal components) active at once there. Children follow their parents in
    // the numbering, so a backward pass sees every child first.
    std::size_t span[static_cast<std::size_t>(n)] = {};
    std::size_t leaves[static_cast<std::size_t>(n)] = {};
    for (int s = n - 1; s >= 0; --s) {
        auto const i = static_cast<std::size_t>(s);
        if (tree.kinds[i] == kind::history) continue;  // a marker, never active itself
        std::size_t sum = 0, most = 0, sum_leaves = 0, most_leaves = 0;
        for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)]) {
            auto const k = static_cast<std::size_t>(c);
            sum += span[k];
            most = span[k] > most ? span[k] : most;
            sum_leaves += leaves[k];
            most_leaves = leaves[k] > most_leaves ? leaves[k] : most_leaves;
        }
        bool const parallel = tree.kinds[i] == kind::parallel;
        span[i] = 1 + (parallel ? sum : most);
        leaves[i] = (parallel ? sum_leaves : most_leaves);
        if (leaves[i] == 0) leaves[i] = 1;
    }
    dispatch_bound b;
    // Index 0 is the implicit top above the root: it is never exited, so it does not count.
    b.states_at_once = span[0] - 1;
    b.components = leaves[0];
    constexpr auto const& names = state_names_of<model>;
    bool eventless = false;
    for (std::size_t r = 0; r < rows.kinds.size(); ++r) {
        if (rows.kinds[r] != row_kind::transition) continue;
        if (rows.trigger[r] == eventless_id) eventless = true;
        if (rows.target[r] < 0 || rows.domain[r] < 0) continue;  // internal: nothing exits or enters
        std::size_t const moved = 2 * (span[static_cast<std::size_t>(rows.domain[r])] - 1);
        if (moved > b.states_per_transition) {
            b.states_per_transition = moved;
            b.widest_transition = std::string(names[static_cast<std::size_t>(rows.source[r])]) + " -> " +
                                  std::string(names[static_cast<std::size_t>(rows.target[r])]);
        }
    }
    bool defers = false;
    for (bool const d : rows.defers) defers = defers || d;
    // Raised and done events, and deferred events retried, count against one limit.
    std::size_t const internal = Machine::queue_capacity > 0 || defers ? policy::max_internal_events : 0;
    std::string from = policy::settle_eventless ? "1 dispatched event" : "1 cycle (one transition per component)";
    if (internal > 0) from += " + " + std::to_string(internal) + " internal events (max_internal_events)";
    // The eventless transitions after each: up to max_eventless_steps, and one more, which
    // reports the livelock. A scan policy leaves them to the next cycle.
    std::size_t each = 1;
    if (eventless && policy::settle_eventless) {
        each += policy::max_eventless_steps + 1;
        from = "(" + from + ") x (1 + " + std::to_string(policy::max_eventless_steps + 1) +
               " eventless transitions (max_eventless_steps + 1))";
    }
    b.microsteps = (1 + internal) * each;
    b.microsteps_from = from;
    return b;
}

}  // namespace bsc::detail
