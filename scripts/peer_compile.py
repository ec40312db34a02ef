#!/usr/bin/env python3
"""bsc's compile time side by side with Boost.SML's, on Boost.SML's own benchmark programs.

    peer_compile.py --sml DIR [--compiler g++] [--repeats 7]

DIR is a checkout of boost-ext/sml (its include/boost/sml.hpp and benchmark/ are read there;
nothing of it is copied). Compiles, one after the other and --repeats times round (-std=c++20
-O2 -c), the pairs:

- header: bench/compile_time/header_bsc.cpp (the small driver and <bsc/bsc.hpp>) against the
  same driver with <boost/sml.hpp>, and the driver alone (header_reference.cpp);
- cd_player: bench/compile_time/cd_player_bsc.cpp against DIR/benchmark/simple/sml.cpp;
- cd_composite: bench/compile_time/cd_composite_bsc.cpp against DIR/benchmark/composite/sml.cpp.

The driver (bench/compile_time/small_driver.hpp) includes what Boost.SML's benchmark.hpp does,
<chrono> and <iostream>. Prints each program's median user CPU time and each pair's ratio of
medians. Nothing is written; the machine should be otherwise quiet. Exit 2 if DIR holds no
Boost.SML.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROBES = ROOT / "bench" / "compile_time"


def user_seconds(cxx, source, includes):
    child = subprocess.Popen([cxx, "-std=c++20", "-O2", *(f"-I{i}" for i in includes), "-c", str(source), "-o",
                              os.devnull])
    _, status, usage = os.wait4(child.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"compiling {source} failed")
    return usage.ru_utime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sml", required=True, type=Path, help="a checkout of boost-ext/sml")
    parser.add_argument("--compiler", default="g++")
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    sml = args.sml.resolve()
    if not (sml / "include" / "boost" / "sml.hpp").exists() or not (sml / "benchmark" / "simple" / "sml.cpp").exists():
        print(f"{sml} is not a checkout of boost-ext/sml (no include/boost/sml.hpp or benchmark/)", file=sys.stderr)
        return 2

    with tempfile.TemporaryDirectory() as work:
        sml_header = Path(work) / "header_sml.cpp"
        sml_header.write_text(f'#include <boost/sml.hpp>\n\n#include "{PROBES / "small_driver.hpp"}"\n\n'
                              "int main() { return probe_driver::program_without_chart(); }\n")
        bsc_includes = [ROOT / "include"]
        sml_includes = [sml / "include", sml / "benchmark"]
        programs = {
            "driver alone": (PROBES / "header_reference.cpp", bsc_includes),
            "bsc header": (PROBES / "header_bsc.cpp", bsc_includes),
            "Boost.SML header": (sml_header, sml_includes),
            "bsc cd_player": (PROBES / "cd_player_bsc.cpp", bsc_includes),
            "Boost.SML cd_player": (sml / "benchmark" / "simple" / "sml.cpp", sml_includes),
            "bsc cd_composite": (PROBES / "cd_composite_bsc.cpp", bsc_includes),
            "Boost.SML cd_composite": (sml / "benchmark" / "composite" / "sml.cpp", sml_includes),
        }
        times = {name: [] for name in programs}
        for _ in range(args.repeats):
            for name, (source, includes) in programs.items():
                times[name].append(user_seconds(args.compiler, source, includes))

    median = {name: statistics.median(t) for name, t in times.items()}
    print(f"{args.compiler}, -std=c++20 -O2 -c, median user CPU of {args.repeats} alternating runs:")
    for name, t in median.items():
        print(f"  {name:24} {t:.3f} s (min {min(times[name]):.3f})")
    print("ratios of medians, bsc / Boost.SML:")
    for what in ("header", "cd_player", "cd_composite"):
        print(f"  {what:14} {median[f'bsc {what}'] / median[f'Boost.SML {what}']:.2f}x")
    print(f"  header over the driver alone: bsc +{median['bsc header'] - median['driver alone']:.3f} s, "
          f"Boost.SML +{median['Boost.SML header'] - median['driver alone']:.3f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
