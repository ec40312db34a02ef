#pragma once
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

#include <bsc/detail/export/model.hpp>

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
