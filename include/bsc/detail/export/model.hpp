#pragma once
// The chart as the diagram exports see it: its states in document order with their names,
// identifiers, kinds, initial children, history and entry/exit actions, and its transitions
// with the labels of their triggers, guards and actions. Built at run time from a chart object
// (the names of guards and actions given with bsc::named, and the delays of timeouts, are
// values in the chart); each format of <bsc/export.hpp> is a walk over this model.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <bsc/detail/delay_label.hpp>
#include <bsc/detail/guard_label.hpp>
#include <bsc/detail/row_storage.hpp>
#include <bsc/dsl/delayed.hpp>
#include <bsc/detail/model/chart_model.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/dsl/action.hpp>
#include <bsc/dsl/guard.hpp>
#include <bsc/dsl/row.hpp>
#include <bsc/dsl/tree.hpp>
#include <bsc/event_name.hpp>
#include <bsc/priority.hpp>

namespace bsc::detail {

// ---- Labels of guards and actions -------------------------------------------------------------

template <class T>
inline constexpr bool is_action_fn = false;
template <class F>
inline constexpr bool is_action_fn<action_fn<F>> = true;
template <class T>
inline constexpr bool is_action_seq = false;
template <class... As>
inline constexpr bool is_action_seq<action_seq<As...>> = true;
template <class T>
inline constexpr bool is_state_action = false;
template <class A>
inline constexpr bool is_state_action<state_action<A>> = true;

template <class A>
expression action_expression(A const& a) {
    if constexpr (has_name<A>) {
        return {std::string(std::string_view{a.name}), true, 3};
    } else if constexpr (std::is_same_v<A, defer_action>) {
        return {"defer", true, 3};
    } else if constexpr (is_delayed_raise<A>) {
        std::string text = "raise_after(" + delay_label(a.delay) + ", " +
                           std::string(event_name<std::remove_cvref_t<decltype(a.event)>>);
        if (a.id != 0) text += ", " + std::to_string(a.id);
        return {text + ")", true, 3};
    } else if constexpr (std::is_same_v<A, cancel_delayed_action>) {
        return {"cancel_delayed(" + std::to_string(a.id) + ")", true, 3};
    } else if constexpr (is_action_seq<A>) {
        expression out{"", false, 3};
        std::apply(
            [&](auto const&... parts) {
                (
                    [&](expression const& part) {
                        if (!out.text.empty()) out.text += ", ";
                        out.text += part.text;
                        out.named = out.named || part.named;
                    }(action_expression(parts)),
                    ...);
            },
            a.actions);
        return out;
    } else if constexpr (is_action_fn<A> || is_state_action<A>) {
        return action_expression(a.fn);
    } else {
        return {"action", false, 3};
    }
}

/// The label of an action: its name, the names of a sequence's parts separated by ", " (an
/// unnamed part shown as "action"), or "action" when no part has a name.
template <class A>
std::string action_label(A const& a) {
    auto const e = action_expression(a);
    return e.named ? e.text : "action";
}

// ---- Identifiers ---------------------------------------------------------------------------

/// An identifier valid in every format: ASCII letters, digits and '_', not starting with a
/// digit. "Slot<cell::P1>" becomes "Slot_cell_P1".
inline std::string identifier(std::string_view name) {
    std::string out;
    bool gap = false;
    for (char const c : name) {
        bool const word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (word) {
            if (gap && !out.empty()) out += '_';
            out += c;
            gap = false;
        } else {
            gap = true;
        }
    }
    if (out.empty()) out = "unnamed";
    if (out.front() >= '0' && out.front() <= '9') out.insert(0, "s_");
    // Words that some of the formats reserve.
    for (std::string_view const reserved :
         {"state", "note", "end", "as", "direction", "class", "classDef", "style", "click", "graph", "digraph",
          "subgraph", "node", "edge", "strict", "scxml", "default", "hide"})
        if (out == reserved) out += '_';
    return out;
}

// ---- The model -----------------------------------------------------------------------------

enum class trigger_kind : std::uint8_t { event, eventless, timeout };

struct state_info {
    std::string id;     ///< unique identifier, valid in every format
    std::string label;  ///< the state's name: bsc::name_of<S>, with scopes where two states share it
    kind node_kind = kind::basic;
    history hist = history::none;
    int parent = -1;  ///< index in diagram::states; -1 for the root
    std::vector<int> children;
    int initial = -1;                ///< a composite's initial state (a child, or deeper); a history state's default
    std::vector<int> more_initials;  ///< a composite's initial states after the first (`initial<A, B>`)
    std::vector<std::string> entry;  ///< labels of the entry actions, in declaration order
    std::vector<std::string> exit;   ///< labels of the exit actions
    /// labels of the actions of its initial transition (a composite) or default transition (a
    /// history state): its on_initial rows
    std::vector<std::string> initial_actions;
    std::vector<int> internal;  ///< internal transitions (indices in diagram::transitions)
    std::string type;           ///< the state's C++ type: bsc::qualified_name<S>
    /// The positions (from 1, in make_chart's order) of the rows of `entry`, `exit` and
    /// `initial_actions`, one for one.
    std::vector<int> entry_rows;
    std::vector<int> exit_rows;
    std::vector<int> initial_rows;

    /// Drawn as a node, not a cluster: a basic or final state, or a history state.
    bool is_leaf() const {
        return node_kind == kind::basic || node_kind == kind::final_state || node_kind == kind::history;
    }
};

struct transition_info {
    int row = 0;      ///< position of the row in make_chart, from 0
    int source = 0;   ///< index in diagram::states
    int target = -1;  ///< -1: an internal transition (no target)
    trigger_kind trigger = trigger_kind::event;
    std::string event;              ///< the event's name, "after(3s)" for a timeout, empty if eventless
    std::string event_type;         ///< the event's C++ type (bsc::qualified_name), empty if none
    std::string delay;              ///< a timeout's delay, "3s"
    std::string guard;              ///< empty if unguarded
    std::string cond;               ///< the guard as SCXML's cond: bsc::in<S> as In('id'); empty if unguarded
    std::string action;             ///< empty if no action
    bool local = false;             ///< a local transition (bsc::local): its source stays active
    bool defers = false;            ///< a row that defers its event (`/ bsc::defer`)
    std::vector<int> more_targets;  ///< a transition with several targets (bsc::targets): the others
    /// Under parent-first priority, the transitions of its source's ancestors (indices in
    /// diagram::transitions) that take every event it takes and are tried before it: it fires
    /// only when none of them is enabled. Empty under child-first.
    std::vector<int> tried_before;

    /// Every target: none for an internal transition, else `target` and `more_targets`.
    std::vector<int> targets() const {
        std::vector<int> all;
        if (target >= 0) all.push_back(target);
        for (int const more : more_targets) all.push_back(more);  // (not insert: GCC 12's -O3 warns falsely)
        return all;
    }

    /// "event [guard] / action", with the parts that exist, and "(local)" for a local one.
    std::string label() const {
        std::string out = event;
        if (!guard.empty()) out += (out.empty() ? "[" : " [") + guard + "]";
        if (!action.empty()) out += (out.empty() ? "/ " : " / ") + action;
        if (local) out += out.empty() ? "(local)" : " (local)";
        return out;
    }
};

struct diagram {
    std::vector<state_info> states;            ///< document order; states[0] is the root
    std::vector<transition_info> transitions;  ///< declaration order, internal ones included
    priority order = priority::child_first;    ///< the chart's priority among nested transitions
    std::string context;                       ///< the chart's context type: bsc::qualified_name

    /// s is a or below a.
    bool contains(int a, int s) const {
        for (; s >= 0; s = states[static_cast<std::size_t>(s)].parent)
            if (s == a) return true;
        return false;
    }
    state_info const& operator[](int s) const { return states[static_cast<std::size_t>(s)]; }
};

template <class Tags>
struct state_name_list;
template <class... Tags>
struct state_name_list<type_list<Tags...>> {
    static std::vector<std::string_view> unqualified() { return {name_of<Tags>...}; }
    static std::vector<std::string_view> qualified() { return {qualified_name<Tags>...}; }
};

/// The last `scopes` components of a qualified name: ("ns::a::Idle", 2) is "a::Idle".
inline std::string_view last_scopes(std::string_view qualified, int scopes) {
    int depth = 0;
    for (std::size_t i = qualified.size(); i-- > 1;) {
        if (qualified[i] == '>') ++depth;
        if (qualified[i] == '<') --depth;
        if (depth == 0 && qualified[i] == ':' && qualified[i - 1] == ':' && --scopes == 0)
            return qualified.substr(i + 1);
    }
    return qualified;
}

/// The names the exports show: the unqualified name, or where two states share it (a::Idle,
/// b::Idle) as many enclosing scopes as tell them apart.
inline std::vector<std::string> unique_names(std::vector<std::string_view> const& names,
                                             std::vector<std::string_view> const& qualified) {
    std::vector<std::string> out(names.begin(), names.end());
    for (int scopes = 2; scopes < 16; ++scopes) {
        bool clash = false;
        std::vector<std::string> next = out;
        for (std::size_t i = 0; i < out.size(); ++i)
            for (std::size_t j = 0; j < out.size(); ++j)
                if (i != j && out[i] == out[j]) {
                    next[i] = std::string(last_scopes(qualified[i], scopes));
                    clash = true;
                }
        if (!clash) break;
        out = next;
    }
    return out;
}

/// Identifiers for the states, from their names; a numbered suffix where two names give the
/// same identifier ("A_B" and "A<B>").
inline std::vector<std::string> unique_identifiers(std::vector<std::string> const& names) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        std::string id = identifier(names[i]);
        // A suffixed id may itself be taken ("A_B_2" next to "A_B" and "A<B>"): suffix again.
        while (std::find(out.begin(), out.end(), id) != out.end()) id += "_" + std::to_string(i);
        out.push_back(id);
    }
    return out;
}

// How a label writes bsc::in<S> (detail/guard_label.hpp): In(S) with S's label, as the diagrams
// name it, or for SCXML In('id') with the id of S's element.
template <class Model>
auto in_state_text(diagram const& m, bool scxml) {
    return [&m, scxml]<class S>(std::type_identity<S>) {
        constexpr int s = Model::template index_of_state<S>::value;
        if constexpr (s < 1) {  // not a state of the chart (which make_chart rejects)
            return "In(" + std::string(name_of<S>) + ")";
        } else {
            auto const& st = m[s - 1];
            return scxml ? "In('" + st.id + "')" : "In(" + st.label + ")";
        }
    };
}

template <class Model, class Row>
void add_row(diagram& m, Row const& row, int index, int source) {
    auto& st = m.states[static_cast<std::size_t>(source)];
    if constexpr (is_entry_row<Row>) {
        st.entry.push_back(action_label(row.action));
        st.entry_rows.push_back(index + 1);
    } else if constexpr (is_exit_row<Row>) {
        st.exit.push_back(action_label(row.action));
        st.exit_rows.push_back(index + 1);
    } else if constexpr (is_initial_row<Row>) {
        st.initial_actions.push_back(action_label(row.action));
        st.initial_rows.push_back(index + 1);
    } else {
        transition_info t;
        t.row = index;
        t.source = source;
        using trigger = typename Row::trigger;
        if constexpr (std::is_same_v<trigger, timeout_trigger>) {
            t.trigger = trigger_kind::timeout;
            t.delay = delay_label(row.trigger_value.delay);
            t.event = "after(" + t.delay + ")";
        } else if constexpr (std::is_same_v<trigger, eventless_trigger>) {
            t.trigger = trigger_kind::eventless;
        } else {
            t.trigger = trigger_kind::event;
            t.event = std::string(event_name<typename trigger::event>);  // as dispatch_by_name knows it
            t.event_type = std::string(qualified_name<typename trigger::event>);
        }
        if constexpr (Row::guarded) {
            t.guard = guard_label(row.guard, in_state_text<Model>(m, false));
            if constexpr (tests_configuration<std::remove_cvref_t<decltype(row.guard)>>)
                t.cond = guard_label(row.guard, in_state_text<Model>(m, true));
            else
                t.cond = t.guard;
        }
        if constexpr (!std::is_same_v<std::remove_cvref_t<decltype(row.action)>, no_action>)
            t.action = action_label(row.action);
        t.defers = Row::defers;
        m.transitions.push_back(std::move(t));
    }
}

/// Under parent-first priority, whether transition row `outer` is tried before row `inner` on
/// every event `inner` takes: it leaves a proper ancestor of inner's source, on the same trigger
/// or on a family of it. (A timeout's trigger is its own.)
template <std::size_t N, std::size_t R>
constexpr bool outer_tried_first(topology<N> const& tree, row_table<R> const& rows, int outer, int inner) {
    auto const o = static_cast<std::size_t>(outer);
    auto const i = static_cast<std::size_t>(inner);
    return rows.kinds[o] == row_kind::transition && tree.is_proper_ancestor(rows.source[o], rows.source[i]) &&
           rows.takes(rows.trigger[o], rows.trigger[i]);
}

/// Under parent-first priority, a row of an ancestor that takes some of the events of a row
/// below it but not all (its trigger derives from the inner row's): it is tried first for
/// those events only, which SCXML's conditions cannot say. {-1, -1} if there is none.
template <class Model>
constexpr std::array<int, 2> outer_row_narrower() {
    if constexpr (Model::order == priority::parent_first && Model::has_families) {
        for (int o = 0; o < Model::R; ++o)
            for (int i = 0; i < Model::R; ++i) {
                auto const oi = static_cast<std::size_t>(o);
                auto const ii = static_cast<std::size_t>(i);
                if (Model::rows.kinds[oi] == row_kind::transition && Model::rows.kinds[ii] == row_kind::transition &&
                    Model::tree.is_proper_ancestor(Model::rows.source[oi], Model::rows.source[ii]) &&
                    Model::rows.trigger[oi] != Model::rows.trigger[ii] &&
                    Model::rows.takes(Model::rows.trigger[ii], Model::rows.trigger[oi]))
                    return {o, i};
            }
    }
    return {-1, -1};
}

/// The model of a chart (a bsc::make_chart result).
template <class Chart>
diagram model_of(Chart const& chart) {
    using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
    constexpr auto const& tree = model::tree;
    diagram m;
    m.context = std::string(qualified_name<typename model::chart_context>);
    auto const names = state_name_list<typename model::tags>::unqualified();
    auto const qualified = state_name_list<typename model::tags>::qualified();
    // Index 0 of the analysis is the implicit top above the root; the model starts at the root.
    std::vector<std::string_view> const own(names.begin() + 1, names.end());
    std::vector<std::string_view> const own_qualified(qualified.begin() + 1, qualified.end());
    auto const labels = unique_names(own, own_qualified);
    auto const ids = unique_identifiers(labels);
    for (int s = 1; s < model::N; ++s) {
        auto const i = static_cast<std::size_t>(s);
        state_info info;
        info.id = ids[i - 1];
        info.label = labels[i - 1];
        info.type = std::string(own_qualified[i - 1]);
        info.node_kind = tree.kinds[i];
        info.hist = tree.hist[i];
        info.parent = tree.parent[i] - 1;
        // A composite's initial state (a child, or deeper), a history state's default.
        info.initial = tree.initial_target[i] >= 0 ? tree.initial_target[i] - 1 : -1;
        for (int const more : tree.more_initial[i])
            if (more >= 0) info.more_initials.push_back(more - 1);
        for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
            info.children.push_back(c - 1);
        m.states.push_back(std::move(info));
    }
    // clang-format off
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        // (In order, as a list: a chart may have more rows than a fold takes, detail::max_fold.)
        [[maybe_unused]] int const added[] = {
            (add_row<model>(m, detail::row_at<I>(chart.rows), static_cast<int>(I), model::rows.source[I] - 1), 0)..., 0};
    }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
    // clang-format on
    for (std::size_t k = 0; k < m.transitions.size(); ++k) {
        auto& t = m.transitions[k];
        t.target = model::rows.target[static_cast<std::size_t>(t.row)] >= 0
                       ? model::rows.target[static_cast<std::size_t>(t.row)] - 1
                       : -1;
        if (t.target < 0) m.states[static_cast<std::size_t>(t.source)].internal.push_back(static_cast<int>(k));
        for (int const more : model::rows.more_targets[static_cast<std::size_t>(t.row)])
            if (more >= 0) t.more_targets.push_back(more - 1);
        // Local in effect: the domain is the source (bsc::local from a composite).
        t.local = t.target >= 0 && model::rows.domain[static_cast<std::size_t>(t.row)] ==
                                       model::rows.source[static_cast<std::size_t>(t.row)];
    }
    m.order = model::order;
    if constexpr (model::order == priority::parent_first)
        for (auto& t : m.transitions)
            for (std::size_t k = 0; k < m.transitions.size(); ++k)
                if (outer_tried_first(model::tree, model::rows, m.transitions[k].row, t.row))
                    t.tried_before.push_back(static_cast<int>(k));
    return m;
}

// ---- Text helpers shared by the formats ----------------------------------------------------

/// What a diagram of a parent-first chart says of its priority (child first, SCXML's and UML's,
/// goes without saying).
inline constexpr std::string_view parent_first_note = "priority: parent first (outer transitions before inner ones)";

inline std::string indent(int level) { return std::string(static_cast<std::size_t>(level) * 4, ' '); }

inline std::string replace_all(std::string text, std::string_view from, std::string_view to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// Text for an XML attribute value or element content.
inline std::string xml_escaped(std::string_view text) {
    std::string out;
    for (char const c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

/// " [H]" or " [H*]" after the name of a composite state with shallow or deep history.
inline std::string history_suffix(history h) {
    return h == history::deep ? " [H*]" : h == history::shallow ? " [H]" : "";
}

/// The label of a composite's initial transition or a history state's default transition: its
/// actions, "/ a, b", or empty.
inline std::string initial_label(state_info const& st) {
    std::string out;
    for (auto const& a : st.initial_actions) out += (out.empty() ? "/ " : ", ") + a;
    return out;
}

/// Lines that describe a state besides its name: "entry / a", "exit / b", and its internal
/// transitions "event [guard] / action".
inline std::vector<std::string> activity_lines(diagram const& m, int s) {
    std::vector<std::string> lines;
    for (auto const& a : m[s].entry) lines.push_back("entry / " + a);
    for (auto const& a : m[s].exit) lines.push_back("exit / " + a);
    for (int const t : m[s].internal) lines.push_back(m.transitions[static_cast<std::size_t>(t)].label());
    return lines;
}

}  // namespace bsc::detail
