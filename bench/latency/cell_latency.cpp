// The cycle latency of the manufacturing cell's controller (examples/manufacturing_cell): one
// step of the controller in every state of the closed loop (controller and finite plant,
// examples/manufacturing_cell/verification.hpp), with the sensors the plant presents there.
// The loop is explored; each of its states gives the controller's state and inputs, and
// bsc::measure_latency times one step from each. docs/benchmarks.md shows its output.

#include <cstdio>
#include <string>
#include <vector>

#include <bsc/benchmark.hpp>
#include <bsc/bsc.hpp>
#include <bsc/verify.hpp>

#include "manufacturing_cell/verification.hpp"

int main() {
    using controller = bsc::machine<bsc::chart_ref<cell::chart>, bsc::scan_policy>;
    bsc::verify::explorer loop{cell::finite::model(bsc::chart_ref<cell::chart>{})};
    loop.run();
    std::vector<controller> starts;
    for (std::size_t i = 0; i < loop.count(); ++i) {
        auto s = loop.at(i);
        cell::finite::present(s.plant, s.controller.context());
        starts.push_back(s.controller);
    }
    // One alternative per state: the inputs are already those the plant presents.
    bsc::verify::cycle_model scan{controller{bsc::chart_ref<cell::chart>{}, cell::data{}}, cell::finite::period, 1,
                                  [](cell::data const&, std::size_t) {},
                                  [](std::size_t) { return std::string("scan"); }};
    bsc::latency_options options;
    options.starts_are_every_state = loop.stats().complete;
    auto const report = bsc::measure_latency(scan, std::span<controller const>{starts}, options);
    std::fputs(report.to_string().c_str(), stdout);
    return report.pairs == loop.count() && !report.worst.empty() ? 0 : 1;
}
