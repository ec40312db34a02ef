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

inline std::string scxml_script(std::string_view action) {
    return "<script>/* " + xml_escaped(replace_all(std::string(action), "*/", "* /")) + " */</script>";
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

inline void scxml_transition(diagram const& m, transition_info const& t, int level, std::string& out) {
    auto const pad = indent(level);
    if (t.defers) {  // SCXML has no deferral: a comment in its place
        out += pad + "<!-- " + scxml_comment(t.label()) + ": the event is deferred (UML), which SCXML cannot say -->\n";
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
    if (t.action.empty())
        out += "/>\n";
    else
        out += ">\n" + pad + "    " + scxml_script(t.action) + "\n" + pad + "</transition>\n";
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

inline void scxml_state(diagram const& m, int s, int level, std::string& out) {
    auto const& st = m[s];
    auto const pad = indent(level);
    if (st.node_kind == kind::history) {  // a history state and its default transition
        out += pad + "<history id=\"" + st.id + "\" type=\"" + (st.hist == history::deep ? "deep" : "shallow") +
               "\">\n";
        out += pad + "    <transition target=\"" + m[st.initial].id + "\"";
        if (st.initial_actions.empty()) {
            out += "/>\n";
        } else {
            out += ">\n";
            for (auto const& a : st.initial_actions) out += pad + "        " + scxml_script(a) + "\n";
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
    out += pad + "<" + element + " id=\"" + st.id + "\"";
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
        for (auto const& a : st.initial_actions) out += inner + "        " + scxml_script(a) + "\n";
        out += inner + "    </transition>\n" + inner + "</initial>\n";
    }
    if (st.initial >= 0 && st.hist != history::none) {
        auto const h = history_id(m, s);
        out += inner + "<initial>\n" + inner + "    <transition target=\"" + h + "\"/>\n" + inner + "</initial>\n";
        out += inner + "<history id=\"" + h + "\" type=\"" + (st.hist == history::deep ? "deep" : "shallow") + "\">\n" +
               inner + "    <transition target=\"" + m[st.initial].id + "\"/>\n" + inner + "</history>\n";
    }
    for (auto const& a : st.entry) out += inner + "<onentry>" + scxml_script(a) + "</onentry>\n";
    for (auto const& a : st.exit) out += inner + "<onexit>" + scxml_script(a) + "</onexit>\n";
    for (auto const& t : m.transitions)
        if (t.source == s) scxml_transition(m, t, level + 1, out);
    if (s == 0 && halts(m))
        out += inner + "<transition event=\"done.state." + m[0].id + "\" target=\"" + m[0].id + "_halted\"/>\n";
    for (int const c : st.children) scxml_state(m, c, level + 1, out);
    out += pad + "</" + element + ">\n";
}

inline std::string to_scxml(diagram const& m) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<!-- The chart " + scxml_comment(m[0].label) +
           ": cond names the guard, the <script> comments name the actions. -->\n";
    if (m.order == priority::parent_first)
        out +=
            "<!-- Parent-first priority: a transition's cond also negates the guards of its source's ancestors' "
            "transitions on the same event, which the chart tries first. -->\n";
    out += "<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" name=\"" + m[0].id + "\" initial=\"" +
           m[0].id + "\">\n";
    scxml_state(m, 0, 1, out);
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
    return detail::to_scxml(detail::model_of(chart));
}

}  // namespace bsc
