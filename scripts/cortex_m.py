#!/usr/bin/env python3
"""bsc on a Cortex-M4: the programs of tests/cortex_m/, built with arm-none-eabi-gcc and run under QEMU.

    cortex_m.py build --build-dir DIR
    cortex_m.py trace --build-dir DIR --host EXE [--reference EXE] PROGRAM
    cortex_m.py symbols --build-dir DIR
    cortex_m.py report [--build-dir DIR] [--check | --update]

build: configures tests/cortex_m/ with its toolchain file (arm-none-eabi-cortex-m4.cmake) in DIR
and builds every program at -Os and -O2 (-j1), with the environment's compiler and linker flags
removed, so that nothing of the host build reaches the target.

trace: runs PROGRAM's two images on QEMU's mps2-an386 (a Cortex-M4) with semihosting, and fails
unless each prints what EXE, the same source built for the host, prints (and exits 0, as EXE
must). With --reference, EXE must also print what the reference prints: a bsc machine and the
hand-written controller of the same chart behave alike.

symbols: fails if any image defines malloc or free, printf or its kin, a __cxa_ function (the
C++ runtime's exceptions, guards and atexit), an unwinder (_Unwind_*, a personality routine) or
typeinfo (_ZTI*, _ZTS*).

report: builds the programs (in a temporary directory unless --build-dir names a built one) and
prints, for each chart, bsc next to the hand-written version: flash (text + data) and
instructions per event at -Os and -O2, both over the chart's floor (its driver with a subject
that does nothing: the startup, the sequence, the printing, the loop), the RAM of the machine
(the size of the global `subject`), and whether it needs a constructor at startup (an
.init_array entry) or is constant-initialised. Instructions are counted by QEMU: with a TCG
plugin that counts them (libinsn.so) where one is installed, otherwise by logging every
translated block executed with one instruction per block (-d exec,nochain -singlestep); the
count of `PROGRAM N` minus that of `PROGRAM 0`, divided by N. Counts are deterministic.

--check compares bsc's programs (default, scan and lean policies) with the baselines of
bench/baselines.json ("cortex_m4", per compiler) and fails if instructions per event grow by
more than 0.5 % (plus 0.1 for rounding), flash by more than 1 % (plus 16 bytes, for alignment),
or the RAM of the machine at all. --update writes the measured values as the new baselines.

Without arm-none-eabi-g++ (or, to run, qemu-system-arm), or for a compiler without baselines,
the script says so and exits 77, which ctest reports as skipped. Exit 0: everything as expected;
1: a difference, a forbidden symbol or a value over its baseline.
"""

import argparse
import glob
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
SOURCES = ROOT / "tests" / "cortex_m"
TOOLCHAIN = SOURCES / "arm-none-eabi-cortex-m4.cmake"
BASELINES = ROOT / "bench" / "baselines.json"
BASELINE_KEY = "cortex_m4"
PREFIX = "arm-none-eabi-"
QEMU = "qemu-system-arm"
OPTIMISATIONS = ("Os", "O2")
SKIP = 77
QEMU_TIMEOUT = 120

# Events counted (scan cycles for the cell, whose recording holds 512).
EVENTS = {"cd_player": 1000, "mcs": 1000, "cell": 500}
CHART_NAMES = {"cd_player": "CD player (bench/sml_simple)", "mcs": "MCS (examples/mcs)",
               "cell": "manufacturing cell's controller (scan cycles)"}
IMPLEMENTATION_NAMES = {"hand": "hand-written", "bsc": "bsc, default_policy", "lean": "bsc, lean_policy",
                        "floor": "floor (driver only)", "cell_bsc": "bsc, scan_policy"}
GATED = ("bsc", "lean")
INSTRUCTION_MARGIN = 0.005
INSTRUCTION_SLACK = 0.1
FLASH_MARGIN = 0.01
FLASH_SLACK = 16

FORBIDDEN = re.compile(
    r"^(_?malloc|_?free|_?calloc|_?realloc|_malloc_r|_free_r|_sbrk|_sbrk_r"  # the heap
    r"|_?(v|f|s|sn|as|d|i|fi|si|vf|vs|vsn)?printf(_r)?|_printf_.*|_svfprintf_r|_vfiprintf_r|puts|fputs"  # printf
    r"|__cxa_.*|__aeabi_atexit|_Unwind_.*|__gxx_personality_.*|__aeabi_unwind_cpp_pr\d"  # C++ runtime, unwinding
    r"|_ZTI.*|_ZTS.*)$")  # typeinfo


def tool(name):
    return shutil.which(PREFIX + name) if name != QEMU else shutil.which(QEMU)


def missing(*names):
    """A sentence naming the tools that are not installed, or None."""
    absent = [(PREFIX + n if n != QEMU else n) for n in names if tool(n) is None]
    if not absent:
        return None
    return f"{', '.join(absent)} not found (scripts/run deps installs the Cortex-M4 toolchain and QEMU): skipped"


def programs():
    """The programs of tests/cortex_m/programs.cmake, in its order."""
    text = (SOURCES / "programs.cmake").read_text()
    found = re.search(r"set\(BSC_CORTEX_M_PROGRAMS([^)]*)\)", text)
    return found.group(1).split()


def chart_of(program):
    return program.rsplit("_", 1)[0]


def implementation_of(program):
    return program.rsplit("_", 1)[1]


def elf(build_dir, program, opt):
    return Path(build_dir) / f"{program}.{opt}.elf"


def build(build_dir):
    env = {k: v for k, v in os.environ.items() if k not in ("CFLAGS", "CXXFLAGS", "CPPFLAGS", "LDFLAGS")}
    configure = ["cmake", "-S", str(SOURCES), "-B", str(build_dir), f"-DCMAKE_TOOLCHAIN_FILE={TOOLCHAIN}"]
    for cmd in (configure, ["cmake", "--build", str(build_dir), "-j", "1"]):
        run = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            print(run.stdout)
            print(f"cortex_m.py: {' '.join(cmd)} failed")
            return False
    return True


# ---- QEMU ------------------------------------------------------------------------------------


def qemu_command(image, out, args):
    semihosting = ",".join(["enable=on", "target=native", "chardev=semihosting"] +
                           [f"arg={a}" for a in [image.name, *map(str, args)]])
    return [tool(QEMU), "-M", "mps2-an386", "-cpu", "cortex-m4", "-display", "none", "-monitor", "none",
            "-serial", "none", "-chardev", f"file,id=semihosting,path={out}", "-semihosting-config", semihosting,
            "-kernel", str(image)]


def run_qemu(image, args, work, extra=()):
    """The exit code and the console output of the image run with args."""
    out = Path(work) / f"{image.name}.{'_'.join(map(str, args)) or 'trace'}.out"
    out.unlink(missing_ok=True)
    try:
        run = subprocess.run(qemu_command(image, out, args) + list(extra), capture_output=True, text=True,
                             timeout=QEMU_TIMEOUT)
    except subprocess.TimeoutExpired:
        return None, f"(no exit within {QEMU_TIMEOUT} s)"
    text = out.read_text() if out.exists() else ""
    if run.stderr.strip():
        text += run.stderr
    return run.returncode, text


def insn_plugin():
    """A TCG plugin that counts the instructions executed, where QEMU's plugins are installed."""
    for pattern in ("/usr/lib/*/qemu/plugins/libinsn.so", "/usr/lib/*/qemu/libinsn.so", "/usr/lib/qemu/plugins/libinsn.so",
                    "/usr/local/lib/qemu/plugins/libinsn.so", "/usr/libexec/qemu/plugins/libinsn.so"):
        found = sorted(glob.glob(pattern))
        if found:
            return found[0]
    return None


def one_instruction_per_block():
    """QEMU 7 spells it -singlestep; 8.1 and later -accel tcg,one-insn-per-tb=on."""
    help_text = subprocess.run([tool(QEMU), "-help"], capture_output=True, text=True).stdout
    return ["-singlestep"] if re.search(r"^-singlestep", help_text, re.M) else ["-accel", "tcg,one-insn-per-tb=on"]


def instructions(image, n, work, method):
    """Instructions executed by the whole run of `image n`."""
    log = Path(work) / f"{image.name}.{n}.log"
    log.unlink(missing_ok=True)
    if method[0] == "plugin":
        extra = ["-plugin", method[1], "-d", "plugin", "-D", str(log)]
    else:
        extra = [*method[1], "-d", "exec,nochain", "-D", str(log)]
    code, text = run_qemu(image, [n], work, extra)
    if code != 0:
        raise RuntimeError(f"{image.name} {n} under QEMU exited {code}:\n{text}")
    if method[0] == "plugin":
        found = re.search(r"insns: (\d+)", log.read_text())
        count = int(found.group(1))
    else:
        with open(log, "rb") as lines:  # one block of one instruction per line
            count = sum(1 for line in lines if line.startswith(b"Trace "))
    log.unlink()
    return count


# ---- The images ------------------------------------------------------------------------------


def tool_output(name, *args):
    return subprocess.run([tool(name), *map(str, args)], capture_output=True, text=True, check=True).stdout


def flash(image):
    """text + data: what the image puts in flash (code, constants, .data's initial values, and
    .init_array, which Berkeley's format counts in data)."""
    line = tool_output("size", "-B", image).splitlines()[1].split()
    return int(line[0]) + int(line[1])


def init_array_entries(image):
    for line in tool_output("size", "-A", image).splitlines():
        parts = line.split()
        if parts and parts[0] == ".init_array":
            return int(parts[1]) // 4
    return 0


def symbols(image):
    """(name, size) of every symbol of the image."""
    out = []
    for line in tool_output("nm", "-S", image).splitlines():
        parts = line.split()
        if len(parts) == 4:
            out.append((parts[3], int(parts[1], 16)))
        elif parts:
            out.append((parts[-1], None))
    return out


def subject_size(image):
    sizes = [size for name, size in symbols(image) if name == "subject"]
    if len(sizes) != 1 or sizes[0] is None:
        raise RuntimeError(f"{image.name}: no global `subject` with a size")
    return sizes[0]


def compiler_id():
    banner = subprocess.run([tool("g++"), "--version"], capture_output=True, text=True, check=True).stdout
    found = re.search(r"(\d+)\.\d+(\.\d+)?", banner.splitlines()[0])
    return f"{PREFIX}gcc-{found.group(1) if found else 'unknown'}"


# ---- The subcommands -------------------------------------------------------------------------


def command_build(args):
    reason = missing("g++")
    if reason:
        print(reason)
        return SKIP
    started = time.monotonic()
    if not build(args.build_dir):
        return 1
    print(f"built {len(programs()) * len(OPTIMISATIONS)} images in {args.build_dir} ({time.monotonic() - started:.0f} s)")
    return 0


def first_difference(a, b):
    a_lines, b_lines = a.splitlines(), b.splitlines()
    for i in range(max(len(a_lines), len(b_lines))):
        left = a_lines[i] if i < len(a_lines) else "(end)"
        right = b_lines[i] if i < len(b_lines) else "(end)"
        if left != right:
            return i + 1, left, right
    return None


def command_trace(args):
    reason = missing("g++", QEMU)
    if reason:
        print(reason)
        return SKIP
    host = subprocess.run([args.host], capture_output=True, text=True)
    if host.returncode != 0:
        print(f"{args.host} exited {host.returncode}:\n{host.stdout}{host.stderr}")
        return 1
    failures = 0
    if args.reference:
        reference = subprocess.run([args.reference], capture_output=True, text=True)
        difference = first_difference(reference.stdout, host.stdout)
        if reference.returncode != 0 or difference:
            line, expected, got = difference or (0, "", "")
            print(f"{args.program} on the host differs from {Path(args.reference).name} at line {line}:\n"
                  f"  {Path(args.reference).name}: {expected}\n  {args.program}: {got}")
            failures += 1
    with tempfile.TemporaryDirectory(prefix="bsc-cortex-m-") as work:
        for opt in OPTIMISATIONS:
            image = elf(args.build_dir, args.program, opt)
            if not image.exists():
                print(f"{image} is missing: build the images first (ctest cortex_m.build, or cortex_m.py build)")
                return 1
            code, text = run_qemu(image, [], work)
            difference = first_difference(host.stdout, text)
            if code != 0 or difference:
                line, expected, got = difference or (0, "", "")
                print(f"{image.name}: exit code {code}, trace differs from the host's at line {line}:\n"
                      f"  host:      {expected}\n  Cortex-M4: {got}")
                failures += 1
            else:
                print(f"{image.name}: the host's trace, {len(text.splitlines())} lines")
    return 1 if failures else 0


def command_symbols(args):
    reason = missing("g++", "nm")
    if reason:
        print(reason)
        return SKIP
    bad = []
    count = 0
    for program in programs():
        for opt in OPTIMISATIONS:
            image = elf(args.build_dir, program, opt)
            if not image.exists():
                print(f"{image} is missing: build the images first (ctest cortex_m.build, or cortex_m.py build)")
                return 1
            count += 1
            found = sorted({name for name, _ in symbols(image) if FORBIDDEN.match(name)})
            if found:
                bad.append(f"{image.name}: {' '.join(found)}")
    for line in bad:
        print("FORBIDDEN: " + line)
    if not bad:
        print(f"{count} images: no malloc, printf, C++ runtime support (__cxa_*), unwinder or typeinfo")
    return 1 if bad else 0


def measure(build_dir, work):
    method = ("plugin", insn_plugin()) if insn_plugin() else ("singlestep", one_instruction_per_block())
    print(f"instructions counted by QEMU {'with ' + method[1] if method[0] == 'plugin' else 'one per block'}")
    measured = {}
    for program in programs():
        n = EVENTS[chart_of(program)]
        entry = {}
        for opt in OPTIMISATIONS:
            image = elf(build_dir, program, opt)
            per_event = (instructions(image, n, work, method) - instructions(image, 0, work, method)) / n
            entry[opt] = {"flash": flash(image), "instructions": round(per_event, 2)}
        # The machine is the same object at either level; its constructor may not be.
        images = [elf(build_dir, program, opt) for opt in OPTIMISATIONS]
        entry["ram"] = subject_size(images[-1])
        entry["constructor"] = any(init_array_entries(image) > 0 for image in images)
        measured[program] = entry
    return measured


def table(measured):
    lines = ["| program | flash -Os | flash -O2 | RAM | constructor at startup | instructions/event -Os | "
             "instructions/event -O2 |",
             "|---|---:|---:|---:|---|---:|---:|"]
    for chart in dict.fromkeys(chart_of(p) for p in measured):
        floor = measured.get(f"{chart}_floor")
        lines.append(f"| **{CHART_NAMES.get(chart, chart)}** | | | | | | |")
        for program, m in measured.items():
            if chart_of(program) != chart:
                continue
            impl = implementation_of(program)
            name = IMPLEMENTATION_NAMES.get(program, IMPLEMENTATION_NAMES.get(impl, impl))
            if impl == "floor" or floor is None:
                cells = [f"{m[o]['flash']}" for o in OPTIMISATIONS] + ["", ""] + \
                        [f"{m[o]['instructions']:.1f}" for o in OPTIMISATIONS]
            else:
                cells = ([f"{m[o]['flash'] - floor[o]['flash']}" for o in OPTIMISATIONS] +
                         [f"{m['ram']} B", "yes" if m["constructor"] else "no"] +
                         [f"{m[o]['instructions'] - floor[o]['instructions']:.1f}" for o in OPTIMISATIONS])
            lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def check(measured, baseline):
    failures = []
    for program, m in measured.items():
        if implementation_of(program) not in GATED:
            continue
        base = baseline.get(program)
        if base is None:
            failures.append(f"{program}: no baseline (record one with --update)")
            continue
        if m["ram"] > base["ram"]:
            failures.append(f"{program}: the machine takes {m['ram']} B of RAM, over its baseline {base['ram']} B")
        for opt in OPTIMISATIONS:
            limit = base[opt]["instructions"] * (1 + INSTRUCTION_MARGIN) + INSTRUCTION_SLACK
            if m[opt]["instructions"] > limit:
                failures.append(f"{program} -{opt}: {m[opt]['instructions']:.2f} instructions/event, over its baseline "
                                f"{base[opt]['instructions']:.2f} (limit {limit:.2f})")
            limit = base[opt]["flash"] * (1 + FLASH_MARGIN) + FLASH_SLACK
            if m[opt]["flash"] > limit:
                failures.append(f"{program} -{opt}: {m[opt]['flash']} bytes of flash, over its baseline "
                                f"{base[opt]['flash']} (limit {limit:.0f})")
    return failures


def command_report(args):
    reason = missing("g++", "size", "nm", QEMU)
    if reason:
        print(reason)
        return SKIP
    ident = compiler_id()
    baselines = json.loads(BASELINES.read_text()) if BASELINES.exists() else {}
    baseline = baselines.get(BASELINE_KEY, {}).get(ident)
    if args.check and baseline is None:
        print(f"no {BASELINE_KEY} baseline for {ident} in {BASELINES.relative_to(ROOT)}: nothing to compare with")
        return SKIP
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="bsc-cortex-m-") as work:
        build_dir = args.build_dir
        if build_dir is None:
            build_dir = Path(work) / "build"
            if not build(build_dir):
                return 1
        measured = measure(build_dir, work)
    print(f"\nCortex-M4 ({ident}, QEMU mps2-an386): flash in bytes and instructions per event over each chart's "
          "floor; RAM: the machine object\n")
    print(table(measured))
    print(f"\n({time.monotonic() - started:.0f} s)")
    if args.update:
        # Read again just before writing: only this key changes.
        baselines = json.loads(BASELINES.read_text()) if BASELINES.exists() else {}
        baselines.setdefault(BASELINE_KEY, {})[ident] = measured
        BASELINES.write_text(json.dumps(baselines, indent=2, sort_keys=True) + "\n")
        print(f"recorded as the {BASELINE_KEY} baseline for {ident}")
        return 0
    if not args.check:
        return 0
    failures = check(measured, baseline)
    for f in failures:
        print("OVER BASELINE: " + f)
    if not failures:
        print("within the baseline")
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("build", help="build the images")
    p.add_argument("--build-dir", type=Path, required=True)
    p = sub.add_parser("trace", help="compare a program's trace on the Cortex-M4 with the host's")
    p.add_argument("--build-dir", type=Path, required=True)
    p.add_argument("--host", required=True, help="the program built for the host")
    p.add_argument("--reference", help="a host program whose trace must be the same (the hand-written one)")
    p.add_argument("program")
    p = sub.add_parser("symbols", help="check that no image holds malloc, printf, unwinding or typeinfo")
    p.add_argument("--build-dir", type=Path, required=True)
    p = sub.add_parser("report", help="flash, RAM and instructions per event, bsc next to hand-written")
    p.add_argument("--build-dir", type=Path, help="images already built (default: build them in a temporary directory)")
    mode = p.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="fail if a bsc program is over its baseline")
    mode.add_argument("--update", action="store_true", help="write the measured values as the baselines")
    args = parser.parse_args()
    return {"build": command_build, "trace": command_trace, "symbols": command_symbols,
            "report": command_report}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
