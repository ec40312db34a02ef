#!/usr/bin/env python3
"""Compiles a 200-state chart with one defect and checks that the error fits on one screen.
Covers the checks of make_chart; errors raised where a machine is used (an unhandled event,
is<S> of an unknown state) still spell the machine's type. Every generated chart is also used
by two machines, one declared on `decltype(chart)` and one on `bsc::chart_ref<chart>`: neither
may add an error to the chart's.

    big_chart_error.py --compiler CXX --include DIR --defect KIND [--keep FILE]

The chart: a root with 20 composites C0..C19 of 9 basic states each (200 states), a ring of
transitions inside each composite and one from each composite to the next, and what each defect
of tests/defects/catalogue.py needs: its rows and states, fixed (the catalogue's "fix" items).
KIND is a defect of the catalogue with a 200-state chart: the chart then holds that defect
instead of its fix, and differs from the chart with every defect fixed by that defect only.
KIND+KIND+... holds several, and one error each is expected. The compiler must fail, and its
output must
  - report exactly one error (one line with "error:");
  - be at most 60 lines and 8 KB;
  - name the check (bsc::error::KIND) and the culprit in the text up to the first error line;
  - match the catalogue's regex for the defect: its error type and bsc's message for the check;
  - for a defect in one row, name the row: bsc::error::at_row<position, ...> with the row's
    position among make_chart's rows, and with GCC the row as written (Clang prints string
    template arguments as character codes, so bsc leaves the text out there);
  - for dead_timeout, which constant evaluation finds (no bsc::error type): with GCC, name the
    dead row's type at the end of the chart's declaration; with Clang, name both rows' positions.
KIND `none` is the chart with every defect fixed, the twin of all the others: it must compile,
without a warning under -Wall -Wextra -Wpedantic.
Exits 0 when all hold; otherwise prints what failed, and the output, and exits 1.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "defects"))
import catalogue  # noqa: E402

COMPOSITES = 20
CHILDREN = 9
EVENTS = 10
MAX_LINES = 60
MAX_BYTES = 8 * 1024


def base_chart():
    """The tree (one declaration per composite) and the rows, as lists of C++ text."""
    tree = {"top": []}  # "top": more children of the root
    rows = []
    for i in range(COMPOSITES):
        children = [f"bsc::state<S{i}_{j}>" for j in range(CHILDREN)]
        tree[i] = [f"bsc::initial<S{i}_0>"] + children
        for j in range(CHILDREN):
            rows.append(f"bsc::state<S{i}_{j}> + bsc::event<e{j % EVENTS}> = bsc::state<S{i}_{(j + 1) % CHILDREN}>")
        rows.append(f"bsc::state<C{i}> + bsc::event<e9> = bsc::state<C{(i + 1) % COMPOSITES}>")
    return tree, rows


# The defects with a 200-state chart, in the catalogue's order (which is that of their rows).
DEFECTS = catalogue.big_chart_kinds()

# Found by constant evaluation of the chart (timeouts are values), not by a bsc::error type. Its
# error is the failed evaluation of the dead row's destruction (dsl/row.hpp, timeout_trigger),
# whose notes name the row's type and, with GCC, the end of the chart's declaration; Clang
# prints the positions.
VALUE_CHECKS = {kind for kind in DEFECTS if catalogue.DEFECTS[kind].value}


def add_defects(kinds, tree, rows, extra):
    """Every defect of the catalogue into the chart: as a defect for those in kinds, fixed for
    the others."""
    for kind in DEFECTS:
        variant = "defect" if kind in kinds else "fix"
        for item in catalogue.DEFECTS[kind].big_chart.items:
            if item.only not in ("both", variant):
                continue
            if item.kind == "row":
                rows.append(item.text)
            elif item.kind == "child":
                tree[item.parent].append(item.text)
            elif item.kind == "initial":
                if not tree[item.parent][0].startswith("bsc::initial<"):
                    raise SystemExit(f"{kind}: C{item.parent}'s initial marker is changed by another defect")
                if item.text:
                    tree[item.parent][0] = item.text
                else:
                    del tree[item.parent][0]
            elif item.kind == "decl":
                if item.text not in extra:
                    extra.append(item.text)
            else:
                raise SystemExit(f"{kind}: unknown item {item.kind}")


def source(kinds, clang=False):
    tree, rows = base_chart()
    extra = []
    add_defects(kinds, tree, rows, extra)
    # A row's position among make_chart's rows, counted from 1: the faulty row is found by its
    # text, with the guard, action and delay written as bsc writes them when unnamed.
    def as_written(row):
        row = re.sub(r"bsc::event<bsc::done<(\w+)>>", r"done<\1>", row)
        row = re.sub(r"bsc::(state|event)<(\w+)>", r"\2", row)
        row = re.sub(r"\[\(.*\)\]", "[guard]", row)
        row = re.sub(r"\[bad_guard\{\}\]", "[guard]", row)
        row = re.sub(r"bsc::local\((\w+)\)", r"local(\1)", row)
        row = re.sub(r"bsc::targets\((\w+), (\w+)\)", r"targets(\1, \2)", row)
        row = row.replace("/ bsc::defer", "/ defer")
        row = re.sub(r"/ \[\]\(ctx&\) \{\}", "/ action", row)
        row = row.replace("bsc::on_exit", "on_exit").replace("bsc::on_initial", "on_initial")
        return re.sub(r"/ bad_action\{\}", "/ action", row)
    written = [as_written(r) for r in rows]
    found = []  # (culprits, the catalogue's regex, (the row as written, its position) or None)
    for kind in kinds:
        chart = catalogue.DEFECTS[kind].big_chart
        row = None
        if chart.row:
            if written.count(chart.row) != 1:
                raise SystemExit(f"{kind}: {written.count(chart.row)} rows read {chart.row!r}, not one")
            row = (chart.row, written.index(chart.row) + 1)
        error = f"at_row<{row[1]}, {chart.error}" if row else chart.error
        found.append((chart.culprits, catalogue.regex(error), row))
    names = [f"struct C{i};" for i in range(COMPOSITES)]
    names += [f"struct S{i}_{j};" for i in range(COMPOSITES) for j in range(CHILDREN)]
    events = [f"struct e{k} {{}};" for k in range(EVENTS)]
    composites = [f"        bsc::composite<C{i}>({', '.join(tree[i])})" for i in range(COMPOSITES)]
    composites += ["        " + t for t in tree["top"]]
    text = ["#include <bsc/bsc.hpp>", "#include <chrono>", "", "namespace big {", "struct ctx {};", "struct Root;"]
    text += names + events + extra
    text.append("inline constexpr auto chart = bsc::make_chart<ctx>(")
    text.append("    bsc::composite<Root>(bsc::initial<C0>,")
    text.append(",\n".join(composites) + "),")
    text.append(",\n".join("    " + r for r in rows) + ");")
    # The machine, declared both ways the documentation teaches: on the chart's type and on
    # bsc::chart_ref. A machine on a rejected chart adds no error of its own.
    # A dead timeout is found by evaluating the chart, which then is no constant: Clang reports
    # every use of it that needs one, and bsc::chart_ref<chart> is such a use (docs/checks.md,
    # section 10). Those charts are used by a machine on their type only.
    by_ref = not (clang and any(kind in VALUE_CHECKS for kind in kinds))
    text.append("using machine = bsc::machine<decltype(chart)>;")
    if by_ref:
        text.append("using machine_of_ref = bsc::machine<bsc::chart_ref<chart>>;")
    text.append("inline void drive() {")
    text.append("    machine m{chart};")
    text.append("    (void)m.dispatch(e0{});")
    if by_ref:
        text.append("    machine_of_ref r{chart};")
        text.append("    (void)r.dispatch(e0{});")
        text.append("    (void)r.is<S0_0>();")
    text.append("}")
    text.append("}  // namespace big")
    return "\n".join(text) + "\n", found, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--compiler", required=True)
    parser.add_argument("--include", required=True, action="append")
    parser.add_argument("--defect", required=True,
                        help="a defect of the catalogue with a 200-state chart, several joined by '+' (then "
                             "one error each is expected), or none (every defect fixed: the chart must compile)")
    parser.add_argument("--keep", help="write the generated source here")
    args = parser.parse_args()

    kinds = [] if args.defect == "none" else args.defect.split("+")
    for kind in kinds:
        if kind not in DEFECTS:
            parser.error(f"unknown defect {kind}; one of {', '.join(DEFECTS)}, or none")
    text, found, rows = source(kinds, "clang" in os.path.basename(args.compiler))
    warnings = [] if kinds else ["-Wall", "-Wextra", "-Wpedantic"]
    with tempfile.TemporaryDirectory() as work:
        path = args.keep or os.path.join(work, "big_chart.cpp")
        with open(path, "w") as f:
            f.write(text)
        command = [args.compiler, "-std=c++20", "-fsyntax-only"] + warnings + [f"-I{d}" for d in args.include] + [path]
        result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    out = result.stdout + result.stderr

    if not kinds:
        # The twin of every other chart of this test.
        print(f"none: {len(rows)} rows, every defect of the catalogue fixed: "
              + ("compiles" if result.returncode == 0 and not out else "FAILED"))
        if result.returncode != 0 or out:
            print(out)
            return 1
        return 0

    failures = []
    if result.returncode == 0:
        failures.append("the chart compiled")
    errors = [line for line in out.splitlines() if re.search(r": error: ", line)]
    if len(errors) != len(kinds):
        failures.append(f"{len(errors)} error lines, not {len(kinds)}")
    lines = out.count("\n")
    clang = "clang" in os.path.basename(args.compiler)
    if lines > MAX_LINES:
        failures.append(f"{lines} lines (at most {MAX_LINES})")
    if len(out.encode()) > MAX_BYTES:
        failures.append(f"{len(out.encode())} bytes (at most {MAX_BYTES})")
    first = out.find(": error: ")
    head = out[: out.find("\n", first) if first >= 0 else len(out)]
    if len(kinds) == 1 and kinds[0] not in VALUE_CHECKS:
        (culprit, expected, row), kind = found[0], kinds[0]
        if f"bsc::error::{kind}<" not in head:
            failures.append(f"bsc::error::{kind} not named up to the first error line")
        for name in culprit:
            if not re.search(rf"\bbig::{name}\b", head):
                failures.append(f"the culprit {name} not named up to the first error line")
    if kinds == ["dead_timeout"]:
        # The dead row is the later, longer timeout of S4_4; the one that fires first, the shorter.
        dead = next(i for i, r in enumerate(rows) if "after(std::chrono::seconds(2))" in r)
        first = next(i for i, r in enumerate(rows) if "after(std::chrono::seconds(1))" in r)
        if clang:
            if f"timeout_row_never_fires({dead + 1}, {first + 1})" not in out:
                failures.append(f"the positions of the dead row and the row before it ({dead + 1}, {first + 1}) not named")
        else:
            # The dead row's copy is destroyed at the end of the chart's declaration, its last line.
            line = text.splitlines().index("    " + rows[-1] + ");") + 1
            if not re.search(rf"{re.escape(os.path.basename(path))}:{line}:\d+:   in .constexpr. expansion of .*transition_row<big::S4_4, "
                             rf"bsc::detail::timeout_trigger, [^>]*, big::S4_1>::~transition_row", out):
                failures.append(f"the dead row (S4_4 after 2 s to S4_1) not named at the end of the chart's declaration "
                                f"(line {line})")
    for (culprit, expected, row), kind in zip(found, kinds):
        if kind not in VALUE_CHECKS and f"bsc::error::{kind}<" not in out:
            failures.append(f"bsc::error::{kind} not named")
        # As CMake's PASS_REGULAR_EXPRESSION reads it, where `.` matches a newline too.
        if not re.search(expected, out, re.S):
            failures.append(f"the catalogue's regex for {kind} ({expected}) not matched")
        if row:
            text, position = row
            if f"bsc::error::at_row<{position}, " not in out:
                failures.append(f"the row's position ({position}) not named as bsc::error::at_row<{position}, ...>")
            if not clang and f'{{"{text}"}}' not in out:
                failures.append(f'the row as written ("{text}") missing')
    print(f"{args.defect}: {lines} lines, {len(out.encode())} bytes, {len(errors)} error line(s)")
    if failures:
        print("FAILED: " + "; ".join(failures))
        print(out)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
