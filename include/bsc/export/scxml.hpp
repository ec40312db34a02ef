#pragma once
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

#include <bsc/detail/export/model.hpp>

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
