// Workload mcs, bsc's table-driven back end (bsc::table::machine): mcs_bsc.cpp's implementation,
// in a translation unit of its own.

#define BENCH_BSC_TABLE 1
#include "mcs_bsc.cpp"
