#pragma once
// Coverage of a chart by the explored state space: the states never active in any reachable
// state and the transition rows never fired on any explored step. Unlike the static checks,
// this accounts for guards and data: a row whose guard can never hold is reported here.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <bsc/machine.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/verify/explorer.hpp>

namespace bsc::verify {

/// An observer that records which rows fire. Give it to the explored machine:
/// `bsc::machine<decltype(chart), bsc::default_policy, bsc::verify::row_recorder>`; copies of
/// the machine share the record.
struct row_recorder {
    std::vector<bool>* fired = nullptr;
    void on_row(int row) {
        if (fired && static_cast<std::size_t>(row) < fired->size()) (*fired)[static_cast<std::size_t>(row)] = true;
    }
};

struct coverage_report {
    std::vector<std::string> dead_states;       ///< never active in an explored state
    std::vector<std::string> dead_transitions;  ///< never fired on an explored step
    bool complete() const { return dead_states.empty() && dead_transitions.empty(); }
    std::string to_string() const {
        std::string out;
        for (auto const& s : dead_states) out += "never active: " + s + '\n';
        for (auto const& t : dead_transitions) out += "never fired: " + t + '\n';
        return out.empty() ? "every state and transition is exercised\n" : out;
    }
};

}  // namespace bsc::verify

namespace bsc::detail {
template <class Row>
std::string trigger_name() {
    if constexpr (bsc::detail::is_timeout_row<Row>)
        return "after";
    else if constexpr (std::is_void_v<typename bsc::detail::trigger_event<Row>::type>)
        return "[eventless]";
    else
        return std::string(name_of<typename bsc::detail::trigger_event<Row>::type>);
}
}  // namespace bsc::detail

namespace bsc::verify {

/// "Source + event -> Target" (or "Source + event (internal)") for each transition row of a
/// chart, by position in make_chart; empty for entry and exit rows.
template <class Chart>
std::vector<std::string> row_names() {
    using model = bsc::detail::chart_model<std::remove_cv_t<Chart>>;
    std::vector<std::string> names(static_cast<std::size_t>(model::R));
    // clang-format off
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (
            [&] {
                using R = typename model::template row_at<static_cast<int>(I)>;
                if constexpr (bsc::detail::is_transition_row<R>) {
                    std::string n = std::string(name_of<typename R::source>) + " + " + detail::trigger_name<R>();
                    if constexpr (std::is_same_v<typename R::target, bsc::detail::no_target>)
                        n += " (internal)";
                    else
                        n += " -> " + std::string(name_of<typename R::target>);
                    names[I] = n;
                }
            }(),
            ...);
    }(std::make_index_sequence<static_cast<std::size_t>(model::R)>{});
    // clang-format on
    return names;
}

/// Coverage of the chart of the machines that `get(state)` returns, over an explorer that
/// has run with a row_recorder writing to `fired`.
template <class Model, class Get>
coverage_report coverage(explorer<Model>& ex, std::vector<bool> const& fired, Get get) {
    ex.run();
    using machine_type = std::remove_cvref_t<decltype(get(ex.at(0)))>;
    using chart = typename machine_type::chart_type;
    using model = bsc::detail::chart_model<chart>;
    std::vector<bool> seen(static_cast<std::size_t>(model::N), false);
    for (std::size_t i = 0; i < ex.count(); ++i) {
        auto const s = ex.at(i);
        auto const active = bsc::detail::access::active_flags(get(s));
        for (std::size_t k = 0; k < active.size(); ++k) seen[k] = seen[k] || active[k];
    }
    coverage_report report;
    constexpr auto const& names = bsc::detail::state_names_of<model>;
    for (std::size_t k = 1; k < seen.size(); ++k)  // (a history state is never active: not dead)
        if (!seen[k] && model::tree.kinds[k] != bsc::detail::kind::history) report.dead_states.emplace_back(names[k]);
    auto const rows = row_names<chart>();
    for (std::size_t r = 0; r < rows.size(); ++r)
        if (!rows[r].empty() && (r >= fired.size() || !fired[r])) report.dead_transitions.push_back(rows[r]);
    return report;
}

/// Coverage for models whose state is the machine itself.
template <class Model>
coverage_report coverage(explorer<Model>& ex, std::vector<bool> const& fired) {
    return coverage(
        ex, fired, [](auto const& m) -> auto const& { return m; });
}

}  // namespace bsc::verify
