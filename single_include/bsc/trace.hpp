#pragma once
// bsc::tracer and bsc::trace_buffer - the trace stream, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/trace.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/trace.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_TRACE_HPP
#define BSC_SINGLE_INCLUDE_BSC_TRACE_HPP
// bsc::tracer: an observer that writes what a machine does as a compact binary trace into a
// bsc::trace_buffer, for a file (record now, replay later) or a socket (watch it live). The
// chart's dictionary (its states, events and, at the first sample, its context's members) is
// written once, then every record carries numbers (docs/trace.md has the format):
//
//   std::array<std::byte, 8192> storage;
//   bsc::trace_buffer buffer{storage};
//   bsc::machine m{chart, ctx{}, bsc::tracer{chart, buffer}};
//   m.step(0s);
//   m.observer().sample(m);   // the channels, timers and variables that changed
//   // drain `buffer` to a file or a socket; bsc::trace_reader reads it back
//
// Opt-in: <bsc/bsc.hpp> does not include it, and a machine without it pays nothing. With it,
// each record costs a frame of 7 bytes plus its payload (an exit or entry: 9 bytes) and the
// instructions docs/trace.md gives; it never blocks. It allocates where it writes names: the
// dictionary (construction, write_dictionary) and sample()'s first call, and in sample() for the
// names of array elements; the hooks never allocate.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

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
// begin include/bsc/detail/member_path.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
// The dotted name of a member during a named walk of a context (detail/members.hpp): "axis.position",
// "dwell.running". The explorer's codec names the fields of a state with it, the trace names the
// members it samples, and the inspector finds the input a page sets by it. Its own header: the
// machines' walks name nothing and need no strings.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bsc::detail {

class member_path {
public:
    /// Enters the scope `name` (an unnamed one, the walk's root, adds nothing); each is left again
    /// in order.
    void enter(std::string_view name) {
        starts_.push_back(text_.size());
        if (name.empty()) return;
        if (!text_.empty()) text_ += '.';
        text_ += name;
    }
    void leave() {
        if (starts_.empty()) return;
        text_.resize(starts_.back());
        starts_.pop_back();
    }
    /// The full name of the member `name` in the present scope (of "" the scope's own).
    std::string of(std::string_view name) const {
        if (text_.empty()) return std::string{name};
        return name.empty() ? text_ : text_ + "." + std::string{name};
    }
    /// Back to no scope, keeping the memory, so that a walk after the first allocates nothing.
    void clear() {
        text_.clear();
        starts_.clear();
    }

private:
    std::string text_;
    std::vector<std::size_t> starts_;  // text_'s length before each scope entered
};

}  // namespace bsc::detail
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_MEMBER_PATH_HPP
// end include/bsc/detail/member_path.hpp
// begin include/bsc/detail/recorded_members.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
// The members a recorder shows (the waveform, the trace stream): the channels of a scalar type,
// the timers and the plain scalar variables of a context, walked by the member layer
// (detail/members.hpp) with their names, each leaf given as a kind, a width and a value.

#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>


namespace bsc::detail::recorded {

// integer: a signed integral type; reg: an unsigned one, an enum or a bool wider than a wire.
enum class var_kind : std::uint8_t { wire, integer, reg, real, string };

// One variable's value: the bits of a wire or integer, a real, or a string's text (a state's
// name, which lives as long as the program).
struct value {
    std::uint64_t bits = 0;
    double real = 0;
    std::string_view text;
    friend bool operator==(value const& a, value const& b) {
        // Reals compare by representation, so that a NaN equals itself and is written once.
        return a.bits == b.bits && std::bit_cast<std::uint64_t>(a.real) == std::bit_cast<std::uint64_t>(b.real) &&
               a.text == b.text;
    }
};

template <class T>
constexpr bool is_scalar_variable = std::is_arithmetic_v<T> || std::is_enum_v<T>;

template <class T>
value scalar_value(T v) {
    value out;
    if constexpr (std::is_floating_point_v<T>) {
        out.real = static_cast<double>(v);
    } else if constexpr (std::is_enum_v<T>) {
        out.bits = static_cast<std::uint64_t>(
            static_cast<std::make_unsigned_t<std::underlying_type_t<T>>>(static_cast<std::underlying_type_t<T>>(v)));
    } else if constexpr (std::is_same_v<T, bool>) {
        out.bits = v ? 1 : 0;
    } else {
        out.bits = static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(v));
    }
    return out;
}

template <class T>
constexpr var_kind var_kind_of() {
    if constexpr (std::is_same_v<T, bool>)
        return var_kind::wire;
    else if constexpr (std::is_floating_point_v<T>)
        return var_kind::real;
    else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>)
        return var_kind::integer;
    else
        return var_kind::reg;
}

template <class T>
constexpr unsigned width_of() {
    if constexpr (std::is_same_v<T, bool>)
        return 1;
    else if constexpr (std::is_floating_point_v<T>)
        return 64;
    else
        return 8 * sizeof(T);
}

// What the recorder shows: a channel of a scalar type, a timer, a plain scalar variable, found
// by the member layer (detail/members.hpp) as the machine finds its channels.
template <class T>
constexpr bool is_recorded() {
    if constexpr (is_channel<T>)
        return is_scalar_variable<channel_value<T>>;
    else
        return is_timer<T> || is_scalar_variable<T>;
}

// An array's element as the recorders name it: name_0, name_1, ...
inline std::string element_name(std::string_view name, std::size_t i) {
    return std::string{name} + "_" + std::to_string(i);
}

// Walks a context's recorded members, calling the visitor's scope(name), upscope() and
// var(kind, width, name, value), in declaration order: a struct is a scope, a timer a scope of
// three variables, an array's elements are name_0, name_1, ...
template <class Visitor>
struct recorded_members {
    static constexpr bool named = true;
    template <class T>
    static constexpr bool visits = is_recorded<T>();
    Visitor& v;
    std::string element_name(std::string_view name, std::size_t i) const { return recorded::element_name(name, i); }
    void enter(std::string_view name) { v.scope(name); }
    void leave() { v.upscope(); }
    template <class T>
    void leaf(T const& member, std::string_view name) {
        if constexpr (is_channel<T>) {
            using V = channel_value<T>;
            v.var(var_kind_of<V>(), width_of<V>(), name, scalar_value(member.get()));
        } else if constexpr (is_timer<T>) {
            v.scope(name);
            v.var(var_kind::wire, 1, "running", scalar_value(member.running()));
            v.var(var_kind::wire, 1, "expired", scalar_value(member.expired()));
            v.var(var_kind::integer, 64, "elapsed", scalar_value(static_cast<std::int64_t>(member.elapsed().count())));
            v.upscope();
        } else {
            v.var(var_kind_of<T>(), width_of<T>(), name, scalar_value(member));
        }
    }
};

}  // namespace bsc::detail::recorded
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_RECORDED_MEMBERS_HPP
// end include/bsc/detail/recorded_members.hpp
// begin include/bsc/detail/trace/format.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
#define BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
// The trace stream's frame (docs/trace.md): what bsc::trace_buffer writes and
// bsc::trace_reader reads, in one place.
//
//   offset  size  field
//   0       1     sync byte 0xB5
//   1       1     record type (record_type)
//   2       2     sequence number, little-endian, +1 per frame written or dropped (mod 2^16)
//   4       1     payload length n (0 to 255)
//   5       n     payload, its integers little-endian
//   5+n     2     CRC-16/CCITT-FALSE of bytes 1 to 4+n, little-endian
//
// A reader finds frames by the sync byte and keeps one only if its checksum holds, so that it
// resynchronises after damage; a gap in the sequence numbers shows a frame lost on the way.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace bsc::detail::trace {

inline constexpr std::byte sync{0xB5};
inline constexpr std::size_t header_size = 5;   // sync, type, sequence, length
inline constexpr std::size_t trailer_size = 2;  // the checksum
inline constexpr std::size_t max_payload = 255;
inline constexpr std::size_t max_frame = header_size + max_payload + trailer_size;
inline constexpr std::uint8_t format_version = 1;

// The records. A hello starts a dictionary: the chart's name and how many states, events and
// transition rows it has; the state, event, row and member records that follow name each number.
enum class record_type : std::uint8_t {
    hello = 0x01,          // version u8, states u16, events u16, rows u16, chart name
    state = 0x02,          // state u16, parent u16 (0xFFFF: none), kind u8 (dsl kind), name
    event = 0x03,          // event u16, name
    row = 0x05,            // row u16, source u16, target u16 (0xFFFF: internal), trigger u16, flags u8
                           // (1: defers, 2: local), label ("event [guard] / action")
    member = 0x04,         // member u16, kind u8 (var kind), width u8, name (dotted path)
    configuration = 0x06,  // begins u8 (1: a configuration begins, 0: the last one goes on), then
                           // the active states, u16 each (up to 127 a record)
    dispatch = 0x10,       // time i64 ns, event u16
    cycle = 0x11,          // time i64 ns
    cycle_end = 0x12,      // (empty)
    exit = 0x13,           // state u16
    entry = 0x14,          // state u16
    transition = 0x15,     // row u16, source u16, target u16 (0xFFFF: internal), trigger u16, [delay i64 ns]
    deferral = 0x16,       // state u16, event u16
    values = 0x20,         // time i64 ns, then (member u16, value u64) pairs: what changed
    overflow = 0x30,       // frames dropped so far u64: written when room returns after a drop
};

// Numbers a trigger takes besides the chart's events.
inline constexpr std::uint16_t no_number = 0xFFFF;  // no parent; internal target; an unnamed event
inline constexpr std::uint16_t eventless_trigger = 0xFFFE;
inline constexpr std::uint16_t timeout_trigger = 0xFFFD;  // the record carries the delay

// CRC-16/CCITT-FALSE (polynomial 0x1021, initial 0xFFFF): a table of 256 entries, one lookup a byte.
inline constexpr std::array<std::uint16_t, 256> crc_table = [] {
    std::array<std::uint16_t, 256> t{};
    for (unsigned i = 0; i < 256; ++i) {
        unsigned c = i << 8;
        for (int b = 0; b < 8; ++b) c = (c & 0x8000u) ? (c << 1) ^ 0x1021u : c << 1;
        t[i] = static_cast<std::uint16_t>(c & 0xFFFFu);
    }
    return t;
}();

constexpr std::uint16_t crc_update(std::uint16_t crc, std::byte b) {
    auto const index = static_cast<unsigned>((crc >> 8) ^ static_cast<unsigned>(b)) & 0xFFu;
    return static_cast<std::uint16_t>((crc << 8) ^ crc_table[index]);
}
constexpr std::uint16_t crc(std::span<std::byte const> bytes, std::uint16_t start = 0xFFFF) {
    for (std::byte b : bytes) start = crc_update(start, b);
    return start;
}

// Little-endian integers into and out of a payload.
template <class T>
constexpr std::byte* put(std::byte* out, T value) {
    auto v = static_cast<std::uint64_t>(value);
    for (std::size_t i = 0; i < sizeof(T); ++i, v >>= 8) *out++ = static_cast<std::byte>(v & 0xFFu);
    return out;
}
template <class T>
constexpr T get(std::byte const* in) {
    std::uint64_t v = 0;
    for (std::size_t i = sizeof(T); i-- > 0;) v = (v << 8) | static_cast<std::uint64_t>(in[i]);
    return static_cast<T>(v);
}

}  // namespace bsc::detail::trace
#endif  // BSC_SINGLE_INCLUDE_BSC_DETAIL_TRACE_FORMAT_HPP
// end include/bsc/detail/trace/format.hpp
// begin include/bsc/trace_buffer.hpp
#ifndef BSC_SINGLE_INCLUDE_BSC_TRACE_BUFFER_HPP
#define BSC_SINGLE_INCLUDE_BSC_TRACE_BUFFER_HPP
// bsc::trace_buffer: the bounded ring a bsc::tracer writes its frames into and a program drains
// to a file or a socket. It never allocates (the storage is the caller's) and never blocks: a
// frame that does not fit is dropped whole and counted, and an overflow record says so when
// room returns, so that a reader sees the loss (docs/trace.md).
//
//   std::array<std::byte, 4096> storage;
//   bsc::trace_buffer buffer{storage};
//   ...
//   std::array<std::byte, 512> chunk;
//   while (auto n = buffer.read(chunk)) file.write(reinterpret_cast<char const*>(chunk.data()), n);
//
// One thread may write (the machine's) while one other reads (a server's): the positions are
// atomic, each side moves its own.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>


namespace bsc {

/// A ring of trace frames over storage the caller owns (which must outlive it).
class trace_buffer {
public:
    /// Frames go into `storage`; a frame longer than storage.size() is always dropped.
    explicit trace_buffer(std::span<std::byte> storage) noexcept : storage_(storage) {}

    trace_buffer(trace_buffer const&) = delete;
    trace_buffer& operator=(trace_buffer const&) = delete;

    /// Appends one frame of type `type` with `payload` (at most 255 bytes, the rest is cut), or
    /// drops it if it does not fit. Either way it takes the next sequence number. After a drop,
    /// the next frame that fits is preceded by an overflow record with the count of drops.
    /// Returns whether the frame was written.
    bool write(detail::trace::record_type type, std::span<std::byte const> payload) noexcept {
        namespace t = detail::trace;
        if (payload.size() > t::max_payload) payload = payload.first(t::max_payload);
        std::size_t const needed = t::header_size + payload.size() + t::trailer_size;
        std::size_t constexpr overflow_frame = t::header_size + 8 + t::trailer_size;
        std::size_t const room = storage_.size() -
                                 used(head_.load(std::memory_order_relaxed), tail_.load(std::memory_order_acquire));
        if (overflow_pending_) {
            if (room < overflow_frame + needed) return drop();
            std::byte count[8];
            t::put(count, dropped_.load(std::memory_order_relaxed));
            append(t::record_type::overflow, count);
            overflow_pending_ = false;
        } else if (room < needed) {
            return drop();
        }
        append(type, payload);
        return true;
    }

    /// Moves the oldest bytes, up to out.size(), into `out`; returns how many. Frames may be cut
    /// between two reads: a reader joins the pieces.
    std::size_t read(std::span<std::byte> out) noexcept {
        std::size_t const tail = tail_.load(std::memory_order_relaxed);
        std::size_t const available = used(head_.load(std::memory_order_acquire), tail);
        std::size_t const n = available < out.size() ? available : out.size();
        if (n > 0) {
            std::size_t const at = index(tail);
            std::size_t const first = n < storage_.size() - at ? n : storage_.size() - at;  // up to the ring's end
            std::memcpy(out.data(), storage_.data() + at, first);
            std::memcpy(out.data() + first, storage_.data(), n - first);
        }
        tail_.store(advance(tail, n), std::memory_order_release);
        return n;
    }

    /// The bytes waiting to be read.
    std::size_t size() const noexcept {
        return used(head_.load(std::memory_order_acquire), tail_.load(std::memory_order_acquire));
    }
    /// The storage's size.
    std::size_t capacity() const noexcept { return storage_.size(); }
    /// The frames dropped for want of room, since construction.
    std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }
    /// The frames written, overflow records included, since construction.
    std::uint64_t written() const noexcept { return written_.load(std::memory_order_relaxed); }

private:
    bool drop() noexcept {
        ++sequence_;
        dropped_.store(dropped_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
        overflow_pending_ = true;
        return false;
    }

    // The frame is made whole first, so that its checksum runs over one array and it goes into
    // the ring in at most two copies.
    void append(detail::trace::record_type type, std::span<std::byte const> payload) noexcept {
        namespace t = detail::trace;
        std::byte frame[t::max_frame];
        frame[0] = t::sync;
        frame[1] = static_cast<std::byte>(type);
        t::put(frame + 2, sequence_++);
        frame[4] = static_cast<std::byte>(payload.size());
        if (!payload.empty()) std::memcpy(frame + t::header_size, payload.data(), payload.size());
        std::size_t const body = t::header_size + payload.size();
        t::put(frame + body, t::crc(std::span<std::byte const>{frame + 1, body - 1}));
        std::size_t const size = body + t::trailer_size;
        std::size_t const head = head_.load(std::memory_order_relaxed);
        std::size_t const at = index(head);
        std::size_t const first = size < storage_.size() - at ? size : storage_.size() - at;
        std::memcpy(storage_.data() + at, frame, first);
        std::memcpy(storage_.data(), frame + first, size - first);
        head_.store(advance(head, size), std::memory_order_release);
        written_.store(written_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    }

    // Positions run over twice the storage's size, so that a full ring (head a lap ahead of tail)
    // differs from an empty one, and never wrap the size type, whatever its width.
    std::size_t used(std::size_t head, std::size_t tail) const noexcept {
        return head >= tail ? head - tail : head + 2 * storage_.size() - tail;
    }
    std::size_t index(std::size_t position) const noexcept {
        return position < storage_.size() ? position : position - storage_.size();
    }
    std::size_t advance(std::size_t position, std::size_t n) const noexcept {
        std::size_t const next = position + n;  // n <= the storage's size: no overflow below twice it
        return next < 2 * storage_.size() ? next : next - 2 * storage_.size();
    }

    std::span<std::byte> storage_;
    std::atomic<std::size_t> head_{0};  // where the writer writes next, in [0, 2 * size): moved by the writer only
    std::atomic<std::size_t> tail_{0};  // where the reader reads next, in [0, 2 * size): moved by the reader only
    std::atomic<std::uint64_t> dropped_{0};
    std::atomic<std::uint64_t> written_{0};
    std::uint16_t sequence_ = 0;
    bool overflow_pending_ = false;
};

}  // namespace bsc
#endif  // BSC_SINGLE_INCLUDE_BSC_TRACE_BUFFER_HPP
// end include/bsc/trace_buffer.hpp

namespace bsc {

/// Writes a machine of chart type Chart into a trace_buffer: construct it with the buffer (which
/// must outlive it) and give it to the machine as its observer. Requirements: the chart has at
/// most 65,533 states and events (numbers 0xFFFD to 0xFFFF are reserved).
template <class Chart>
class tracer {
    using model = detail::chart_model<std::remove_cv_t<Chart>>;
    using events = typename model::events;
    static_assert(model::N < detail::trace::timeout_trigger && events::size < detail::trace::timeout_trigger,
                  "bsc::tracer: a chart with more than 65,532 states or events cannot be traced");

public:
    using chart_type = Chart;

    /// Writes the dictionary of `chart`'s states, events and transitions into `buffer`. Both
    /// must outlive the tracer.
    tracer(Chart const& chart, trace_buffer& buffer) : chart_(&chart), buffer_(&buffer) { write_dictionary(); }

    /// The ring it writes into.
    trace_buffer& buffer() const { return *buffer_; }

    /// Writes the dictionary again (for a reader that joins late): the hello, the states,
    /// events and transitions now, the members at the next sample(). The transitions' labels
    /// are built as the exports build them (with std::string: this allocates).
    void write_dictionary() {
        namespace t = detail::trace;
        static constexpr auto const& names = detail::state_names_of<model>;
        std::byte payload[t::max_payload];
        std::byte* p = payload;
        p = t::put(p, t::format_version);
        p = t::put(p, static_cast<std::uint16_t>(model::N));
        p = t::put(p, static_cast<std::uint16_t>(events::size));
        auto const diagram = detail::model_of(*chart_);
        p = t::put(p, static_cast<std::uint16_t>(diagram.transitions.size()));
        write(t::record_type::hello, with_text(payload, p, names[1]));
        for (std::size_t s = 0; s < names.size(); ++s) {
            p = t::put(payload, static_cast<std::uint16_t>(s));
            int const parent = model::tree.parent[s];
            p = t::put(p, parent < 0 ? t::no_number : static_cast<std::uint16_t>(parent));
            p = t::put(p, static_cast<std::uint8_t>(model::tree.kinds[s]));
            write(t::record_type::state, with_text(payload, p, s == 0 ? std::string_view{"(top)"} : names[s]));
        }
        // clang-format off
        [&]<class... Es>(detail::type_list<Es...>) {
            std::uint16_t number = 0;
            ((p = t::put(payload, number++), write(t::record_type::event, with_text(payload, p, event_name<Es>))), ...);
        }(events{});
        // clang-format on
        for (auto const& row : diagram.transitions) {
            p = t::put(payload, static_cast<std::uint16_t>(row.row));
            p = t::put(p, static_cast<std::uint16_t>(row.source + 1));  // the diagram leaves out the top
            p = t::put(p, row.target < 0 ? t::no_number : static_cast<std::uint16_t>(row.target + 1));
            p = t::put(p, row.trigger == detail::trigger_kind::timeout
                              ? t::timeout_trigger
                              : row_triggers[static_cast<std::size_t>(row.row)]);
            p = t::put(p, static_cast<std::uint8_t>((row.defers ? 1 : 0) | (row.local ? 2 : 0)));
            write(t::record_type::row, with_text(payload, p, row.label()));
        }
        members_named_ = false;
    }

    /// Writes the dictionary again and then the machine's active configuration, so that a
    /// reader that joins now knows where the machine stands (the inspector does this when it
    /// lets the oldest part of its history go).
    template <class Machine>
    void write_dictionary(Machine const& machine) {
        namespace t = detail::trace;
        write_dictionary();
        auto const active = detail::access::active_flags(machine);
        std::byte payload[t::max_payload];
        std::byte* p = t::put(payload, std::uint8_t{1});
        for (std::size_t s = 1; s < active.size(); ++s) {
            if (!active[s]) continue;
            if (static_cast<std::size_t>(p - payload) + 2 > t::max_payload) {
                write(t::record_type::configuration, std::span<std::byte const>{payload, p});
                p = t::put(payload, std::uint8_t{0});
            }
            p = t::put(p, static_cast<std::uint16_t>(s));
        }
        write(t::record_type::configuration, std::span<std::byte const>{payload, p});
    }

    /// Writes the machine's channels, timers and scalar variables that changed since the last
    /// sample (all of them, with their names, at the first), at the machine's time. Call it
    /// after each step or dispatch you want the values of. Allocates at the first call, and
    /// where it names the elements of an array member.
    template <class Machine>
    void sample(Machine const& machine) {
        using context = typename Machine::context_type;
        using visitor = detail::recorded::recorded_members<value_writer>;
        if constexpr (detail::reaches<visitor, context>()) {
            value_writer writer{*this, machine.now().count()};
            visitor members{writer};
            detail::walk(machine.context(), members, std::string_view{});
            writer.flush();
            members_named_ = true;
        }
    }

    // ---- the observer hooks (observer.hpp) ------------------------------------------------
    template <class E>
    void on_dispatch(E const&) {
        std::byte payload[10];
        detail::trace::put(detail::trace::put(payload, time_), event_number<E>());
        write(detail::trace::record_type::dispatch, payload);
    }
    void on_cycle(duration now) {
        time_ = now.count();
        std::byte payload[8];
        detail::trace::put(payload, time_);
        write(detail::trace::record_type::cycle, payload);
    }
    void on_cycle_end() { write(detail::trace::record_type::cycle_end, {}); }
    template <class State>
    void on_exit(State) {
        write_state(detail::trace::record_type::exit, state_number<typename State::type>());
    }
    template <class State>
    void on_entry(State) {
        write_state(detail::trace::record_type::entry, state_number<typename State::type>());
    }
    template <class Source, class E>
    void on_defer(Source, E const&) {
        deferring_ = true;
    }
    // The transition is written at on_row, which follows, so that one record holds the row too.
    template <class Source, class Target, class E>
    void on_transition(Source, Target, E const& e) {
        source_ = state_number<typename Source::type>();
        target_ = std::is_same_v<typename Target::type, internal> ? detail::trace::no_number
                                                                  : state_number<typename Target::type>();
        trigger_ = event_number<E>();
        if constexpr (std::is_same_v<E, timeout_elapsed>)
            delay_ = e.delay.count();
        else
            (void)e;
    }
    void on_row(int row) {
        namespace t = detail::trace;
        std::byte payload[16];
        if (deferring_) {
            deferring_ = false;
            t::put(t::put(payload, source_), trigger_);
            write(t::record_type::deferral, std::span<std::byte const>{payload, 4});
            return;
        }
        std::byte* p = t::put(payload, static_cast<std::uint16_t>(row));
        p = t::put(p, source_);
        p = t::put(p, target_);
        p = t::put(p, trigger_);
        if (trigger_ == t::timeout_trigger) p = t::put(p, delay_);
        write(t::record_type::transition, std::span<std::byte const>{payload, p});
    }

private:
    template <class S>
    static constexpr std::uint16_t state_number() {
        return static_cast<std::uint16_t>(model::template index_of_state<S>::value);
    }
    template <class E>
    static constexpr std::uint16_t event_number() {
        if constexpr (std::is_same_v<E, eventless>) {
            return detail::trace::eventless_trigger;
        } else if constexpr (std::is_same_v<E, timeout_elapsed>) {
            return detail::trace::timeout_trigger;
        } else {
            constexpr int at = detail::position_in<E, events>::value;
            constexpr int family = model::template trigger_of<E>::value;
            return at >= 0 ? static_cast<std::uint16_t>(at)
                           : (family >= 0 ? static_cast<std::uint16_t>(family) : detail::trace::no_number);
        }
    }

    // Each row's trigger by its type (an eventless row's, and a timeout's, as eventless: the
    // diagram tells the timeouts apart), as the transition records number it.
    // clang-format off
    static constexpr auto row_triggers = []<std::size_t... I>(std::index_sequence<I...>) {
        return std::array<std::uint16_t, sizeof...(I)>{
            event_number<detail::row_event_t<typename model::template row_at<static_cast<int>(I)>>>()...};
    }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
    // clang-format on

    void write(detail::trace::record_type type, std::span<std::byte const> payload) { buffer_->write(type, payload); }
    void write_state(detail::trace::record_type type, std::uint16_t state) {
        std::byte payload[2];
        detail::trace::put(payload, state);
        write(type, payload);
    }
    // The payload from `begin` to `end` followed by as much of `text` as fits.
    static std::span<std::byte const> with_text(std::byte* begin, std::byte* end, std::string_view text) {
        auto const room = detail::trace::max_payload - static_cast<std::size_t>(end - begin);
        std::size_t const n = text.size() < room ? text.size() : room;
        for (std::size_t i = 0; i < n; ++i) *end++ = static_cast<std::byte>(text[i]);
        return {begin, end};
    }

    // Receives the context's recorded members (detail/recorded_members.hpp) in walk order,
    // names them at the first sample and writes the values that changed, in frames of up to 24.
    struct value_writer {
        value_writer(tracer& owner, std::int64_t now) : self(owner), time(now), path(owner.path_) { path.clear(); }

        tracer& self;
        std::int64_t time;
        std::size_t next = 0;       // the member's number
        detail::member_path& path;  // the tracer's, whose memory each sample reuses
        std::byte payload[detail::trace::max_payload]{};
        std::byte* end = nullptr;

        void scope(std::string_view name) { path.enter(name); }
        void upscope() { path.leave(); }
        void var(detail::recorded::var_kind kind, unsigned width, std::string_view name,
                 detail::recorded::value const& v) {
            namespace t = detail::trace;
            std::size_t const number = next++;
            if (number >= t::no_number) return;  // past the numbers a record can carry
            if (!self.members_named_) {
                std::byte entry[t::max_payload];
                std::byte* p = t::put(entry, static_cast<std::uint16_t>(number));
                p = t::put(p, static_cast<std::uint8_t>(kind));
                p = t::put(p, static_cast<std::uint8_t>(width));
                std::string const full = path.of(name);
                self.write(t::record_type::member, with_text(entry, p, full));
            }
            std::uint64_t const bits = kind == detail::recorded::var_kind::real ? std::bit_cast<std::uint64_t>(v.real)
                                                                                : v.bits;
            if (self.last_.size() <= number) self.last_.resize(number + 1);
            if (self.members_named_ && self.last_[number] == bits) return;
            self.last_[number] = bits;
            if (end == nullptr || static_cast<std::size_t>(end - payload) + 10 > t::max_payload) {
                flush();
                end = t::put(payload, time);
            }
            end = t::put(t::put(end, static_cast<std::uint16_t>(number)), bits);
        }
        void flush() {
            if (end != nullptr && end - payload > 8)
                self.write(detail::trace::record_type::values, std::span<std::byte const>{payload, end});
            end = nullptr;
        }
    };

    Chart const* chart_;
    trace_buffer* buffer_;
    std::int64_t time_ = 0;  // the last cycle's time: a dispatch's too
    std::uint16_t source_ = 0, target_ = 0, trigger_ = 0;
    std::int64_t delay_ = 0;
    bool deferring_ = false;
    bool members_named_ = false;
    std::vector<std::uint64_t> last_;  // each member's last value written
    detail::member_path path_;         // the member names of sample()'s walk
};

template <class Chart>
tracer(Chart const&, trace_buffer&) -> tracer<Chart const>;

}  // namespace bsc
#endif  // BSC_SINGLE_INCLUDE_BSC_TRACE_HPP
// end include/bsc/trace.hpp
