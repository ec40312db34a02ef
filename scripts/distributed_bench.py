#!/usr/bin/env python3
"""Measure the production cell distributed over MQTT against the cell in one process.

Runs the supervised cell (examples/production_cell/supervised.hpp) for 10 minutes of the cell
(6001 steps) with a continuous supply of bricks, three ways:

  1. in one process: eleven bsc::net nodes over the in-process transport, and one bsc::system
     (production_cell_node --memory, which also checks that both compute the same steps);
  2. eleven processes and a Mosquitto broker on a loopback port, as fast as the links allow;
  3. the same with the press controller's process killed after 2 s and started again 1 s later.

It prints a Markdown table: bricks per minute of the cell, wall time per step, and the latency
of a signal from one node's cycle to another's (from the end of a controller's step n to the end
of its plant model's step n, which reads the command; and from the end of a plant's step n to
the end of its controller's step n + 1, which reads the sensor), median and 99th percentile over
every step of the five controller/plant pairs. Timestamps are the machine's monotonic clock,
which all processes on one machine share.

usage: scripts/distributed_bench.py [--binary build/release/examples/production_cell/production_cell_node]
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "distributed"))
import cell  # noqa: E402

STEPS = 6000
BRICKS = 255
PAIRS = [("feed_belt", "env_feed_belt"), ("table", "env_table"), ("robot", "env_robot"), ("press", "env_press"),
         ("deposit_belt", "env_deposit_belt")]


def percentile(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))]


def distributed(binary, scenario):
    cell.configure(STEPS, 0, BRICKS)
    cell.RUN_LIMIT = 300
    cell.FAULT_AT = 2.0
    workdir = tempfile.mkdtemp(prefix="bsc-cell-bench-")
    run = cell.Run(binary, scenario, workdir)
    try:
        failed, seconds = run.run()
    finally:
        run.stop_everything()
    if failed:
        raise SystemExit(f"nodes {failed} failed; files in {workdir}")
    traces = cell.load_traces(workdir)
    problems = [p for p in cell.check(traces) if not p.startswith("at the end")]
    if problems:
        raise SystemExit(f"safety violated: {problems[:3]}; files in {workdir}")
    command, sensor = [], []
    for ctl, plant in PAIRS:
        c, p = traces[ctl], traces[plant]
        for n in range(1, STEPS):
            if n in c and n in p:
                command.append(p[n]["us"] - c[n]["us"])
            if n in p and n + 1 in c:
                sensor.append(c[n + 1]["us"] - p[n]["us"])
    times = [r["us"] for t in traces.values() for r in t.values()]
    delivered = traces["env_deposit_belt"][STEPS]["delivered"]
    shutil.rmtree(workdir, ignore_errors=True)
    return {
        "bricks_per_minute": delivered / ((STEPS + 1) / 600),
        "us_per_step": (max(times) - min(times)) / (STEPS + 1),
        "command": (statistics.median(command), percentile(command, 0.99)),
        "sensor": (statistics.median(sensor), percentile(sensor, 0.99)),
        "seconds": seconds,
    }


def in_memory(binary):
    out = subprocess.run([binary, "--memory", "--steps", str(STEPS), "--bricks", str(BRICKS)],
                         capture_output=True, text=True, check=True).stdout
    per_minute = float(re.search(r"\(([\d.]+) per minute", out).group(1))
    nodes, plain = map(float, re.search(r"([\d.]+) us deployed .*?, ([\d.]+) us as one", out).groups())
    return per_minute, nodes, plain


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", default="build/release/examples/production_cell/production_cell_node")
    args = parser.parse_args()
    if not os.path.exists(cell.mosquitto()):
        raise SystemExit("mosquitto is not installed")
    per_minute, nodes_us, plain_us = in_memory(args.binary)
    fast = distributed(args.binary, "none")
    killed = distributed(args.binary, "kill")
    print(f"The production cell, {STEPS + 1} steps (10 minutes of the cell), bricks supplied continuously; "
          f"{time.strftime('%Y-%m-%d')}\n")
    print("| run | bricks per minute of the cell | wall time per step | controller to plant, median / p99 "
          "| plant to controller, median / p99 |")
    print("| --- | ---: | ---: | ---: | ---: |")
    print(f"| one bsc::system, one process | {per_minute:.2f} | {plain_us:.1f} us | - | - |")
    print(f"| 11 nodes, in-process transport | {per_minute:.2f} | {nodes_us:.1f} us | - | - |")
    for name, r in (("11 processes over MQTT", fast), ("11 processes over MQTT, press controller killed for 1 s",
                                                         killed)):
        print(f"| {name} | {r['bricks_per_minute']:.2f} | {r['us_per_step']:.0f} us "
              f"| {r['command'][0] / 1000:.2f} / {r['command'][1] / 1000:.2f} ms "
              f"| {r['sensor'][0] / 1000:.2f} / {r['sensor'][1] / 1000:.2f} ms |")


if __name__ == "__main__":
    main()
