// Writes the diagrams of the examples: <dir>/<name>.mmd (Mermaid) and <dir>/<name>.dot
// (Graphviz) for each chart below, and with --all also <name>.puml (PlantUML) and <name>.scxml,
// and the chart of tests/export/beyond_core_chart.hpp in all four.
// scripts/diagrams.py runs it on docs/diagrams/, renders the SVGs and updates the Diagram
// sections of the example pages; the ctests exports.* run it with --all on a directory of the
// build, check the SCXML and render the DOT, and diagrams_up_to_date compares with docs/.
//
//   export_diagrams [--all] <dir>

#include <bsc/export.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include "../../examples/eca_cell/pause.hpp"
#include "../../examples/filling_station/station.hpp"
#include "../../examples/manufacturing_cell/controller.hpp"
#include "../../examples/mcs/mcs.hpp"
#include "../../examples/production_cell/controllers.hpp"
#include "../../tests/export/beyond_core_chart.hpp"

namespace {

bool write(std::string const& path, std::string const& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    return static_cast<bool>(out);
}

bool all_formats = false;

template <class Chart>
bool export_chart(std::string const& dir, char const* name, Chart const& chart) {
    std::string const base = dir + "/" + name;
    bool ok = write(base + ".mmd", bsc::to_mermaid(chart)) && write(base + ".dot", bsc::to_dot(chart));
    if (all_formats)
        ok = ok && write(base + ".puml", bsc::to_plantuml(chart)) && write(base + ".scxml", bsc::to_scxml(chart));
    if (!ok) std::fprintf(stderr, "export_diagrams: cannot write %s.*\n", base.c_str());
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    all_formats = argc == 3 && std::string_view(argv[1]) == "--all";
    if (argc != (all_formats ? 3 : 2)) {
        std::fprintf(stderr, "usage: export_diagrams [--all] <dir>\n");
        return 2;
    }
    std::string const dir = argv[argc - 1];
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    bool ok = true;
    ok = export_chart(dir, "mcs", mcs::chart) && ok;
    ok = export_chart(dir, "manufacturing_cell", cell::chart) && ok;
    ok = export_chart(dir, "eca_cell", eca::main_chart) && ok;
    ok = export_chart(dir, "eca_cell_extended", eca::extended_main_chart) && ok;
    ok = export_chart(dir, "production_cell_feed_belt", pcell::feed_belt_chart) && ok;
    ok = export_chart(dir, "production_cell_table", pcell::table_chart) && ok;
    ok = export_chart(dir, "production_cell_robot", pcell::robot_chart) && ok;
    ok = export_chart(dir, "production_cell_press", pcell::press_chart) && ok;
    ok = export_chart(dir, "production_cell_deposit_belt", pcell::deposit_belt_chart) && ok;
    ok = export_chart(dir, "filling_station", filling::controller_chart) && ok;
    // Not an example: the constructs beyond the core, for the exports.* tests only.
    if (all_formats) ok = export_chart(dir, "beyond_core", beyond_core::chart) && ok;
    return ok ? 0 : 1;
}
