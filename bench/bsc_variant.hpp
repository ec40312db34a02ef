#pragma once
// What a bsc implementation of a workload is built as, for scripts/perf_gate.py's variants:
// -DBENCH_NOEXCEPT_ACTIONS=1 declares the chart's actions noexcept (BENCH_NOEXCEPT_ACTIONS is
// their noexcept operand), and -DBENCH_LEAN_POLICY=1 runs the compiled machine under
// bsc::lean_policy (bench::bsc_policy), and -DBENCH_PARENT_FIRST=1 declares the chart of a
// workload that reads bench::priority parent first. By default the actions are plain lambdas, as
// users write them, the policy is bsc::default_policy and the priority child first.

#include <bsc/outcome.hpp>
#include <bsc/priority.hpp>

#ifndef BENCH_NOEXCEPT_ACTIONS
#define BENCH_NOEXCEPT_ACTIONS 0
#endif

namespace bench {
#if defined(BENCH_LEAN_POLICY) && BENCH_LEAN_POLICY
using bsc_policy = bsc::lean_policy;
#else
using bsc_policy = bsc::default_policy;
#endif
#if defined(BENCH_PARENT_FIRST) && BENCH_PARENT_FIRST
inline constexpr bsc::priority priority = bsc::parent_first;
#else
inline constexpr bsc::priority priority = bsc::child_first;
#endif
}  // namespace bench
