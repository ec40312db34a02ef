// The driver of the instruction counts: `bench_<workload>_insns IMPLEMENTATION EVENTS` builds one
// machine of the implementation and processes EVENTS events of the workload's recorded
// sequence (from its start, wrapping around). scripts/benchmarks.py runs it under callgrind
// with EVENTS = N and EVENTS = 0; the difference divided by N is the instructions per event.

#include BENCH_WORKLOAD_HEADER

int main(int argc, char** argv) { return bench::drive<BENCH_WORKLOAD>(argc, argv); }
