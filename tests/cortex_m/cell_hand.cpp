// The manufacturing cell's controller written by hand as a scan (cell_controller.hpp).

#include "cell_controller.hpp"

scan::hand_written subject;

int main(int argc, char** argv) { return scan::run<scan::hand_adapter<subject>>(argc, argv); }
