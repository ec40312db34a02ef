#pragma once
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

#include <bsc/detail/export/model.hpp>

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
