#pragma once
// bsc exports - Mermaid, Graphviz, PlantUML and SCXML, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/export.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/export.hpp
// bsc exports: a chart as a diagram or as a document for other tools.
//
//   bsc::to_mermaid(chart)   Mermaid stateDiagram-v2
//   bsc::to_dot(chart)       Graphviz DOT
//   bsc::to_plantuml(chart)  PlantUML state diagram
//   bsc::to_scxml(chart)     W3C SCXML
//
// Not included by <bsc/bsc.hpp>: the exports build std::string, which machines never need.
// Guards and actions appear by name when they have one (bsc::named, <bsc/dsl/named.hpp>).

// begin include/bsc/export/dot.hpp
// bsc::to_dot: a chart as a Graphviz digraph (render it with `dot -Tsvg`).
//
// Basic and final states are rounded boxes (a final state with a double border) whose label
// lists the entry and exit actions and the internal transitions under the name. Composite and
// parallel states are clusters; the regions of a parallel state are dashed clusters. A
// composite's initial child is marked by an edge from a small black dot; history by a circled
// H (shallow) or H* (deep) inside the composite. Transitions are edges labelled
// "event [guard] / action", the label padded with two spaces on each side so that the labels of
// neighbouring edges never run together; an edge from or to a composite or parallel state starts
// or ends at the cluster's border (`compound=true` with `ltail`/`lhead`, through an invisible
// anchor node inside the cluster); the label of an edge that crosses a cluster's border, which
// Graphviz may place far from the part it draws, is tied to it by a line (`decorate`). Nodes
// and ranks are spread (`nodesep`, `ranksep`) to leave room for the labels.

#include <string>
#include <string_view>

// begin include/bsc/detail/export/model.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_EXPORT_MODEL_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_EXPORT_MODEL_HPP
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

// begin include/bsc/detail/delay_label.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// A duration as short exact text, for the exports' timeout labels and the logger's times.

#include <string>


namespace bsc::detail {

/// "3s", "250ms", "20us" or "7ns": the largest unit that divides the delay.
inline std::string delay_label(std::chrono::nanoseconds d) {
    auto const n = d.count();
    if (n % 1'000'000'000 == 0) return std::to_string(n / 1'000'000'000) + "s";
    if (n % 1'000'000 == 0) return std::to_string(n / 1'000'000) + "ms";
    if (n % 1'000 == 0) return std::to_string(n / 1'000) + "us";
    return std::to_string(n) + "ns";
}

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_DELAY_LABEL_HPP
// end include/bsc/detail/delay_label.hpp

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
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_EXPORT_MODEL_HPP
// end include/bsc/detail/export/model.hpp

namespace bsc::detail {

/// A double-quoted DOT string.
inline std::string dot_quoted(std::string_view text) {
    std::string out = "\"";
    for (char const c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n')
            out += "\\n";
        else
            out += c;
    }
    return out + "\"";
}

inline std::string dot_cluster(diagram const& m, int s) { return dot_quoted("cluster_" + m[s].id); }
inline std::string dot_anchor(diagram const& m, int s) { return dot_quoted(m[s].id + ":anchor"); }
/// The node an edge to or from state s attaches to.
inline std::string dot_node(diagram const& m, int s) { return m[s].is_leaf() ? dot_quoted(m[s].id) : dot_anchor(m, s); }

inline std::string dot_label(diagram const& m, int s) {
    std::string label = m[s].label;
    for (auto const& line : activity_lines(m, s)) label += "\n" + line;
    return label;
}

inline void dot_state(diagram const& m, int s, int level, bool region, std::string& out) {
    auto const& st = m[s];
    auto const pad = indent(level);
    if (st.is_leaf()) {
        if (region) {  // a basic state as a region of a parallel state: its own dashed cluster
            out += pad + "subgraph " + dot_quoted("cluster_region_" + st.id) + " {\n";
            out += pad + "    label=\"\"; style=\"rounded,dashed\";\n";
            dot_state(m, s, level + 1, false, out);
            out += pad + "}\n";
            return;
        }
        out += pad + dot_quoted(st.id) + " [label=" + dot_quoted(dot_label(m, s) + history_suffix(st.hist));
        if (st.node_kind == kind::final_state) out += ", peripheries=2";
        if (st.node_kind == kind::history) out += ", shape=circle";
        out += "];\n";
        if (st.node_kind == kind::history && st.initial >= 0) {  // its default transition
            out += pad + dot_quoted(st.id) + " -> " + dot_node(m, st.initial) + " [style=dashed";
            if (!m[st.initial].is_leaf()) out += ", lhead=" + dot_cluster(m, st.initial);
            if (!st.initial_actions.empty()) out += ", label=" + dot_quoted(initial_label(st));
            out += "];\n";
        }
        return;
    }
    out += pad + "subgraph " + dot_cluster(m, s) + " {\n";
    out += pad + "    label=" + dot_quoted(dot_label(m, s)) +
           "; style=" + (region ? "\"rounded,dashed\"" : "\"rounded\"") + ";\n";
    out += pad + "    " + dot_anchor(m, s) + " [shape=point, style=invis, width=0, height=0, label=\"\"];\n";
    if (st.initial >= 0) {
        auto const initial = dot_quoted(st.id + ":initial");
        out += pad + "    " + initial + " [shape=point, width=0.12, label=\"\"];\n";
        out += pad + "    " + initial + " -> " + dot_node(m, st.initial);
        std::string attributes;
        if (!m[st.initial].is_leaf()) attributes += "lhead=" + dot_cluster(m, st.initial);
        if (!st.initial_actions.empty())
            attributes += (attributes.empty() ? "" : ", ") + std::string("label=") + dot_quoted(initial_label(st));
        if (!attributes.empty()) out += " [" + attributes + "]";
        out += ";\n";
        for (int const more : st.more_initials) {
            out += pad + "    " + initial + " -> " + dot_node(m, more);
            if (!m[more].is_leaf()) out += " [lhead=" + dot_cluster(m, more) + "]";
            out += ";\n";
        }
    }
    if (st.hist != history::none)
        out += pad + "    " + dot_quoted(st.id + ":history") +
               " [shape=circle, label=" + (st.hist == history::deep ? "\"H*\"" : "\"H\"") +
               ", width=0.3, fixedsize=true, fontsize=9];\n";
    for (int const c : st.children) dot_state(m, c, level + 1, st.node_kind == kind::parallel, out);
    out += pad + "}\n";
}

inline std::string to_dot(diagram const& m) {
    std::string out = "digraph " + dot_quoted(m[0].label) + " {\n";
    out += "    compound=true; nodesep=0.6; ranksep=0.8; forcelabels=true;\n";
    out += "    fontname=\"Helvetica\"; fontsize=11;\n";
    if (m.order == priority::parent_first) out += "    label=" + dot_quoted(parent_first_note) + "; labelloc=t;\n";
    out += "    node [shape=box, style=rounded, fontname=\"Helvetica\", fontsize=11];\n";
    out += "    edge [fontname=\"Helvetica\", fontsize=9];\n";
    out += "    \":start\" [shape=point, width=0.12, label=\"\"];\n";
    out += "    \":start\" -> " + dot_node(m, 0) + " [lhead=" + dot_cluster(m, 0) + "];\n";
    dot_state(m, 0, 1, false, out);
    for (auto const& t : m.transitions) {
        for (int const target : t.targets()) {  // none for an internal one: listed in its state
            out += "    " + dot_node(m, t.source) + " -> " + dot_node(m, target);
            std::string attributes;
            auto const add = [&](std::string const& a) { attributes += (attributes.empty() ? "" : ", ") + a; };
            auto const label = t.label();
            if (!label.empty()) add("label=" + dot_quoted("  " + label + "  "));
            // Graphviz ignores ltail when the head is inside the tail's cluster, and lhead when
            // the tail is inside the head's cluster; such an edge starts or ends at the anchor.
            bool clipped = false;
            if (!m[t.source].is_leaf() && !m.contains(t.source, target)) {
                add("ltail=" + dot_cluster(m, t.source));
                clipped = true;
            }
            if (!m[target].is_leaf() && !m.contains(target, t.source)) {
                add("lhead=" + dot_cluster(m, target));
                clipped = true;
            }
            // Graphviz may place the label of an edge that crosses a cluster's border far from it.
            if (!label.empty() && (clipped || m[t.source].parent != m[target].parent)) add("decorate=true");
            out += (attributes.empty() ? "" : " [" + attributes + "]") + ";\n";
        }
    }
    out += "}\n";
    return out;
}

}  // namespace bsc::detail

namespace bsc {

/// The chart as a Graphviz digraph with clusters for composite and parallel states.
template <class Chart>
std::string to_dot(Chart const& chart) {
    return detail::to_dot(detail::model_of(chart));
}

}  // namespace bsc
// end include/bsc/export/dot.hpp
// begin include/bsc/export/mermaid.hpp
// bsc::to_mermaid: a chart as a Mermaid state diagram (stateDiagram-v2), which GitHub and
// many Markdown viewers render.
//
// The state tree comes first: composite states as `state X { ... }` starting with
// `[*] --> initial`, the regions of a parallel state separated by `--`, a final state followed
// by `--> [*]`. Entry and exit actions and internal transitions are lines under the state's
// name. Mermaid has no history pseudo-state: a composite state with history shows [H] (shallow)
// or [H*] (deep) after its name. The transitions follow, after the whole tree, as
// `A --> B : event [guard] / action`: Mermaid places a state in the last composite block that
// mentions it, so a transition written inside a block could move a state out of its parent.

#include <string>
#include <string_view>


namespace bsc::detail {

/// Text inside a quoted Mermaid label or after `:`; `;` would end the statement and `<`
/// would start HTML.
inline std::string mermaid_text(std::string_view text) {
    std::string out;
    for (char const c : text) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += '\''; break;
            case ';': out += ','; break;
            case '#': out += "&num;"; break;
            case '\n': out += ' '; break;
            default: out += c;
        }
    }
    return out;
}

inline std::string with_label(std::string const& label) { return label.empty() ? "" : " : " + mermaid_text(label); }

inline void mermaid_state(diagram const& m, int s, int level, std::string& out) {
    auto const& st = m[s];
    auto const activities = activity_lines(m, s);
    if (st.is_leaf()) {
        if (st.label != st.id || !activities.empty() || st.node_kind == kind::history)
            out += indent(level) + "state \"" + mermaid_text(st.label + history_suffix(st.hist)) + "\" as " + st.id +
                   "\n";
        else
            out += indent(level) + st.id + "\n";
        for (auto const& line : activities) out += indent(level) + st.id + " : " + mermaid_text(line) + "\n";
        if (st.node_kind == kind::final_state) out += indent(level) + st.id + " --> [*]\n";
        if (st.node_kind == kind::history && st.initial >= 0)  // its default transition
            out += indent(level) + st.id + " --> " + m[st.initial].id + with_label(initial_label(st)) + "\n";
        return;
    }
    // A composite state's description would replace its name: its activities go into its title.
    std::string title = mermaid_text(st.label) + history_suffix(st.hist);
    for (auto const& line : activities) title += "<br/>" + mermaid_text(line);
    out += indent(level) + "state \"" + title + "\" as " + st.id + " {\n";
    if (st.initial >= 0)
        out += indent(level + 1) + "[*] --> " + m[st.initial].id + with_label(initial_label(st)) + "\n";
    for (int const more : st.more_initials) out += indent(level + 1) + "[*] --> " + m[more].id + "\n";
    bool first = true;
    for (int const c : st.children) {
        if (st.node_kind == kind::parallel && !first) out += indent(level + 1) + "--\n";
        first = false;
        mermaid_state(m, c, level + 1, out);
    }
    out += indent(level) + "}\n";
}

inline std::string to_mermaid(diagram const& m) {
    std::string out;
    // (The title quoted: front matter is YAML, where the note's colon would start a mapping.)
    if (m.order == priority::parent_first) out += "---\ntitle: \"" + std::string(parent_first_note) + "\"\n---\n";
    out += "stateDiagram-v2\n";
    out += indent(1) + "[*] --> " + m[0].id + "\n";
    mermaid_state(m, 0, 1, out);
    for (auto const& t : m.transitions) {
        for (int const target : t.targets()) {  // none for an internal one: shown in its state
            out += indent(1) + m[t.source].id + " --> " + m[target].id;
            auto const label = t.label();
            if (!label.empty()) out += " : " + mermaid_text(label);
            out += "\n";
        }
    }
    return out;
}

}  // namespace bsc::detail

namespace bsc {

/// The chart as a Mermaid state diagram (`stateDiagram-v2`).
template <class Chart>
std::string to_mermaid(Chart const& chart) {
    return detail::to_mermaid(detail::model_of(chart));
}

}  // namespace bsc
// end include/bsc/export/mermaid.hpp
// begin include/bsc/export/plantuml.hpp
// bsc::to_plantuml: a chart as a PlantUML state diagram (@startuml ... @enduml).
//
// Composite and parallel states are `state "Name" as Id { ... }`, a composite's initial child is
// `[*] --> Child`, the regions of a parallel state are separated by `--`, a final state is
// followed by `--> [*]`; entry and exit actions and internal transitions are description lines
// `Id : entry / action`. A composite state with history shows [H] or [H*] after its name (the
// [H*] pseudo-state is not understood by every PlantUML release). The transitions follow the
// tree: `A --> B : event [guard] / action`.

#include <string>
#include <string_view>


namespace bsc::detail {

/// Text of a quoted PlantUML name or of a label after `:`.
inline std::string plantuml_text(std::string_view text) {
    std::string out;
    for (char const c : text) {
        if (c == '"')
            out += '\'';
        else if (c == '\n')
            out += ' ';
        else
            out += c;
    }
    return out;
}

inline void plantuml_state(diagram const& m, int s, int level, std::string& out) {
    auto const& st = m[s];
    auto const pad = indent(level);
    out += pad + "state \"" + plantuml_text(st.label + history_suffix(st.hist)) + "\" as " + st.id;
    if (st.is_leaf()) {
        out += "\n";
    } else {
        out += " {\n";
        if (st.initial >= 0) {
            auto const label = initial_label(st);
            out += indent(level + 1) + "[*] --> " + m[st.initial].id +
                   (label.empty() ? "" : " : " + plantuml_text(label)) + "\n";
            for (int const more : st.more_initials) out += indent(level + 1) + "[*] --> " + m[more].id + "\n";
        }
        bool first = true;
        for (int const c : st.children) {
            if (st.node_kind == kind::parallel && !first) out += indent(level + 1) + "--\n";
            first = false;
            plantuml_state(m, c, level + 1, out);
        }
        out += pad + "}\n";
    }
    for (auto const& line : activity_lines(m, s)) out += pad + st.id + " : " + plantuml_text(line) + "\n";
    if (st.node_kind == kind::final_state) out += pad + st.id + " --> [*]\n";
    if (st.node_kind == kind::history && st.initial >= 0) {  // its default transition
        auto const label = initial_label(st);
        out += pad + st.id + " --> " + m[st.initial].id + (label.empty() ? "" : " : " + plantuml_text(label)) + "\n";
    }
}

inline std::string to_plantuml(diagram const& m) {
    std::string out = "@startuml\nhide empty description\n";
    if (m.order == priority::parent_first) out += "title " + std::string(parent_first_note) + "\n";
    out += "[*] --> " + m[0].id + "\n";
    plantuml_state(m, 0, 0, out);
    for (auto const& t : m.transitions) {
        for (int const target : t.targets()) {  // none for an internal one: a line of its state
            out += m[t.source].id + " --> " + m[target].id;
            auto const label = t.label();
            if (!label.empty()) out += " : " + plantuml_text(label);
            out += "\n";
        }
    }
    return out + "@enduml\n";
}

}  // namespace bsc::detail

namespace bsc {

/// The chart as a PlantUML state diagram.
template <class Chart>
std::string to_plantuml(Chart const& chart) {
    return detail::to_plantuml(detail::model_of(chart));
}

}  // namespace bsc
// end include/bsc/export/plantuml.hpp
// begin include/bsc/export/scxml.hpp
// bsc::to_scxml: a chart as a W3C SCXML document.
//
// The state tree maps one for one: composite states are <state> with `initial`, parallel
// states <parallel>, final states <final> (a final state with outgoing transitions stays a
// <state>, since <final> may have none), the chart's root is the <scxml> element's initial.
// Transitions are children of their source, in declaration order (which is SCXML's priority
// among transitions of one source):
//   - `event` is the event's bsc::event_name, made a valid token; eventless transitions have none;
//   - a state-scoped timeout `after(3s)` is a transition on the event "after(3s)", with a
//     comment: SCXML has no timeouts, a platform would send that event delayed from <onentry>;
//   - `cond` is the guard's name (bsc::named), or "guard", with bsc::in<S> as In('id') (the id
//     of S's element) and the operators of composed guards; under parent-first priority
//     (bsc/priority.hpp) it also negates the guards of the outer transitions tried first;
//   - an internal transition (a row without a target) is type="internal" without a target, and
//     a local one (bsc::local) type="internal" with its target;
//   - bsc::done<S> is the event done.state.S, bsc::any_event the descriptor "*", and an event
//     whose type derives from another's takes its rows only if its name extends theirs
//     (name events "error" and "error.send" to keep the families SCXML's);
//   - a row that defers its event (`/ bsc::defer`) is a comment: SCXML has no deferral;
//   - actions, and entry and exit actions (<onentry>, <onexit>), are <script> placeholders that
//     name the action in a comment.
// A chart that halts (a final child of its root) leaves its root on done.state.Root for a
// top-level <final>, since SCXML halts only there.
// History states (shallow_history_state, deep_history_state) are <history> elements whose
// <transition> is their default; an initial transition with actions (on_initial) is an <initial>
// element, and a deep initial state is the `initial` attribute's (a descendant).
// History: bsc restores a composite with history on every entry that does not name a state
// inside it, which is what entering its <history> pseudo-state does in SCXML; so such a
// composite's <initial> targets its <history>, whose default transition targets the initial child.

#include <string>
#include <string_view>
#include <type_traits>


namespace bsc::detail {

/// Text inside an XML comment, which may not contain "--".
inline std::string scxml_comment(std::string_view text) { return replace_all(xml_escaped(text), "--", "- -"); }

// With a row position (annotated documents, below), the script says which row's action it is.
inline std::string scxml_script(std::string_view action, int row = 0) {
    std::string const open = row > 0 ? "<script bsc:row=\"" + std::to_string(row) + "\">" : "<script>";
    return open + "/* " + xml_escaped(replace_all(std::string(action), "*/", "* /")) + " */</script>";
}

// What an annotated document (bsc::scxml_annotated) says of a state: its C++ type.
inline std::string scxml_state_annotation(diagram const& m, state_info const& st, bool annotated) {
    return annotated && !m.context.empty() ? " bsc:type=\"" + xml_escaped(st.type) + "\"" : "";
}

/// The id of the <history> pseudo-state of a composite: "<id>_history", unique among the states.
inline std::string history_id(diagram const& m, int s) {
    std::string id = m[s].id + "_history";
    for (bool clash = true; clash;) {
        clash = false;
        for (auto const& st : m.states)
            if (st.id == id) {
                id += '_';
                clash = true;
            }
    }
    return id;
}

// An event's name as an SCXML event descriptor: "*" stays, and so do letters, digits, '_', '-'
// and the dots that separate the descriptor's parts ("done.state.Work"); every other run of
// characters becomes one '_' ("cell::Start" becomes "cell_Start").
inline std::string event_descriptor(std::string_view name) {
    if (name == "*") return "*";
    std::string out;
    bool gap = false;
    for (char const c : name) {
        bool const kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                          c == '-' || c == '.';
        if (!kept) {
            gap = true;
            continue;
        }
        if (gap && !out.empty()) out += '_';
        out += c;
        gap = false;
    }
    return out.empty() ? "unnamed" : out;
}

// The transition's cond: its guard, and under parent-first priority (SCXML's is child first)
// the negated guards of the outer transitions tried before it, so that the document selects
// what the chart does. An unguarded outer transition (possible only for an eventless one across
// a parallel state: otherwise the chart is rejected) makes it "false".
inline std::string scxml_condition(diagram const& m, transition_info const& t) {
    std::string cond;
    for (int const k : t.tried_before) {
        auto const& outer = m.transitions[static_cast<std::size_t>(k)];
        if (outer.cond.empty()) return "false";
        cond += (cond.empty() ? "!(" : " && !(") + outer.cond + ")";
    }
    if (t.cond.empty()) return cond;
    return cond.empty() ? t.cond : cond + " && (" + t.cond + ")";
}

// A cond as an attribute value: escaped, but for the quotes of In('id'), which an attribute in
// double quotes holds as they are.
inline std::string scxml_cond_attribute(std::string_view cond) { return replace_all(xml_escaped(cond), "&apos;", "'"); }

inline void scxml_transition(diagram const& m, transition_info const& t, int level, std::string& out, bool annotated) {
    auto const pad = indent(level);
    if (t.defers) {  // SCXML has no deferral: a comment in its place
        out += pad + "<!-- " + scxml_comment(t.label()) + ": the event is deferred (UML), which SCXML cannot say -->\n";
        if (annotated)  // an element of bsc's namespace, which SCXML processors ignore
            out += pad + "<bsc:defer event=\"" + event_descriptor(t.event) + "\" bsc:row=\"" +
                   std::to_string(t.row + 1) + "\" bsc:event=\"" + xml_escaped(t.event_type) + "\"/>\n";
        return;
    }
    if (t.trigger == trigger_kind::timeout)
        out += pad + "<!-- " + t.event + ": a timeout, enabled once " + scxml_comment(m[t.source].label) +
               " has been active for " + t.delay + " -->\n";
    out += pad + "<transition";
    if (t.trigger == trigger_kind::timeout)
        out += " event=\"" + xml_escaped(t.event) + "\"";
    else if (t.trigger == trigger_kind::event)
        out += " event=\"" + event_descriptor(t.event) + "\"";
    if (auto const cond = scxml_condition(m, t); !cond.empty()) out += " cond=\"" + scxml_cond_attribute(cond) + "\"";
    if (t.target >= 0) {
        out += " target=\"";
        for (int const target : t.targets()) out += (target == t.target ? "" : " ") + m[target].id;
        out += "\"";
    }
    if (t.target < 0 || t.local) out += " type=\"internal\"";
    int const row = annotated ? t.row + 1 : 0;
    if (annotated) {
        out += " bsc:row=\"" + std::to_string(row) + "\"";
        if (!t.event_type.empty() && t.trigger == trigger_kind::event)
            out += " bsc:event=\"" + xml_escaped(t.event_type) + "\"";
    }
    if (t.action.empty())
        out += "/>\n";
    else
        out += ">\n" + pad + "    " + scxml_script(t.action, row) + "\n" + pad + "</transition>\n";
}

// Whether the chart halts: its root is a composite with a final child. In SCXML the root is a
// <state>, whose final child raises done.state.Root; the document then leaves the root for a
// <final> of the <scxml> element, which ends it after running the same exit actions.
inline bool halts(diagram const& m) {
    if (m[0].node_kind != kind::composite) return false;
    for (int const c : m[0].children)
        if (m[c].node_kind == kind::final_state) return true;
    return false;
}

inline void scxml_state(diagram const& m, int s, int level, std::string& out, bool annotated) {
    auto const& st = m[s];
    auto const pad = indent(level);
    auto const row_of = [annotated](std::vector<int> const& rows, std::size_t k) {
        return annotated && k < rows.size() ? rows[k] : 0;
    };
    if (st.node_kind == kind::history) {  // a history state and its default transition
        out += pad + "<history id=\"" + st.id + "\" type=\"" + (st.hist == history::deep ? "deep" : "shallow") + "\"" +
               scxml_state_annotation(m, st, annotated) + ">\n";
        out += pad + "    <transition target=\"" + m[st.initial].id + "\"";
        if (st.initial_actions.empty()) {
            out += "/>\n";
        } else {
            out += ">\n";
            for (std::size_t k = 0; k < st.initial_actions.size(); ++k)
                out += pad + "        " + scxml_script(st.initial_actions[k], row_of(st.initial_rows, k)) + "\n";
            out += pad + "    </transition>\n";
        }
        out += pad + "</history>\n";
        return;
    }
    bool has_transitions = false;
    for (auto const& t : m.transitions) has_transitions = has_transitions || t.source == s;
    std::string element = "state";
    if (st.node_kind == kind::parallel) element = "parallel";
    if (st.node_kind == kind::final_state && !has_transitions) element = "final";
    out += pad + "<" + element + " id=\"" + st.id + "\"" + scxml_state_annotation(m, st, annotated);
    // An initial transition with actions is an <initial> element; without, the attribute.
    bool const initial_element = st.initial >= 0 && st.hist == history::none && !st.initial_actions.empty();
    if (st.initial >= 0 && st.hist == history::none && !initial_element) {
        out += " initial=\"" + m[st.initial].id;
        for (int const more : st.more_initials) out += " " + m[more].id;
        out += "\"";
    }
    bool const empty = st.children.empty() && st.entry.empty() && st.exit.empty() && !has_transitions;
    if (empty) {
        out += "/>\n";
        return;
    }
    out += ">\n";
    auto const inner = indent(level + 1);
    if (st.node_kind == kind::final_state && element == "state")
        out += inner + "<!-- a final state of the chart; <final> may not have transitions -->\n";
    if (initial_element) {
        std::string targets = m[st.initial].id;
        for (int const more : st.more_initials) targets += " " + m[more].id;
        out += inner + "<initial>\n" + inner + "    <transition target=\"" + targets + "\">\n";
        for (std::size_t k = 0; k < st.initial_actions.size(); ++k)
            out += inner + "        " + scxml_script(st.initial_actions[k], row_of(st.initial_rows, k)) + "\n";
        out += inner + "    </transition>\n" + inner + "</initial>\n";
    }
    if (st.initial >= 0 && st.hist != history::none) {
        auto const h = history_id(m, s);
        out += inner + "<initial>\n" + inner + "    <transition target=\"" + h + "\"/>\n" + inner + "</initial>\n";
        out += inner + "<history id=\"" + h + "\" type=\"" + (st.hist == history::deep ? "deep" : "shallow") + "\">\n" +
               inner + "    <transition target=\"" + m[st.initial].id + "\"/>\n" + inner + "</history>\n";
    }
    for (std::size_t k = 0; k < st.entry.size(); ++k)
        out += inner + "<onentry>" + scxml_script(st.entry[k], row_of(st.entry_rows, k)) + "</onentry>\n";
    for (std::size_t k = 0; k < st.exit.size(); ++k)
        out += inner + "<onexit>" + scxml_script(st.exit[k], row_of(st.exit_rows, k)) + "</onexit>\n";
    for (auto const& t : m.transitions)
        if (t.source == s) scxml_transition(m, t, level + 1, out, annotated);
    if (s == 0 && halts(m))
        out += inner + "<transition event=\"done.state." + m[0].id + "\" target=\"" + m[0].id + "_halted\"/>\n";
    for (int const c : st.children) scxml_state(m, c, level + 1, out, annotated);
    out += pad + "</" + element + ">\n";
}

inline std::string to_scxml(diagram const& m, bool annotated) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<!-- The chart " + scxml_comment(m[0].label) +
           ": cond names the guard, the <script> comments name the actions. -->\n";
    if (m.order == priority::parent_first)
        out +=
            "<!-- Parent-first priority: a transition's cond also negates the guards of its source's ancestors' "
            "transitions on the same event, which the chart tries first. -->\n";
    out += "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\"";
    if (annotated) {
        out += " xmlns:bsc=\"urn:bsc:scxml\" bsc:context=\"" + xml_escaped(m.context) + "\"";
        if (m.order == priority::parent_first) out += " bsc:priority=\"parent_first\"";
    }
    out += " version=\"1.0\" name=\"" + m[0].id + "\" initial=\"" + m[0].id + "\">\n";
    scxml_state(m, 0, 1, out, annotated);
    if (halts(m)) out += "    <final id=\"" + m[0].id + "_halted\"/>\n";
    return out + "</scxml>\n";
}

}  // namespace bsc::detail

namespace bsc {

/// The chart as a W3C SCXML document.
/// A chart with parent-first priority is written with conditions that say it (each transition
/// negates the guards of the outer ones tried first); one whose outer row takes only some of an
/// inner row's events (an event derived from the inner row's) cannot be, and does not compile.
template <class Chart>
std::string to_scxml(Chart const& chart) {
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    static_assert(detail::outer_row_narrower<model>()[0] < 0,
                  "bsc::to_scxml: under parent-first priority a row of an ancestor takes an event derived from "
                  "the event of a row below it: it is tried first for that event only, which SCXML's cond cannot "
                  "say without the event's name; give the rows the same event, or export a child-first chart");
    return detail::to_scxml(detail::model_of(chart), false);
}

/// The chart as an SCXML document annotated for bsc-scxml (docs/scxml.md, "Round trip"): the
/// same document as to_scxml, whose elements also say, in the namespace urn:bsc:scxml, which
/// C++ type each state and event is, which row of the chart each transition and action comes
/// from (`bsc:row`, counted from 1), the context, and the priority. `bsc-scxml --chart ns::chart`
/// compiles it back into a chart of the same types whose rows reuse the guards and actions of
/// `ns::chart`'s: the same machine, built from the document's structure.
template <class Chart>
std::string to_scxml_annotated(Chart const& chart) {
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    static_assert(detail::outer_row_narrower<model>()[0] < 0,
                  "bsc::to_scxml_annotated: under parent-first priority a row of an ancestor takes an event derived "
                  "from the event of a row below it, which SCXML's cond cannot say; export a child-first chart");
    return detail::to_scxml(detail::model_of(chart), true);
}

}  // namespace bsc
// end include/bsc/export/scxml.hpp
// end include/bsc/export.hpp
