#!/usr/bin/env python3
"""Runs bsc's benchmark suite and regenerates docs/benchmarks.md.

    python3 scripts/benchmarks.py            # the whole suite (about half an hour, most of it
                                             # compiling the Boost.MSM probes)

Steps, each logged with the exact command it runs:

1. builds the benchmark targets of the release preset, one file at a time;
2. runs every dispatch benchmark (bench_mcs, bench_flat, bench_deep, bench_wide and the
   existing bench_manufacturing_cell) with --benchmark_format=json --benchmark_repetitions=5
   --benchmark_report_aggregates_only=true, and takes the median CPU time per event;
3. counts instructions per event with callgrind: bench_<workload>_insns IMPLEMENTATION N, run
   with N events and with none, the difference divided by N (for the cell, per cycle:
   bench_manufacturing_cell_insns);
4. measures the compile time and peak memory (/usr/bin/time -f '%e %M') of `g++ -O2 -c` on
   generated translation units holding a flat chart of 25, 50, 100 and 200 states, with bsc and
   with Boost.MSM (bench/compile_time/*.cpp.in), and on each workload's translation units
   (bench/<workload>/<workload>_{hand,bsc,bsc_table,msm,statechart}.cpp, each with the benchmark
   harness it includes);
5. writes docs/benchmarks.md: the tables, the targets met or missed, the machine, the
   compilers, the load during the runs and the commands. The section between the
   `analysis:begin` and `analysis:end` markers is kept as it is.

Timings are taken only when the 1-minute load average is below 1.2: the script waits for it
before each measurement, up to --max-wait seconds each and --wait-budget seconds in all, and
records the load before and after each run; a run during which the process was descheduled
(real time more than 10% above CPU time) or the load rose is repeated, up to three times. A
compilation is stopped after 900 s (--compile-timeout). --skip-timings and --skip-compile-time keep the results of
the previous run (build/release/benchmark-results/results.json) for that part. Plots are drawn
when matplotlib is installed, and skipped otherwise. Only the Python standard library is
required.
"""

import argparse
import datetime
import json
import math
import os
import platform
import re
import resource
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BUILD = ROOT / "build" / "release"
OUT = BUILD / "benchmark-results"
DOC = ROOT / "docs" / "benchmarks.md"
PLOTS = ROOT / "docs" / "benchmarks"

# The last five are the peers' own workloads, ported (hand-written and bsc only).
WORKLOADS = ["mcs", "flat", "deep", "wide", "sml_simple", "sml_composite", "sml_complex", "fsmb_large", "fsmb_deep"]
ALL_WORKLOADS = WORKLOADS + ["cell"]
IMPLS = ["hand_written", "hand_minimal", "bsc_compiled", "bsc_table", "boost_msm", "boost_statechart"]
IMPL_LABEL = {
    "hand_written": "hand-written (switch/if)",
    "hand_minimal": "hand-written, minimal (for context)",
    "bsc_compiled": "bsc compiled (`bsc::machine`)",
    "bsc_table": "bsc table-driven (`bsc::table::machine`)",
    "boost_msm": "Boost.MSM",
    "boost_statechart": "Boost.Statechart",
}
# bench_manufacturing_cell's benchmarks, as implementations of the workload `cell`.
CELL_NAMES = {"bm_bsc_step": "bsc_compiled", "bm_hand_written_scan": "hand_written"}

SIZES = [25, 50, 100, 200]
LOAD_LIMIT = 1.2
CALLGRIND_EVENTS = 20000

commands = []  # every command run, for the report


def log(msg):
    print(f"[benchmarks] {msg}", flush=True)


def shown(cmd):
    """A command as the report shows it: paths relative to the repository."""
    return cmd.replace(str(ROOT) + "/", "")


def run(cmd, **kw):
    commands.append(shown(" ".join(str(c) for c in cmd)))
    log("$ " + commands[-1])
    return subprocess.run([str(c) for c in cmd], check=True, **kw)


def load1():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


wait_budget = [3600.0]  # seconds of waiting left for the whole run (--wait-budget)


def wait_quiet(max_wait):
    """Waits until the 1-minute load average is below LOAD_LIMIT, at most max_wait seconds and
    at most what is left of the run's waiting budget; returns the load then."""
    start = time.time()
    limit = min(max_wait, wait_budget[0])
    load = load1()
    while load >= LOAD_LIMIT and time.time() - start < limit:
        log(f"load average {load:.2f} >= {LOAD_LIMIT}: waiting")
        time.sleep(20)
        load = load1()
    wait_budget[0] = max(0.0, wait_budget[0] - (time.time() - start))
    if load >= LOAD_LIMIT:
        log(f"load average still {load:.2f}: measuring anyway (recorded)")
    return load


# ---- 1. build ------------------------------------------------------------------------------


def build(targets):
    run(["cmake", "--preset", "release"], cwd=ROOT, stdout=subprocess.DEVNULL)
    # One file at a time: the machine is shared.
    run(["cmake", "--build", "--preset", "release", "-j", "1", "--target", *targets], cwd=ROOT,
        stdout=subprocess.DEVNULL)


# ---- 2. timings ----------------------------------------------------------------------------


def run_benchmark(exe, name, args, max_wait):
    """Runs one benchmark executable; returns (json, conditions)."""
    out = OUT / f"{name}.json"
    best = None
    for attempt in range(1, 4):
        before = wait_quiet(max_wait)
        t0 = time.time()
        run([exe, "--benchmark_format=json", "--benchmark_repetitions=5",
             "--benchmark_report_aggregates_only=true", f"--benchmark_out={out}",
             "--benchmark_out_format=json", *args], stdout=subprocess.DEVNULL)
        after = load1()
        data = json.loads(out.read_text())
        medians = [b for b in data["benchmarks"] if b.get("aggregate_name") == "median"]
        stretch = max(b["real_time"] / b["cpu_time"] for b in medians)
        cond = {"attempt": attempt, "load_before": before, "load_after": after,
                "seconds": time.time() - t0, "real_over_cpu": stretch}
        # The benchmark itself adds about 1 to the load average.
        quiet = before < LOAD_LIMIT and after < LOAD_LIMIT + 1.0 and stretch < 1.10
        cond["quiet"] = quiet
        if best is None or stretch < best[1]["real_over_cpu"]:
            best = (data, cond)
        if quiet:
            break
        log(f"{name}: run disturbed (load {before:.2f} -> {after:.2f}, real/cpu {stretch:.2f}); repeating")
    return best


def parse_timings(workload, data):
    """{impl: {ns, cv, real_ns}} from Google Benchmark JSON (medians over the repetitions)."""
    scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
    result = {}
    by_name = {}
    for b in data["benchmarks"]:
        by_name.setdefault(b["run_name"], {})[b.get("aggregate_name")] = b
    for run_name, aggs in by_name.items():
        med = aggs.get("median")
        if med is None:
            continue
        if workload == "cell":
            impl = CELL_NAMES.get(run_name)
            per = med.get("cycles")
        else:
            impl = run_name.split("/", 1)[1]
            per = med.get("events")
        if impl is None or not per:
            continue
        unit = scale[med.get("time_unit", "ns")]
        cv = aggs.get("cv", {}).get("cpu_time")
        result[impl] = {
            "ns": med["cpu_time"] * unit / per,
            "real_ns": med["real_time"] * unit / per,
            "cv": cv,
        }
    return result


# ---- 3. instruction counts -------------------------------------------------------------------


def callgrind_total(cmd):
    out = OUT / "callgrind.out"
    run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *cmd],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for line in out.read_text().splitlines():
        if line.startswith("totals:") or line.startswith("summary:"):
            return int(line.split()[1])
    raise RuntimeError("no totals in callgrind output")


def implementations_of(exe):
    p = subprocess.run([str(exe)], capture_output=True, text=True)
    return [l.strip() for l in p.stderr.splitlines()[1:] if l.strip()]


def instructions(workload):
    exe = BUILD / "bench" / ("bench_manufacturing_cell_insns" if workload == "cell" else f"bench_{workload}_insns")
    result = {}
    for impl in implementations_of(exe):
        with_events = callgrind_total([exe, impl, CALLGRIND_EVENTS])
        without = callgrind_total([exe, impl, 0])
        result[impl] = (with_events - without) / CALLGRIND_EVENTS
    return result


# ---- 4. compile time -----------------------------------------------------------------------

COMPILE_TIMEOUT = 900  # seconds per translation unit (--compile-timeout)
COMPILE_MEMORY = 16 << 30  # address-space limit per compiler run


def compile_probe(lib, n, max_wait):
    """Compiles the probe of `lib` for n states (0: the library's headers alone)."""
    ct = BUILD / "compile_time"
    ct.mkdir(parents=True, exist_ok=True)
    src = ct / f"flat_{lib}_{n}.cpp"
    if n == 0:
        if lib in ("bsc", "bsc_ref"):
            src.write_text("// The library's headers alone.\n#include <bsc/bsc.hpp>\nint probe() { return 0; }\n")
        else:
            src.write_text("// The library's headers alone (and MPL's raised limits).\n"
                           "#define BENCH_FLAT_N 1\n#include \"flat/flat_chart_msm.hpp\"\n"
                           "int probe() { return 0; }\n")
    else:
        template = (ROOT / "bench" / "compile_time" / f"flat_{lib}.cpp.in").read_text()
        src.write_text(template.replace("@N@", str(n)))
    return timed_compile(src, ct / f"flat_{lib}_{n}.o", "-std=c++17" if lib == "msm" else "-std=c++20", max_wait)


def timed_compile(src, obj, std, max_wait):
    """Elapsed and CPU seconds and peak memory of `g++ -O2 -c src`, once the machine is quiet."""
    cmd = ["/usr/bin/time", "-f", "%e %M %U %S", "g++", std, "-O2", "-DNDEBUG", f"-I{ROOT / 'include'}",
           f"-I{ROOT / 'bench'}", "-c", str(src), "-o", str(obj)]
    load = wait_quiet(max_wait)
    commands.append(shown(" ".join(cmd)))
    log("$ " + commands[-1])

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (COMPILE_MEMORY, COMPILE_MEMORY))

    # Its own process group, so that a timeout stops the compiler proper (cc1plus), not only
    # /usr/bin/time and the g++ driver.
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, preexec_fn=limit,
                         start_new_session=True)
    try:
        _, stderr = p.communicate(timeout=COMPILE_TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        return {"seconds": None, "kb": None, "cpu": None, "load": load, "load_after": load1(),
                "note": f"stopped after {COMPILE_TIMEOUT} s"}
    last = stderr.strip().splitlines()[-1] if stderr.strip() else ""
    m = re.match(r"([\d.]+) (\d+) ([\d.]+) ([\d.]+)$", last)
    if p.returncode != 0 or not m:
        return {"seconds": None, "kb": None, "cpu": None, "load": load, "load_after": load1(),
                "note": "failed: " + last[-200:]}
    return {"seconds": float(m.group(1)), "kb": int(m.group(2)), "cpu": float(m.group(3)) + float(m.group(4)),
            "load": load, "load_after": load1(), "note": ""}


# The translation units of each workload, as the release build compiles them (Boost.MSM's as
# C++17: bench/CMakeLists.txt says why), with the label of their table row.
UNITS = [("hand", "hand-written"), ("bsc", "bsc compiled"), ("bsc_table", "bsc table-driven"), ("msm", "Boost.MSM"),
         ("statechart", "Boost.Statechart")]
PEER_UNITS = ("msm", "statechart")


def compile_units(workload, max_wait):
    ct = BUILD / "compile_time"
    ct.mkdir(parents=True, exist_ok=True)
    result = {}
    for unit, _ in UNITS:
        src = ROOT / "bench" / workload / f"{workload}_{unit}.cpp"
        if src.exists():
            result[unit] = timed_compile(src, ct / f"unit_{src.stem}.o", "-std=c++17" if unit == "msm" else "-std=c++20",
                                         max_wait)
            log(f"compile {src.name}: {result[unit]}")
    return result


def growth_exponent(points):
    """Least-squares slope of log(t) against log(n): 1 is linear, 2 quadratic."""
    pts = [(math.log(n), math.log(t)) for n, t in points if t and t > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


# ---- 5. the report -------------------------------------------------------------------------


def sh(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, shell=True).stdout.strip()
    except OSError:
        return ""


def machine_description():
    cpu = sh("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2").strip()
    cores = sh("grep -c ^processor /proc/cpuinfo")
    mhz = sh("grep -m1 'cpu MHz' /proc/cpuinfo | cut -d: -f2").strip()
    cache = sh("grep -m1 'cache size' /proc/cpuinfo | cut -d: -f2").strip()
    mem = sh("grep MemTotal /proc/meminfo | awk '{printf \"%.1f GiB\", $2/1048576}'")
    gbench = sh("dpkg-query -W -f='${Version}' libbenchmark-dev")
    boost = sh("dpkg-query -W -f='${Version}' libboost-dev")
    return [
        f"- Machine: `{sh('uname -a')}`",
        f"- CPU: {cpu}, {cores} logical CPUs (shared with other users), {mhz} MHz, cache {cache}; memory {mem}",
        f"- Compilers: `{sh('g++ --version | head -1')}` (all measurements), "
        f"`{sh('clang++ --version | head -1')}` (not used for the numbers)",
        f"- Libraries: Google Benchmark {gbench}, Boost {boost} (MSM, Statechart), "
        f"valgrind {sh('valgrind --version')}",
        f"- Flags: the release preset (`-O2 -DNDEBUG`), no `-march`; Boost.MSM translation units are C++17, the others C++20",
    ]


def fmt(x, digits=1):
    if x is None:
        return "—"
    if x >= 100:
        return f"{x:,.0f}"
    return f"{x:.{digits}f}"


def fmt_ratio(x):
    return "—" if x is None else f"{x:.2f}x"


def timing_tables(times, insns, unit_compile):
    lines = []
    for w in ALL_WORKLOADS:
        t = times.get(w, {})
        if not t:
            continue
        ins = insns.get(w, {})
        hand_t = t.get("hand_written", {}).get("ns")
        hand_i = ins.get("hand_written")
        unit = "cycle" if w == "cell" else "event"
        lines += [f"### {w}", "",
                  f"| implementation | ns/{unit} (median CPU) | cv | ratio to hand-written | instructions/{unit} | instruction ratio |",
                  "| --- | ---: | ---: | ---: | ---: | ---: |"]
        for impl in IMPLS:
            if impl not in t and impl not in ins:
                continue
            ns = t.get(impl, {}).get("ns")
            cv = t.get(impl, {}).get("cv")
            ir = ins.get(impl)
            lines.append(
                f"| {IMPL_LABEL[impl]} | {fmt(ns)} | {'—' if cv is None else f'{100 * cv:.1f}%'} | "
                f"{fmt_ratio(ns / hand_t if ns and hand_t else None)} | {fmt(ir)} | "
                f"{fmt_ratio(ir / hand_i if ir and hand_i else None)} |")
        if w in ("mcs", "flat", "deep", "wide") and "bsc_table" not in t:
            lines.append("| bsc table-driven (`bsc::table::machine`) | not built | | | | |")
        lines.append("")
        units = unit_compile.get(w, {})
        if units:
            lines += [f"Compiling `bench/{w}/{w}_<unit>.cpp` (`g++ -O2 -c`, the benchmark harness included):", "",
                      "| translation unit | CPU (user+sys) | peak memory | elapsed | CPU above hand-written |",
                      "| --- | ---: | ---: | ---: | ---: |"]
            base = units.get("hand", {}).get("cpu")
            for unit, label in UNITS:
                r = units.get(unit)
                if not r:
                    continue
                cpu, kb, el = r.get("cpu"), r.get("kb"), r.get("seconds")
                above = cpu - base if cpu is not None and base is not None and unit != "hand" else None
                lines.append(f"| {label} | {'—' if cpu is None else f'{cpu:.2f} s'}"
                             f"{(' (' + r['note'] + ')') if r.get('note') else ''} | "
                             f"{'—' if kb is None else f'{kb / 1024:.0f} MiB'} | {'—' if el is None else f'{el:.2f} s'} | "
                             f"{'' if above is None else f'{above:.2f} s'} |")
            lines.append("")
    return lines


def verdicts(times, insns, compile_times, unit_compile):
    rows = []
    for w in ALL_WORKLOADS:
        t = times.get(w, {})
        c, h = t.get("bsc_compiled", {}).get("ns"), t.get("hand_written", {}).get("ns")
        if c and h:
            r = c / h
            rows.append((f"compiled within 1.1x of hand-written: {w}", f"{r:.2f}x",
                         "met" if r <= 1.1 else f"missed: {100 * (r / 1.1 - 1):.0f}% over 1.1x"))
    t = times.get("mcs", {})
    c, tb = t.get("bsc_compiled", {}).get("ns"), t.get("bsc_table", {}).get("ns")
    if c and tb:
        r = tb / c
        rows.append(("compiled at least 20x faster than table-driven: mcs", f"{r:.1f}x",
                     "met" if r >= 20 else f"missed: {r:.1f}x instead of 20x"))
    else:
        rows.append(("compiled at least 20x faster than table-driven: mcs", "—", "not measured"))
    for other in ("boost_msm", "boost_statechart"):
        for w in ALL_WORKLOADS:
            t = times.get(w, {})
            c, o = t.get("bsc_compiled", {}).get("ns"), t.get(other, {}).get("ns")
            if c and o:
                rows.append((f"compiled faster than {IMPL_LABEL[other]}: {w}", f"{o / c:.2f}x",
                             "met" if c < o else f"missed: {c / o:.2f}x slower"))
    for lib, how in (("bsc", "machine<decltype(chart)>"), ("bsc_ref", "machine<chart_ref<chart>>")):
        bsc = compile_times.get(lib, {})
        if not bsc:
            continue
        for n, limit in ((50, 1.5), (200, 10.0)):
            s = bsc.get(n, {}).get("seconds")
            note = bsc.get(n, {}).get("note", "")
            target = f"{n}-state flat chart compiles in < {limit} s (g++ -O2, {how})"
            if s is None and note.startswith("stopped"):
                rows.append((target, f"> {COMPILE_TIMEOUT} s",
                             f"missed by more than {COMPILE_TIMEOUT / limit:.0f}x ({note})"))
            elif s is None:
                rows.append((target, "—", "not measured " + note))
            else:
                rows.append((target, f"{s:.2f} s", "met" if s < limit else f"missed by {s / limit:.1f}x"))
        e = bsc.get("exponent_above_headers")
        if e is not None:
            measured = [n for n in SIZES if bsc.get(n, {}).get("seconds")]
            rows.append((f"compile time grows no faster than linearly in transitions ({how})",
                         f"exponent {e:.2f} ({measured[0]} to {measured[-1]} states, above the headers)",
                         "met" if e <= 1.15 else "missed: superlinear"))
    for w in WORKLOADS:
        units = unit_compile.get(w, {})
        ours = units.get("bsc", {}).get("cpu")
        peers = [(units[u]["cpu"], label) for u, label in UNITS if u in PEER_UNITS and units.get(u, {}).get("cpu") is not None]
        if ours is None or not peers:
            continue
        best, label = min(peers)
        rows.append((f"compiled back end's translation unit compiles in no more CPU than the best peer's: {w}",
                     f"{ours:.2f} s against {label}'s {best:.2f} s",
                     "met" if ours <= best else f"missed: {ours / best:.2f}x"))
    lines = ["| target | measured | verdict |", "| --- | ---: | --- |"]
    lines += [f"| {a} | {b} | {c} |" for a, b, c in rows]
    return lines


def compile_table(compile_times):
    lines = ["| library | states (= events = transitions) | g++ -O2 -c elapsed | CPU (user+sys) | peak memory | elapsed above headers alone | load before / after |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for lib, label in (("bsc", "bsc (`bsc::machine<decltype(chart)>`)"),
                       ("bsc_ref", "bsc (`bsc::machine<bsc::chart_ref<chart>>`)"), ("msm", "Boost.MSM")):
        res = compile_times.get(lib, {})
        base = res.get(0, {}).get("seconds")
        for n in [0] + SIZES:
            r = res.get(n)
            if not r:
                continue
            s, kb = r["seconds"], r["kb"]
            above = s - base if s is not None and base is not None and n else None
            cpu = r.get("cpu")
            after = r.get("load_after")
            lines.append(f"| {label} | {'headers only' if n == 0 else n} | "
                         f"{'—' if s is None else f'{s:.2f} s'}{(' (' + r['note'] + ')') if r['note'] else ''} | "
                         f"{'—' if cpu is None else f'{cpu:.2f} s'} | "
                         f"{'—' if kb is None else f'{kb / 1024:.0f} MiB'} | "
                         f"{'' if above is None else f'{above:.2f} s'} | "
                         f"{r['load']:.2f} / {'—' if after is None else f'{after:.2f}'} |")
        e, e0 = res.get("exponent"), res.get("exponent_above_headers")
        if e is not None:
            lines.append(f"| {label} | growth exponent over the sizes that finished | {e:.2f} | | | "
                         f"{'' if e0 is None else f'{e0:.2f}'} | |")
    return lines


def plots(times, compile_times):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    PLOTS.mkdir(parents=True, exist_ok=True)
    columns = 5  # two rows of five: ten workloads in one row would be too small to read
    rows = (len(ALL_WORKLOADS) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 4 * rows), squeeze=False)
    for ax in axes.flat[len(ALL_WORKLOADS):]:
        ax.set_visible(False)
    for ax, w in zip(axes.flat, ALL_WORKLOADS):
        t = times.get(w, {})
        names = [i for i in IMPLS if i in t]
        ax.bar(range(len(names)), [t[i]["ns"] for i in names])
        ax.set_xticks(range(len(names)))
        ax.set_xticklabels(names, rotation=60, ha="right", fontsize=7)
        ax.set_yscale("log")
        ax.set_title(w)
        ax.set_ylabel("ns per event (log)")
    fig.tight_layout()
    fig.savefig(PLOTS / "dispatch.png", dpi=100)
    fig, ax = plt.subplots(figsize=(5, 4))
    for lib in ("bsc", "bsc_ref", "msm"):
        pts = [(n, compile_times.get(lib, {}).get(n, {}).get("seconds")) for n in SIZES]
        pts = [(n, s) for n, s in pts if s]
        if pts:
            ax.plot([n for n, _ in pts], [s for _, s in pts], marker="o", label=lib)
    ax.set_xlabel("states (= transitions)")
    ax.set_ylabel("g++ -O2 -c seconds")
    ax.legend()
    fig.tight_layout()
    fig.savefig(PLOTS / "compile_time.png", dpi=100)
    return ["benchmarks/dispatch.png", "benchmarks/compile_time.png"]


def kept_analysis():
    if DOC.exists():
        m = re.search(r"<!-- analysis:begin -->.*?<!-- analysis:end -->", DOC.read_text(), re.S)
        if m:
            return m.group(0)
    return ("<!-- analysis:begin -->\n(no analysis yet; the standing rules the measurements established are in\n"
            "[performance.md](performance.md))\n<!-- analysis:end -->")


def write_report(times, insns, compile_times, unit_compile, conditions, timings_at, compile_at, table_ready):
    plot_files = plots(times, compile_times)
    lines = [
        "# Benchmarks",
        "",
        "<!-- Generated by scripts/benchmarks.py; edit the script (or the analysis section, which it keeps), not the tables. -->",
        "",
        "How fast bsc's compiled back end dispatches events, next to a hand-written implementation of",
        "the same chart, bsc's table-driven back end, Boost.MSM and Boost.Statechart; how many",
        "instructions each needs per event; and how long a chart takes to compile.",
        "",
        "## Running it",
        "",
        "```sh",
        "python3 scripts/benchmarks.py",
        "```",
        "",
        "builds the benchmark targets of the release preset one file at a time, runs them, counts",
        "instructions with callgrind, times the compilation of generated charts and rewrites this file",
        "(python3 standard library only; plots need Debian's `python3-matplotlib` and are skipped",
        "without it). It waits for the 1-minute load average to fall below 1.2 before each timing and",
        "repeats a run that was disturbed. Needs the Debian packages `libbenchmark-dev`, `libboost-dev`,",
        "`valgrind` and `time`. `--skip-timings` or `--skip-compile-time` reuse the previous run's",
        "results for that part (`python3 scripts/benchmarks.py --help`).",
        "",
        "## The workloads",
        "",
        "Each workload replays a recorded sequence of about 10,000 events (fixed seeds, or the peers'",
        "fixed loops for the ported workloads) on every",
        "implementation. Before any timing, every implementation is run over the whole sequence and",
        "observed after every event (active state, counters, and for MCS the whole display of Show);",
        "the benchmark aborts if any differs from the hand-written one. All implementations run the",
        "same actions. Events reach every implementation as a number, and the typed implementations",
        "turn it into their event type with the same `switch` (`bench/harness.hpp`).",
        "",
        "| workload | chart | source |",
        "| --- | --- | --- |",
        "| mcs | the Mode Control Supervisor: 15 states, 4 levels, deep history, Show on every entry and exit; 10,000 random button presses of 13 buttons | `bench/mcs/` |",
        "| flat | 50 states, 50 events, 50 transitions, each event handled by one state; half the events fire | `bench/flat/` |",
        "| deep | 8 levels of nesting, one event per level whose transitions are declared at that level, entry actions | `bench/deep/` |",
        "| wide | 8 parallel regions of 3 states, 3 events broadcast to every region, 48 transitions | `bench/wide/` |",
        "| cell | one execution cycle (`step`) of the manufacturing cell controller vs a hand-written scan loop | `bench/manufacturing_cell_bench.cpp` |",
        "| sml_simple | Boost.SML's benchmark simple CD player, ported: 5 states, 6 events, 12 transitions with empty actions; its 11-event loop, every event handled | `bench/sml_simple/` |",
        "| sml_composite | Boost.SML's benchmark composite CD player, ported: Playing a composite of 3 songs; its loop of 4,011 events, twice | `bench/sml_composite/` |",
        "| sml_complex | Boost.SML's benchmark complex chart, ported: a ring of 50 states and 50 events, guards that hold, empty actions; each event sent with probability 1/2, most ignored | `bench/sml_complex/` |",
        "| fsmb_large | fsm-benchmark's Large, ported: 25 states, each exit action raising an event the next state takes with an internal transition | `bench/fsmb_large/` |",
        "| fsmb_deep | fsm-benchmark's Deep, ported: 3 levels of 3 composites, final states and completion transitions (`bsc::done`), exit actions on the 27 basic states | `bench/fsmb_deep/` |",
        "",
        "`hand_minimal` (flat, deep) is the shortest code for that particular chart, exploiting its",
        "regularity so that no switch on the event is needed; it is shown for context and is not the",
        "reference of the targets, which is the switch/if code `hand_written`.",
        "",
        "## Machine, compilers and conditions",
        "",
        *machine_description(),
        f"- Dispatch timings and instruction counts: {timings_at} (UTC); compile times: {compile_at} (UTC)",
        "",
        "Load during the timed runs (1-minute load average; the benchmark itself adds about 1; "
        "`real/cpu` is the largest ratio of wall to CPU time among the medians of that run: near 1.0 "
        "means the process ran undisturbed):",
        "",
        "| executable | attempt | load before | load after | real/cpu | quiet |",
        "| --- | ---: | ---: | ---: | ---: | --- |",
    ]
    for name, c in conditions.items():
        lines.append(f"| {name} | {c['attempt']} | {c['load_before']:.2f} | {c['load_after']:.2f} | "
                     f"{c['real_over_cpu']:.2f} | {'yes' if c['quiet'] else 'no'} |")
    lines += [
        "",
        "## Dispatch: time and instructions per event",
        "",
        "Median over 5 repetitions of the CPU time of one replay divided by the number of events",
        "(`cv`: coefficient of variation of the 5 repetitions). Instructions per event: callgrind,",
        f"`bench_<workload>_insns IMPL {CALLGRIND_EVENTS}` minus `bench_<workload>_insns IMPL 0`, divided by "
        f"{CALLGRIND_EVENTS} (includes the replay loop and the switch from event number to event type);",
        f"for `cell`, per cycle: `bench_manufacturing_cell_insns IMPL {CALLGRIND_EVENTS}` minus `... IMPL 0`, the",
        "recorded cycles replayed from a fresh controller each time round (inputs written, one cycle, outputs read).",
        "Below each workload's table, the compile time and peak memory of each implementation's",
        "translation unit, measured as the flat charts' below (`/usr/bin/time`, `g++ -O2 -DNDEBUG -c`,",
        "Boost.MSM's as C++17, the others as C++20), during the compile-time run; every unit includes",
        "the same benchmark harness (`bench/harness.hpp`, Google Benchmark, `<string>`, `<vector>`), so",
        "the hand-written unit is the harness's own cost and the last column what the chart adds.",
        "",
    ]
    if not table_ready:
        lines += ["The table-driven back end (`bsc::table::machine`) was not available when this was run;",
                  "its rows are marked `not built`.", ""]
    lines += timing_tables(times, insns, unit_compile)
    lines += [
        "## Compile time",
        "",
        "`g++ -O2 -c` of one translation unit holding the flat chart of the `flat` workload with N",
        "states, N events and N transitions, a machine of it, and one dispatch of every event type",
        "(`bench/compile_time/flat_bsc.cpp.in`, `flat_msm.cpp.in`, generated into",
        "`build/release/compile_time/`), measured with `/usr/bin/time -f '%e %M %U %S'` (elapsed seconds,",
        "peak resident memory, and the compiler's CPU time, which other users of the machine affect",
        f"less than the elapsed time). Each compilation is limited to {COMPILE_TIMEOUT} s and 16 GiB of",
        "address space. The targets are judged on the elapsed time. Boost.MSM needs",
        "MPL's limits raised as its documentation says (`BOOST_MPL_CFG_NO_PREPROCESSED_HEADERS`,",
        "`BOOST_MPL_LIMIT_VECTOR_SIZE`, `BOOST_MPL_LIMIT_MAP_SIZE`), and above 50 rows the numbered",
        "`vectorN` templates generated the way MPL generates its own (`bench/flat/flat_chart_msm.hpp`).",
        "The growth exponent is the least-squares slope of log(time) against log(N) over the sizes",
        "that finished (1: linear, 2: quadratic), on the total elapsed time and on the time above the",
        "headers alone.",
        "",
        *compile_table(compile_times),
        "",
        "## Targets",
        "",
        *verdicts(times, insns, compile_times, unit_compile),
        "",
    ]
    if plot_files:
        lines += ["## Plots", ""] + [f"![{p}]({p})" for p in plot_files] + [""]
    else:
        lines += ["## Plots", "", "Skipped: matplotlib is not installed (Debian: `python3-matplotlib`).", ""]
    lines += ["## Analysis", "", kept_analysis(), "",
              "## Commands", "", "Every command the script ran, in order:", "", "```"]
    lines += commands
    lines += ["```", ""]
    DOC.write_text("\n".join(lines))
    log(f"wrote {DOC.relative_to(ROOT)}" + ("" if plot_files else " (plots skipped: matplotlib is not installed)"))


# ---- main ----------------------------------------------------------------------------------


def main():
    global COMPILE_TIMEOUT
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--max-wait", type=int, default=1800,
                    help="seconds to wait for a quiet machine before each measurement (default 1800)")
    ap.add_argument("--wait-budget", type=int, default=3600,
                    help="seconds of waiting for a quiet machine in the whole run (default 3600)")
    ap.add_argument("--skip-timings", action="store_true",
                    help="keep the dispatch timings and instruction counts of the last run")
    ap.add_argument("--skip-compile-time", action="store_true", help="keep the compile-time results of the last run")
    ap.add_argument("--skip-msm-compile-time", action="store_true",
                    help="measure bsc's compile times only, keep Boost.MSM's from the last run")
    ap.add_argument("--compile-timeout", type=int, default=COMPILE_TIMEOUT,
                    help="seconds after which a compilation is stopped (default 900)")
    args = ap.parse_args()
    wait_budget[0] = float(args.wait_budget)
    COMPILE_TIMEOUT = args.compile_timeout

    for tool in ("cmake", "g++", "valgrind"):
        if not shutil.which(tool):
            sys.exit(f"benchmarks.py: {tool} is not installed")
    if not Path("/usr/bin/time").exists():
        sys.exit("benchmarks.py: /usr/bin/time is missing (Debian package `time`)")

    started = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M")
    OUT.mkdir(parents=True, exist_ok=True)
    previous = {}
    prev_path = OUT / "results.json"
    if prev_path.exists():
        previous = json.loads(prev_path.read_text())
    if "timings_at" not in previous and DOC.exists():
        m = re.search(r"^- Run: (.*) \(UTC\)$", DOC.read_text(), re.M)
        if m:
            previous["timings_at"] = m.group(1)
    if "commands" not in previous and DOC.exists():
        m = re.search(r"## Commands\n.*?```\n(.*?)```", DOC.read_text(), re.S)
        previous["commands"] = m.group(1).splitlines() if m else []

    targets = ["bench_manufacturing_cell", "bench_manufacturing_cell_insns"]
    for w in WORKLOADS:
        targets += [f"bench_{w}", f"bench_{w}_insns"]
    build(targets)
    table_ready = (ROOT / "include" / "bsc" / "table" / "engine.hpp").exists()

    timings_at = previous.get("timings_at", "")
    if args.skip_timings and "times" in previous:
        times, insns, conditions = previous["times"], previous["insns"], previous["conditions"]
        commands.extend(shown(c) for c in previous.get("commands", []) if c.split()[0] not in ("cmake", "/usr/bin/time"))
    else:
        times, conditions = {}, {}
        for w in ALL_WORKLOADS:
            exe = BUILD / "bench" / ("bench_manufacturing_cell" if w == "cell" else f"bench_{w}")
            data, cond = run_benchmark(exe, w, [], args.max_wait)
            times[w] = parse_timings(w, data)
            conditions[exe.name] = cond
        insns = {w: instructions(w) for w in ALL_WORKLOADS}
        timings_at = f"{started} to {datetime.datetime.utcnow().strftime('%Y-%m-%d %H:%M')}"

    compile_times = {k: {int(n): v for n, v in d.items() if n.isdigit()} | {x: d[x] for x in d if not x.isdigit()}
                     for k, d in previous.get("compile_times", {}).items()}
    kept_compile = [] if not args.skip_compile_time else ["bsc", "bsc_ref", "msm"]
    if args.skip_msm_compile_time:
        kept_compile = ["msm"]
    commands.extend(shown(c) for c in previous.get("commands", [])
                    if c.startswith("/usr/bin/time") and (any(f"/flat_{lib}_" in c for lib in kept_compile) or
                                                         (args.skip_compile_time and "/unit_" in c)))
    compile_at = previous.get("compile_at", "")
    if not args.skip_compile_time:
        compile_at = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M")
        libs = ["bsc", "bsc_ref"] if args.skip_msm_compile_time else ["bsc", "bsc_ref", "msm"]
        for lib in libs:
            res = {}
            for n in [0] + SIZES:
                res[n] = compile_probe(lib, n, args.max_wait)
                log(f"compile {lib} {n}: {res[n]}")
            base = res[0]["seconds"]
            res["exponent"] = growth_exponent([(n, res[n]["seconds"]) for n in SIZES])
            res["exponent_above_headers"] = growth_exponent(
                [(n, res[n]["seconds"] - base) for n in SIZES if res[n]["seconds"] and base is not None])
            compile_times[lib] = res

    unit_compile = previous.get("unit_compile", {})
    if not args.skip_compile_time:
        unit_compile = {w: compile_units(w, args.max_wait) for w in WORKLOADS}
    if not args.skip_compile_time:
        compile_at += " to " + datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M")
    prev_path.write_text(json.dumps({"timings_at": timings_at, "compile_at": compile_at, "commands": commands, "times": times, "insns": insns, "conditions": conditions,
                                     "unit_compile": unit_compile,
                                     "compile_times": {k: {str(n): v for n, v in d.items()}
                                                       for k, d in compile_times.items()}}, indent=1))
    write_report(times, insns, compile_times, unit_compile, conditions, timings_at, compile_at, table_ready)


if __name__ == "__main__":
    main()
