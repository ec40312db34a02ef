#!/usr/bin/env python3
"""The performance gate: fails when bsc's dispatch or compile time grows past its recorded baseline.

    perf_gate.py instructions --compiler CXX [--record]
    perf_gate.py compile-time --compiler CXX [--record]

instructions: builds each dispatch workload of bench/ (flat, mcs, deep, wide, and the peers'
workloads ported: sml_simple, sml_composite, sml_complex, fsmb_large, fsmb_deep; flat with its
actions declared noexcept; flat, deep, wide and the ports with noexcept actions and
bsc::lean_policy: bsc
and the hand-written switch, -O2, no sanitizers; and the manufacturing cell's execution cycle,
bench_manufacturing_cell_insns, per cycle), counts with callgrind the instructions per event of
`bench_<workload>_insns IMPL N` minus `... IMPL 0`, divided by N, and fails if bsc's count of a
workload exceeds the baseline by more than 0.5 % (plus 0.1 instruction for rounding). Callgrind
counts are deterministic for a given compiler and library, so the margin is small; a change that
makes dispatch cheaper passes and should record the new, lower baseline.

compile-time: compiles each probe of COMPILE_PROBES alternately with its reference, five times
each: the 50-state flat chart (bench/compile_time/flat_bsc.cpp.in, bsc::machine<decltype(chart)>)
and the 200-state one (flat_bsc_ref.cpp.in, bsc::machine<bsc::chart_ref<chart>>), each against
bench/compile_time/reference.cpp (the hand-written flat workload, which includes the same standard
and benchmark headers); Boost.SML's CD player (bench/sml_simple/sml_simple_bsc.cpp), a small
chart, against the same chart written by hand (sml_simple_hand.cpp); and the front header alone
(bench/compile_time/header_bsc.cpp, <bsc/bsc.hpp> in a small program that uses none of it)
against the same program without it (header_reference.cpp). The CPU ratio is the median
of the five ratios probe / reference of a pair compiled one after the other (CPU time, user +
system), so that the speed and load of the machine cancel and one unusually quick or slow
compilation does not move it; the memory ratio is that of the largest peak memory of each. It
fails if a CPU ratio exceeds its baseline by more than 25 % or a memory ratio by more than 15 %.

Baselines are kept per compiler and major version in bench/baselines.json; --record writes the
measured values there instead of checking them. A compiler with no baseline is reported and the
script exits 77 (ctest counts the test as skipped). Exit 0: within the baseline; 1: over it.
"""

import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINES = ROOT / "bench" / "baselines.json"
# (name, bench/ directory, extra compile flags): flat_noexcept is the flat workload with its
# actions declared noexcept, where the machine keeps no record of failures; *_lean also runs the
# machine under bsc::lean_policy (no reentrancy test, no record of the last outcome); deep_parent_first
# declares the deep chart with parent-first priority (bench/bsc_variant.hpp), which must cost
# what child first does.
WORKLOADS = [("flat", "flat", []), ("flat_noexcept", "flat", ["-DBENCH_NOEXCEPT_ACTIONS=1"]),
             ("flat_lean", "flat", ["-DBENCH_NOEXCEPT_ACTIONS=1", "-DBENCH_LEAN_POLICY=1"]),
             ("mcs", "mcs", []), ("deep", "deep", []),
             ("deep_lean", "deep", ["-DBENCH_NOEXCEPT_ACTIONS=1", "-DBENCH_LEAN_POLICY=1"]),
             ("deep_parent_first", "deep", ["-DBENCH_PARENT_FIRST=1"]), ("wide", "wide", []),
             ("wide_lean", "wide", ["-DBENCH_NOEXCEPT_ACTIONS=1", "-DBENCH_LEAN_POLICY=1"])]
# The peers' own workloads, ported (Boost.SML's benchmark/ charts, fsm-benchmark's Large and
# Deep), as users write them and lean.
for _port in ["sml_simple", "sml_composite", "sml_complex", "fsmb_large", "fsmb_deep"]:
    WORKLOADS += [(_port, _port, []), (_port + "_lean", _port, ["-DBENCH_NOEXCEPT_ACTIONS=1", "-DBENCH_LEAN_POLICY=1"])]
# The manufacturing cell's execution cycle (bench/manufacturing_cell_bench.cpp, built as its own
# driver of instruction counts): instructions per cycle rather than per event.
WORKLOADS += [("cell", None, [])]
IMPLEMENTATIONS = ["bsc_compiled", "hand_written"]
EVENTS = 20000
INSTRUCTION_MARGIN = 0.005
INSTRUCTION_SLACK = 0.1
CPU_MARGIN = 0.25
MEMORY_MARGIN = 0.15
REPEATS = 5
SKIP = 77


def compiler_id(cxx):
    """'gcc-12' or 'clang-14', from the compiler's own version banner."""
    banner = subprocess.run([cxx, "--version"], capture_output=True, text=True, check=True).stdout
    kind = "clang" if "clang" in banner else "gcc"
    found = re.search(r"(\d+)\.\d+(\.\d+)?", banner.splitlines()[0])
    return f"{kind}-{found.group(1) if found else 'unknown'}"


def flags():
    return ["-std=c++20", "-O2", "-DNDEBUG", f"-I{ROOT / 'include'}", f"-I{ROOT / 'bench'}"]


def compile_object(cxx, source, out, extra=()):
    subprocess.run([cxx, *flags(), *extra, "-c", str(source), "-o", str(out)], check=True)


def callgrind_total(cmd, work):
    out = work / ("callgrind." + "_".join(Path(str(c)).name for c in cmd) + ".out")  # one per run: runs overlap
    run = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *map(str, cmd)],
                         capture_output=True, text=True)
    if run.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, cmd))} under callgrind failed:\n{run.stderr}")
    for line in out.read_text().splitlines():
        if line.startswith("totals:") or line.startswith("summary:"):
            return int(line.split()[1])
    raise RuntimeError("no totals in callgrind output")


def measure_workload(cxx, work, w, directory, extra):
    """Builds workload w and counts its instructions per event; returns (w, counts, report line)."""
    exe = work / f"{w}_insns"
    if directory is None:  # the cell
        subprocess.run([cxx, *flags(), "-DBENCH_CELL_INSNS=1", str(ROOT / "bench" / "manufacturing_cell_bench.cpp"),
                        "-lbenchmark", "-lpthread", "-o", str(exe)], check=True)
    else:
        objects = []
        for impl in ("bsc", "hand"):
            obj = work / f"{w}_{impl}.o"
            compile_object(cxx, ROOT / "bench" / directory / f"{directory}_{impl}.cpp", obj, extra)
            objects.append(str(obj))
        subprocess.run([cxx, *flags(), f'-DBENCH_WORKLOAD_HEADER="{directory}/{directory}_workload.hpp"',
                        f"-DBENCH_WORKLOAD={directory}_bench::workload", str(ROOT / "bench" / "insns_main.cpp"),
                        *objects, "-lbenchmark", "-lpthread", "-o", str(exe)], check=True)
    counts = {}
    for impl in IMPLEMENTATIONS:
        with_events = callgrind_total([exe, impl, EVENTS], work)
        without = callgrind_total([exe, impl, 0], work)
        counts[impl] = round((with_events - without) / EVENTS, 2)
    line = (f"{w}: " + ", ".join(f"{impl} {counts[impl]:.2f}" for impl in IMPLEMENTATIONS) +
            f" instructions/event (bsc / hand {counts['bsc_compiled'] / counts['hand_written']:.3f})")
    return w, counts, line


def measure_instructions(cxx, work):
    # The workloads are built and counted side by side, one per core (the test runs alone:
    # RUN_SERIAL). Callgrind counts instructions, not time, so the load does not change them.
    jobs = max(1, len(os.sched_getaffinity(0)))
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(lambda spec: measure_workload(cxx, work, *spec), WORKLOADS))
    counts = {}
    for w, workload_counts, line in results:
        counts[w] = workload_counts
        print(line)
    return counts


def check_instructions(measured, baseline):
    failures = []
    for w, impls in measured.items():
        if w not in baseline:
            failures.append(f"{w}: no baseline (record one with --record)")
            continue
        limit = baseline[w]["bsc_compiled"] * (1 + INSTRUCTION_MARGIN) + INSTRUCTION_SLACK
        if impls["bsc_compiled"] > limit:
            failures.append(f"{w}: bsc dispatch costs {impls['bsc_compiled']:.2f} instructions/event, over its "
                            f"baseline {baseline[w]['bsc_compiled']:.2f} (limit {limit:.2f})")
    return failures


def timed_compile(cxx, source, work):
    """CPU seconds (user + system) and peak memory (KiB) of compiling source: the resource usage
    of that one child process, as wait4 reports it."""
    with open(work / "compile.log", "w+") as log:
        child = subprocess.Popen([cxx, *flags(), "-c", str(source), "-o", str(work / "probe.o")],
                                 stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(child.pid, 0)
        child.returncode = os.waitstatus_to_exitcode(status)
        if child.returncode != 0:
            log.seek(0)
            raise RuntimeError(f"compiling {source} failed:\n{log.read()}")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss


# The compile-time probes: (name, how to make the probe, the reference it is compiled alternately
# with). flat_50: the 50-state flat chart as bsc::machine<decltype(chart)>; flat_200_ref: the
# 200-state one as bsc::machine<bsc::chart_ref<chart>>, the spelling docs/api.md recommends for
# large charts; cd_player: Boost.SML's CD player (bench/sml_simple), a small chart, against the
# same chart written by hand with the same includes; header: <bsc/bsc.hpp> included in a small
# program and nothing of it used (bench/compile_time/header_bsc.cpp), against the program alone.
COMPILE_PROBES = [
    ("header", ROOT / "bench" / "compile_time" / "header_bsc.cpp", ROOT / "bench" / "compile_time" / "header_reference.cpp"),
    ("flat_50", ("flat_bsc.cpp.in", 50), ROOT / "bench" / "compile_time" / "reference.cpp"),
    ("flat_200_ref", ("flat_bsc_ref.cpp.in", 200), ROOT / "bench" / "compile_time" / "reference.cpp"),
    ("cd_player", ROOT / "bench" / "sml_simple" / "sml_simple_bsc.cpp", ROOT / "bench" / "sml_simple" / "sml_simple_hand.cpp"),
]


def measure_probe(cxx, work, name, source, reference):
    if isinstance(source, tuple):
        template, n = source
        probe = work / f"{name}.cpp"
        probe.write_text((ROOT / "bench" / "compile_time" / template).read_text().replace("@N@", str(n)))
    else:
        probe = source
    results = {"probe": [], "reference": []}
    for _ in range(REPEATS):
        results["reference"].append(timed_compile(cxx, reference, work))
        results["probe"].append(timed_compile(cxx, probe, work))
    probe_cpu = min(c for c, _ in results["probe"])
    ref_cpu = min(c for c, _ in results["reference"])
    probe_mem = max(m for _, m in results["probe"])
    ref_mem = max(m for _, m in results["reference"])
    ratios = sorted(p / r for (p, _), (r, _) in zip(results["probe"], results["reference"]))
    measured = {"probe_cpu_seconds": round(probe_cpu, 3), "reference_cpu_seconds": round(ref_cpu, 3),
                "probe_peak_kib": probe_mem, "reference_peak_kib": ref_mem,
                "cpu_ratio": round(ratios[len(ratios) // 2], 3), "memory_ratio": round(probe_mem / ref_mem, 3)}
    print(f"{name}: {probe_cpu:.2f} s CPU, {probe_mem / 1024:.0f} MiB; reference {reference.name}: {ref_cpu:.2f} s, "
          f"{ref_mem / 1024:.0f} MiB; ratios: CPU {measured['cpu_ratio']:.3f}, memory {measured['memory_ratio']:.3f}")
    return measured


def measure_compile_time(cxx, work):
    return {name: measure_probe(cxx, work, name, source, reference) for name, source, reference in COMPILE_PROBES}


def check_compile_time(measured, baselines):
    failures = []
    for name, m in measured.items():
        baseline = baselines.get(name)
        if baseline is None:
            failures.append(f"{name}: no baseline (record one with --record)")
            continue
        cpu_limit = baseline["cpu_ratio"] * (1 + CPU_MARGIN)
        mem_limit = baseline["memory_ratio"] * (1 + MEMORY_MARGIN)
        if m["cpu_ratio"] > cpu_limit:
            failures.append(f"{name}: compile CPU ratio {m['cpu_ratio']:.3f} over its baseline "
                            f"{baseline['cpu_ratio']:.3f} (limit {cpu_limit:.3f})")
        if m["memory_ratio"] > mem_limit:
            failures.append(f"{name}: compile memory ratio {m['memory_ratio']:.3f} over its baseline "
                            f"{baseline['memory_ratio']:.3f} (limit {mem_limit:.3f})")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("gate", choices=["instructions", "compile-time"])
    parser.add_argument("--compiler", required=True)
    parser.add_argument("--record", action="store_true", help="write the measured values as the new baseline")
    args = parser.parse_args()

    cxx = shutil.which(args.compiler) or args.compiler
    ident = compiler_id(cxx)
    key = "instructions" if args.gate == "instructions" else "compile_time"
    if args.gate == "instructions" and shutil.which("valgrind") is None:
        print("valgrind is not installed: no instruction counts (scripts/run deps installs it)")
        return SKIP
    baselines = json.loads(BASELINES.read_text()) if BASELINES.exists() else {}
    baseline = baselines.get(ident, {}).get(key)
    if baseline is None and not args.record:
        print(f"no {key} baseline for {ident} in {BASELINES.relative_to(ROOT)}: nothing to compare with")
        return SKIP

    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="bsc-perf-gate-") as tmp:
        work = Path(tmp)
        measured = (measure_instructions if args.gate == "instructions" else measure_compile_time)(cxx, work)
    print(f"({ident}, {time.monotonic() - started:.0f} s)")

    if args.record:
        baselines.setdefault(ident, {})[key] = measured
        BASELINES.write_text(json.dumps(baselines, indent=2, sort_keys=True) + "\n")
        print(f"recorded as the {key} baseline for {ident}")
        return 0
    failures = (check_instructions if args.gate == "instructions" else check_compile_time)(measured, baseline)
    for f in failures:
        print("OVER BASELINE: " + f)
    if not failures:
        print("within the baseline")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
