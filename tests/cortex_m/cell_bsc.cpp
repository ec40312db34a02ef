// The manufacturing cell's controller (cell_controller.hpp) as a bsc machine of
// examples/manufacturing_cell's chart, under its bsc::scan_policy.

#include "cell_controller.hpp"

cell::machine subject{cell::chart};

int main(int argc, char** argv) { return scan::run<scan::bsc_adapter<subject>>(argc, argv); }
