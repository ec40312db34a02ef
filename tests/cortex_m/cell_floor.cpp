// The manufacturing cell's driver with a controller that does nothing of the cell's
// (scan::floor): the image the report measures the controllers' flash from.

#include "cell_controller.hpp"

scan::floor subject;

int main(int argc, char** argv) { return scan::run<scan::hand_adapter<subject>>(argc, argv); }
