#pragma once
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

#include <bsc/detail/export/model.hpp>

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
