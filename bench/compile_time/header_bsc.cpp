// The header probe: the small program of header_reference.cpp with bsc's front header included
// and nothing of it used, so that the difference of the two is what including bsc costs every
// translation unit (scripts/perf_gate.py's `header`, scripts/peer_compile.py).

#include <bsc/bsc.hpp>

#include "small_driver.hpp"

int main() { return probe_driver::program_without_chart(); }
