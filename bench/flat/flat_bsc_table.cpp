// Workload flat, bsc's table-driven back end (bsc::table::machine): flat_bsc.cpp's implementation,
// in a translation unit of its own.

#define BENCH_BSC_TABLE 1
#include "flat_bsc.cpp"
