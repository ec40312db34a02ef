#pragma once
// The operation rules of the table-driven runtime: a chart as the two constant tables of the
// machine-tool paper [MCS] (docs/references.md, section 3.3.1), the topology table (the paper's
// BSTATE, one row per state) and the transition table (BTRANS, one row per transition). The
// chart's guards, actions, entry and exit actions are reached through plain function pointers:
// one small generated function ("thunk") per row, which receives the chart object and the
// context and calls the row's callable. Everything here is computed by the compiler from the
// chart model; bsc::table::machine interprets it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <utility>

#include <bsc/chart.hpp>
#include <bsc/detail/meta.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/detail/model/configuration_view.hpp>
#include <bsc/detail/model/layout.hpp>
#include <bsc/outcome.hpp>
#include <bsc/policies.hpp>
#include <bsc/detail/runtime/queue_for.hpp>
#include <bsc/detail/runtime/failures.hpp>

namespace bsc::table {

/// A state's number: its row in the topology table. Row 0 is the implicit top above the
/// chart's root (the paper's ancestor 0 of MCS); since the top is nobody's child or sibling,
/// 0 (no_state) also means "none" in the first_child, next_sibling, initial and `to` columns.
using state_id = std::uint16_t;
inline constexpr state_id no_state = 0;

/// An event's number: the position of its type in the machine's event_types.
using event_id = std::int16_t;
inline constexpr event_id eventless_id = -1;  ///< a transition without an event
inline constexpr event_id timeout_id = -2;    ///< a timeout transition, taken by a BSC cycle only

/// Eventless and timeout transitions are condition-driven: the ones a BSC cycle considers.
constexpr bool is_condition(event_id event) { return event < 0; }

/// The paper's status column, in the words of the DSL: the kind of state and its history.
enum class state_kind : std::uint8_t {
    top,          ///< the implicit state above the root (row 0)
    basic,        ///< an atomic state
    final_state,  ///< an atomic state that ends its parent (the root: the machine halts)
    composite,    ///< exactly one child active (the paper's hierarchical, or OR, state)
    parallel,     ///< all children active (the paper's concurrent, or AND, state)
    history,      ///< a history pseudo-state of its parent composite: never active
};
enum class history_kind : std::uint8_t { none, shallow, deep };

struct state_status {
    state_kind kind = state_kind::basic;
    history_kind history = history_kind::none;
    friend constexpr bool operator==(state_status, state_status) = default;
};

/// One row of the topology table (the paper's BSTATE, Figure 7, whose descendant, sibling and
/// ancestor columns are first_child, next_sibling and parent here), then the columns the
/// engine would otherwise recompute by walking the tree.
template <class Chart, class Raise>
struct state_row {
    using context_type = typename Chart::context_type;
    /// Runs the state's entry (or exit) actions, in declaration order; each is one block, and
    /// what one throws goes to `failures` before the next runs.
    using state_action = void (*)(Chart const& chart, context_type& context, Raise& raise,
                                  bsc::detail::failure_sink const& failures);

    state_id state = no_state;         ///< this row's number
    state_id first_child = no_state;   ///< first child in document order (BSTATE's descendant)
    state_id next_sibling = no_state;  ///< next sibling in document order (BSTATE's sibling)
    state_id parent = no_state;        ///< parent, 0 (the top) for the root (BSTATE's ancestor)
    state_status status{};
    state_action entry = nullptr;           ///< null: no entry action
    state_action exit = nullptr;            ///< null: no exit action
    state_action initial_action = nullptr;  ///< a composite's initial transition's actions (on_initial); null: none

    // Derived columns.
    state_id initial = no_state;         ///< default child of a composite (of a history state: its default's path)
    state_id initial_target = no_state;  ///< its initial state: `initial`, or a descendant below it (a deep initial)
    std::array<state_id, 3>
        more_initial{};              ///< its initial states after the first (`initial<A, B>`); no_state where fewer
    std::uint16_t ordinal = 0;       ///< position among its siblings: the configuration entry that selects it
    std::int16_t slot = -1;          ///< the byte of the configuration a composite owns, -1 for others
    state_id end = 0;                ///< one past its last descendant: d is below s iff s < d < end
    std::int16_t timeout_slot = -1;  ///< the first slot of its timeout rows (see transition_row), else -1
    std::int16_t timeout_slots = 0;  ///< how many of its rows are timeouts: its slots follow the first
};

/// One row of the transition table (the paper's BTRANS, Figure 8).
template <class Chart, class Raise>
struct transition_row {
    using context_type = typename Chart::context_type;
    /// Whether a guard of the chart tests the configuration (bsc::in<S>): then every guard
    /// receives the configuration bytes too (bsc::configuration::active, null for a chart without
    /// composites), and the guards of other charts do not.
    static constexpr bool guards_read_configuration =
        bsc::detail::any_row_tests_configuration<typename Chart::row_types>;
    /// The guard, called with the event the transition is triggered by (bsc::eventless{} for
    /// eventless transitions) passed as `event`, and in a chart with bsc::in<S> with the
    /// configuration bytes as `active`.
    using guard_fn = std::conditional_t<guards_read_configuration,
                                        bool (*)(Chart const& chart, context_type const& context, void const* event,
                                                 typename bsc::detail::chart_model<Chart>::ordinal_type const* active),
                                        bool (*)(Chart const& chart, context_type const& context, void const* event)>;
    using action_fn = void (*)(Chart const& chart, context_type& context, void const* event, Raise& raise);
    /// The delay of a timeout. `after(d)` stores d in the chart object, not in its type, so the
    /// delay is read from the chart like a guard.
    using delay_fn = duration (*)(Chart const& chart);

    state_id from = no_state;       ///< origin state
    event_id event = eventless_id;  ///< trigger, or `eventless_id` / `timeout_id`
    state_id to = no_state;         ///< destination state; no_state: an internal transition
    guard_fn guard = nullptr;       ///< null: unguarded
    action_fn action = nullptr;     ///< null: no action
    state_id domain = no_state;     ///< the transition domain: the state whose active descendants it exits
    delay_fn delay = nullptr;       ///< a timeout's delay; null for the other transitions
    /// A timeout's slot: where the machine keeps the time its delay counts from (its origin's
    /// entry, or for an internal timeout the cycle it last fired in); -1 for the others.
    std::int16_t timeout_slot = -1;
    bool defers = false;  ///< the row defers its event (`/ bsc::defer`): it keeps the event, and has no action
    bool rearms = false;  ///< a timeout that leaves its source active: it counts again from when it fires
    /// A transition with several targets (bsc::targets): the others after `to`; no_state where
    /// there are fewer.
    std::array<state_id, 3> more_to{};
};

/// The operation rules of `Chart`: its topology table `states` and transition table
/// `transitions`, plus the indexes the engine uses to read them. `Policy` only fixes the
/// capacity of the queue that actions raise events into (the `Raise` argument of the thunks).
template <class Chart, class Policy = default_policy>
struct tables {
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    using raise_type = bsc::detail::queue_for<chart_type, Policy>;
    using state_row_type = state_row<chart_type, raise_type>;
    using transition_row_type = transition_row<chart_type, raise_type>;

private:
    using model = bsc::detail::chart_model<chart_type>;
    using layout = bsc::detail::chart_layout<model>;
    using row_kind = bsc::detail::row_kind;
    static constexpr auto const& tree = model::tree;
    static constexpr auto const& rows = model::rows;

    // The event type a transition row's guard and action receive.
    template <int Row>
    using event_type_of = bsc::detail::row_event_t<typename model::template row_at<Row>>;

    // ---- the thunks: one per state and per transition ---------------------------------------
    template <row_kind K, int S>
    static void state_thunk(chart_type const& chart, context_type& context, raise_type& raise,
                            bsc::detail::failure_sink const& failures) {
        constexpr auto const& actions = layout::template rows_of<K, S>;
        auto const report = [&](std::exception_ptr error) { failures.report(failures.machine, std::move(error)); };
        // clang-format off
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (bsc::detail::run_block(
                 [&] { bsc::detail::row_at<static_cast<std::size_t>(actions[I])>(chart.rows).action(context, raise); },
                 report),
             ...);
        }(std::make_index_sequence<actions.size()>{});
        // clang-format on
    }

    template <int Row>
    static bool guard_thunk(chart_type const& chart, context_type const& context, void const* event) {
        return static_cast<bool>(bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows)
                                     .guard(context, *static_cast<event_type_of<Row> const*>(event)));
    }
    // The thunk of a guard in a chart with bsc::in<S>: a guard that tests the configuration sees
    // it through the view of its row (detail/model/configuration_view.hpp, tests resolved at
    // compile time), the others ignore it.
    template <int Row>
    static bool configuration_guard_thunk(chart_type const& chart, context_type const& context, void const* event,
                                          [[maybe_unused]] typename model::ordinal_type const* active) {
        auto const& guard = bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows).guard;
        auto const& e = *static_cast<event_type_of<Row> const*>(event);
        using view = bsc::detail::configuration_view<model, rows.source[Row]>;
        if constexpr (bsc::detail::tests_configuration<std::remove_cvref_t<decltype(guard)>>)
            return static_cast<bool>(guard(context, e, view{active}));
        else
            return static_cast<bool>(guard(context, e));
    }

    template <int Row>
    static void action_thunk(chart_type const& chart, context_type& context, void const* event, raise_type& raise) {
        bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows)
            .action(context, *static_cast<event_type_of<Row> const*>(event), raise);
    }

    template <int Row>
    static duration delay_thunk(chart_type const& chart) {
        return bsc::detail::row_at<static_cast<std::size_t>(Row)>(chart.rows).trigger_value.delay;
    }

    template <row_kind K, int S>
    static constexpr typename state_row_type::state_action state_action_of() {
        if constexpr (layout::template rows_of<K, S>.size() == 0)
            return nullptr;
        else
            return &state_thunk<K, S>;
    }

    static constexpr state_id id(int s) { return s < 0 ? no_state : static_cast<state_id>(s); }

    static constexpr state_kind kind_of(bsc::detail::kind k) {
        switch (k) {
            case bsc::detail::kind::top: return state_kind::top;
            case bsc::detail::kind::basic: return state_kind::basic;
            case bsc::detail::kind::final_state: return state_kind::final_state;
            case bsc::detail::kind::composite: return state_kind::composite;
            case bsc::detail::kind::parallel: return state_kind::parallel;
            case bsc::detail::kind::history: return state_kind::history;
        }
        return state_kind::basic;
    }
    static constexpr history_kind history_of(bsc::detail::history h) {
        switch (h) {
            case bsc::detail::history::none: return history_kind::none;
            case bsc::detail::history::shallow: return history_kind::shallow;
            case bsc::detail::history::deep: return history_kind::deep;
        }
        return history_kind::none;
    }

    template <int S>
    static constexpr state_row_type make_state_row() {
        constexpr auto i = static_cast<std::size_t>(S);
        state_row_type row{};
        row.state = static_cast<state_id>(S);
        row.first_child = id(tree.first_child[i]);
        row.next_sibling = id(tree.next_sibling[i]);
        row.parent = id(tree.parent[i]);
        row.status = {kind_of(tree.kinds[i]), history_of(tree.hist[i])};
        row.entry = state_action_of<row_kind::entry, S>();
        row.exit = state_action_of<row_kind::exit, S>();
        row.initial = id(tree.initial[i]);
        row.initial_target = id(tree.initial_target[i]);
        for (std::size_t k = 0; k < row.more_initial.size(); ++k) row.more_initial[k] = id(tree.more_initial[i][k]);
        row.initial_action = state_action_of<row_kind::initial, S>();
        row.ordinal = static_cast<std::uint16_t>(tree.ordinal[i]);
        row.slot = static_cast<std::int16_t>(tree.slot[i]);
        row.end = static_cast<state_id>(tree.end[i]);
        row.timeout_slot = static_cast<std::int16_t>(layout::timeout_slot[i]);
        row.timeout_slots = static_cast<std::int16_t>(layout::timeout_slot_count[i]);
        return row;
    }

    template <std::size_t K>
    static constexpr transition_row_type make_transition_row() {
        constexpr int r = layout::transition_rows[K];
        constexpr auto i = static_cast<std::size_t>(r);
        using R = typename model::template row_at<r>;
        transition_row_type row{};
        row.from = id(rows.source[i]);
        row.event = rows.trigger[i] >= 0                           ? static_cast<event_id>(rows.trigger[i])
                    : rows.trigger[i] == bsc::detail::eventless_id ? eventless_id
                                                                   : timeout_id;
        row.to = id(rows.target[i]);
        if constexpr (rows.guarded[i] && transition_row_type::guards_read_configuration)
            row.guard = &configuration_guard_thunk<r>;
        else if constexpr (rows.guarded[i])
            row.guard = &guard_thunk<r>;
        // (A deferring row keeps its event and runs nothing: no action either.)
        if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(std::declval<R const&>().action)>,
                                      bsc::detail::no_action> &&
                      !std::is_same_v<std::remove_cvref_t<decltype(std::declval<R const&>().action)>,
                                      bsc::detail::defer_action>)
            row.action = &action_thunk<r>;
        row.domain = id(rows.domain[i]);
        if constexpr (bsc::detail::is_timeout_row<R>) row.delay = &delay_thunk<r>;
        row.timeout_slot = static_cast<std::int16_t>(layout::row_timeout_slot[i]);
        row.defers = rows.defers[i];
        row.rearms = layout::rearms(static_cast<int>(i));
        for (std::size_t k = 0; k < row.more_to.size(); ++k) row.more_to[k] = id(rows.more_targets[i][k]);
        return row;
    }

    static constexpr std::size_t transition_count = layout::transition_rows.size();
    static_assert(model::N <= 0xffff, "bsc::table: a chart has at most 65535 states");
    static_assert(transition_count <= 0x7fff, "bsc::table: a chart has at most 32767 transitions");

public:
    /// The position among make_chart's rows of each transition (what observers' on_row gets).
    static constexpr auto const& transition_chart_row = layout::transition_rows;

    /// Number of rows of each table.
    static constexpr std::size_t state_count = static_cast<std::size_t>(model::N);
    static constexpr std::size_t transition_rows = transition_count;
    /// Number of event types (valid event ids are 0 .. event_count - 1).
    static constexpr std::size_t event_count = model::events::size;
    /// Bytes of the active configuration: one per composite.
    static constexpr std::size_t slots = static_cast<std::size_t>(tree.slots);
    /// The root of the chart (row 1; row 0 is the implicit top).
    static constexpr state_id root = layout::root;
    /// The chart's priority among nested transitions (bsc/priority.hpp): whether a basic
    /// state tries its own transitions before its ancestors' (child_first) or after
    /// (parent_first).
    static constexpr bsc::priority order = model::order;
    /// The most states on one path from the top down: the longest list of origins a state tries.
    static constexpr std::size_t levels = [] {
        int deepest = 0;
        for (int d : tree.depth) deepest = d > deepest ? d : deepest;
        return static_cast<std::size_t>(deepest) + 1;
    }();
    /// The number of state S (its row in `states`).
    template <class S>
    static constexpr state_id state_of = id(model::template index_of_state<S>::value);
    /// The number of event type E (-1 if no transition takes it).
    template <class E>
    static constexpr event_id event_of = static_cast<event_id>(model::template trigger_of<E>::value);

    /// The topology table (BSTATE), in document order: row s describes state s.
    static constexpr std::array<state_row_type, state_count> states =
        // clang-format off
        []<std::size_t... S>(std::index_sequence<S...>) {
            return std::array<state_row_type, state_count>{make_state_row<static_cast<int>(S)>()...};
        }(std::make_index_sequence<state_count>{});
    // clang-format on

    /// The transition table (BTRANS), in declaration order.
    static constexpr std::array<transition_row_type, transition_count> transitions =
        // clang-format off
        []<std::size_t... K>(std::index_sequence<K...>) {
            return std::array<transition_row_type, transition_count>{make_transition_row<K>()...};
        }(std::make_index_sequence<transition_count>{});
    // clang-format on

    /// The unqualified names of the states, by row (row 0, the top, has an internal name).
    static constexpr auto const& names = bsc::detail::state_names_of<model>;

    /// The transitions leaving each state, as a list threaded through the transition table in
    /// declaration order: first_out[s] is the first, next_out[t] the one after t (-1: no more).
    static constexpr auto first_out = [] {
        std::array<std::int16_t, state_count> first{};
        for (auto& f : first) f = -1;
        for (std::size_t t = transition_count; t-- > 0;) first[transitions[t].from] = static_cast<std::int16_t>(t);
        return first;
    }();
    static constexpr auto next_out = [] {
        std::array<std::int16_t, transition_count> next{};
        for (std::size_t t = 0; t < transition_count; ++t) {
            next[t] = -1;
            for (std::size_t u = t + 1; u < transition_count; ++u)
                if (transitions[u].from == transitions[t].from) {
                    next[t] = static_cast<std::int16_t>(u);
                    break;
                }
        }
        return next;
    }();

    /// How many states keep an entry time for their timeouts.
    static constexpr std::size_t timeout_slots = static_cast<std::size_t>(layout::timeout_slots);
    /// Whether a state has several timeout rows, which compete by due time when due together.
    static constexpr bool competing_timeouts = layout::has_competing_timeouts;

    /// True if a transition triggered by `row_event` takes `event`: the same event, or a family
    /// of it (a base class of its type among the chart's events, or bsc::any_event).
    static constexpr bool takes(event_id row_event, event_id event) {
        if constexpr (model::has_families)
            return rows.takes(row_event, event);
        else
            return row_event == event;
    }

    /// True if some transition is triggered by `event` (an event id, or `eventless_id`), or by
    /// a family of it.
    static constexpr bool handles(event_id event) {
        for (auto const& t : transitions)
            if (takes(t.event, event)) return true;
        return false;
    }

    static constexpr bool has_eventless = handles(eventless_id);
    /// True if a BSC cycle has anything to consider: an eventless or timeout transition.
    static constexpr bool has_conditions = has_eventless || handles(timeout_id);

    /// The components of a BSC cycle, in the order they run: the root and every child of a
    /// parallel state, in document order.
    static constexpr auto components = [] {
        std::array<state_id, layout::components.size()> out{};
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<state_id>(layout::components[i]);
        return out;
    }();

    /// The configuration every composite starts from: its initial child.
    static constexpr auto const& initial_bytes = layout::initial_bytes;

    /// How many basic states can be active at once: the most transitions one event can select.
    static constexpr std::size_t max_active_leaves = static_cast<std::size_t>(layout::max_active_leaves());

    /// a is d or one of its ancestors.
    static constexpr bool contains(state_id a, state_id d) { return a <= d && d < states[a].end; }
};

}  // namespace bsc::table
