// Workload deep, bsc's table-driven back end (bsc::table::machine): deep_bsc.cpp's implementation,
// in a translation unit of its own.

#define BENCH_BSC_TABLE 1
#include "deep_bsc.cpp"
