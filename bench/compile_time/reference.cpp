// The reference translation unit of the compile-time gate (scripts/perf_gate.py): the
// hand-written flat workload, which includes no bsc header. The gate compares the 50-state bsc
// probe with it, compiled alternately on the same machine, so that what the machine's speed
// and load do to both cancel out of the ratio.

#include "flat/flat_hand.cpp"
