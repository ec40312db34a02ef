// Workload wide, bsc's table-driven back end (bsc::table::machine): wide_bsc.cpp's implementation,
// in a translation unit of its own.

#define BENCH_BSC_TABLE 1
#include "wide_bsc.cpp"
