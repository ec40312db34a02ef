// The reference of the header probe (header_bsc.cpp): the same small program without bsc.

#include "small_driver.hpp"

int main() { return probe_driver::program_without_chart(); }
