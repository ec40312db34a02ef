#!/usr/bin/env python3
"""Compiles a 200-state chart with one defect and checks that the error fits on one screen.
Covers the checks of make_chart; errors raised where a machine is used (an unhandled event,
is<S> of an unknown state) still spell the machine's type. Every generated chart is also used
by two machines, one declared on `decltype(chart)` and one on `bsc::chart_ref<chart>`: neither
may add an error to the chart's.

    big_chart_error.py --compiler CXX --include DIR --defect KIND [--keep FILE]

The chart: a root with 20 composites C0..C19 of 9 basic states each (200 states), a ring of
transitions inside each composite and one from each composite to the next. KIND adds one
defect (see DEFECTS); KIND+KIND+... adds several, and one error each is expected. The compiler must fail, and its output must
  - report exactly one error (one line with "error:");
  - be at most 60 lines and 8 KB;
  - name the check (bsc::error::KIND) and the culprit in the text up to the first error line;
  - carry bsc's message for the check;
  - for a defect in one row, name the row: bsc::error::at_row<position, ...> with the row's
    position among make_chart's rows, and with GCC the row as written (Clang prints string
    template arguments as character codes, so bsc leaves the text out there);
  - for dead_timeout, which constant evaluation finds (no bsc::error type): with GCC, point at
    the dead row's line and name its type; with Clang, name both rows' positions.
Exits 0 when all hold; otherwise prints what failed, and the output, and exits 1.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

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


# kind -> (culprit names, message regex, edit of (tree, rows, extra declarations, main body))
def edit(kind, tree, rows, extra, body):
    if kind == "unreachable_state":
        tree[5].append("bsc::state<Orphan>")
        rows.append("bsc::state<Orphan> + bsc::event<e1> = bsc::state<S5_0>")
        extra.append("struct Orphan;")
        return ["Orphan"], "unreachable state"
    if kind == "dead_end_state":
        tree["top"].append("bsc::state<Stuck>")
        rows.append("bsc::state<S5_3> + bsc::event<e5> = bsc::state<Stuck>")
        extra.append("struct Stuck;")
        return ["Stuck"], "dead end"
    if kind == "conflicting_transitions":
        rows.append("bsc::state<S7_2> + bsc::event<e2> = bsc::state<S7_5>")
        return ["S7_2", "e2"], "conflicting transitions", "S7_2 + e2 = S7_5"
    if kind == "shadowed_transition":
        rows.append("bsc::state<S7_2> + bsc::event<e2> [([](ctx const&) { return true; })] = bsc::state<S7_5>")
        return ["S7_2", "e2", "S7_5"], "shadowed transition", "S7_2 + e2 [guard] = S7_5"
    if kind == "transition_between_orthogonal_regions":
        extra.append("struct P; struct R1; struct R2; struct A; struct B;")
        tree["top"].append("bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A>), bsc::composite<R2>(bsc::initial<B>))")
        rows.append("bsc::state<S3_4> + bsc::event<e8> = bsc::state<P>")
        rows.append("bsc::state<A> + bsc::event<e1> = bsc::state<B>")
        rows.append("bsc::state<B> + bsc::event<e2> = bsc::state<S3_0>")
        return ["A", "B"], "transition between orthogonal regions", "A + e1 = B"
    if kind == "state_not_in_chart":
        extra.append("struct Ghost;")
        rows.append("bsc::state<S11_1> + bsc::event<e8> = bsc::state<Ghost>")
        return ["Ghost"], "a row names a state that the state tree does not declare", "S11_1 + e8 = Ghost"
    if kind == "duplicate_state":
        tree[4].append("bsc::state<S3_3>")
        return ["S3_3"], "declared twice"
    if kind == "missing_initial_state":
        tree[7] = tree[7][1:]
        return ["C7"], "no initial child"
    if kind == "multiple_initial_states":
        tree[7].insert(1, "bsc::initial<S7_1>")
        return ["C7"], "more than one bsc::initial"
    if kind == "initial_not_a_child":
        tree[7][0] = "bsc::initial<S8_0>"
        return ["C7", "S8_0"], "declared elsewhere in the tree"
    if kind == "eventless_livelock":
        rows.append("bsc::state<S9_1> = bsc::state<S9_2>")
        rows.append("bsc::state<S9_2> = bsc::state<S9_1>")
        return ["S9_[12]"], "eventless livelock"
    if kind == "not_a_row":
        rows.append("bsc::state<S2_2>")
        return ["S2_2"], "every argument of make_chart must be a row"
    if kind == "guard_signature_not_supported":
        extra.append("struct bad_guard { bool operator()(int const&) const { return true; } };")
        rows.append("bsc::state<S6_6> + bsc::event<e0> [bad_guard{}] = bsc::state<S6_1>")
        # The guard is the culprit; its row must be named too, anywhere in the error.
        return (["bad_guard"], r"(?s)(?=.*a guard must be callable as)(?=.*in_row<big::S6_6, big::e0, big::S6_1)",
                "S6_6 + e0 [guard] = S6_1")
    if kind == "action_signature_not_supported":
        extra.append("struct bad_action { void operator()(int&) const {} };")
        rows.append("bsc::state<S6_6> + bsc::on_exit / bad_action{}")
        return (["bad_action"], r"(?s)(?=.*an action must be callable as)(?=.*in_row<big::S6_6, bsc::detail::exit_keyword)",
                "S6_6 + on_exit / action")
    if kind == "dead_transition":
        # Every child of C12 takes e9 first... except that C12's ring uses e0..e8, so give each
        # child its own unguarded e9 row: the composite's e9 row (to C13) never fires.
        for j in range(CHILDREN):
            target = "C13" if j == 1 else f"S12_{(j + 2) % CHILDREN}"  # C13 stays reachable
            rows.append(f"bsc::state<S12_{j}> + bsc::event<e9> = bsc::state<{target}>")
        return ["C12", "e9", "C13"], "dead transition", "C12 + e9 = C13"
    if kind == "empty_parallel_state":
        extra.append("struct P;")
        tree["top"].append("bsc::parallel<P>()")
        rows.append("bsc::state<S5_5> + bsc::event<e9> = bsc::state<P>")
        rows.append("bsc::state<P> + bsc::event<e1> = bsc::state<S5_0>")
        return ["P"], "this parallel state has no regions"
    if kind == "dead_timeout":
        rows.append("bsc::state<S4_4> + bsc::after(std::chrono::seconds(1)) = bsc::state<S4_0>")
        rows.append("bsc::state<S4_4> + bsc::after(std::chrono::seconds(2)) = bsc::state<S4_1>")
        return [], "bsc_dead_transition_timeout_behind_a_shorter_unguarded_timeout", None
    if kind == "local_target_outside_source":
        rows.append("bsc::state<C3> + bsc::event<e8> = bsc::local(bsc::state<S4_0>)")
        return ["C3", "S4_0"], "local transition to a state outside its source", "C3 + e8 = local(S4_0)"
    if kind == "event_in_two_families":
        extra.append("struct fa {}; struct fb {}; struct fab : fa, fb {};")
        rows.append("bsc::state<S2_3> + bsc::event<fab> = bsc::state<S2_4>")
        rows.append("bsc::state<S2_3> + bsc::event<fa> = bsc::state<S2_5>")
        rows.append("bsc::state<S2_3> + bsc::event<fb> = bsc::state<S2_6>")
        return ["fab"], "event in two families"
    if kind == "initial_action_without_initial_transition":
        rows.append("bsc::state<S8_8> + bsc::on_initial / [](ctx&) {}")
        return ["S8_8"], "initial action of a state without an initial transition", "S8_8 + on_initial / action"
    if kind == "invalid_history_state":
        extra.append("struct H;")
        tree[6].append("bsc::shallow_history_state<H, S7_0>")
        rows.append("bsc::state<S5_5> + bsc::event<e9> = bsc::state<H>")
        return ["H"], "invalid history state"
    if kind == "targets_not_orthogonal":
        extra.append("struct P; struct R1; struct R2; struct A1; struct A2; struct B1;")
        tree["top"].append("bsc::parallel<P>(bsc::composite<R1>(bsc::initial<A1>, bsc::state<A2>), "
                           "bsc::composite<R2>(bsc::initial<B1>))")
        rows.append("bsc::state<S3_4> + bsc::event<e8> = bsc::targets(bsc::state<A1>, bsc::state<A2>)")
        rows.append("bsc::state<A1> + bsc::event<e1> = bsc::state<A2>")
        rows.append("bsc::state<P> + bsc::event<e2> = bsc::state<S3_0>")
        return ["S3_4", "A1", "A2"], "targets not orthogonal", "S3_4 + e8 = targets(A1, A2)"
    if kind == "initial_states_not_orthogonal":
        # Q's two initial states are siblings, not states of two regions.
        extra.append("struct Q; struct QA; struct QB;")
        tree["top"].append("bsc::composite<Q>(bsc::initial<QA, QB>, bsc::state<QA>, bsc::state<QB>)")
        rows.append("bsc::state<S3_4> + bsc::event<e8> = bsc::state<Q>")
        rows.append("bsc::state<QA> + bsc::event<e1> = bsc::state<QB>")
        rows.append("bsc::state<Q> + bsc::event<e2> = bsc::state<S3_0>")
        return ["Q"], "initial states not orthogonal"
    if kind == "invalid_deferral":
        rows.append("bsc::state<S5_5> + bsc::event<e9> / bsc::defer = bsc::state<S5_0>")
        return ["S5_5", "e9"], "invalid deferral", "S5_5 + e9 / defer = S5_0"
    if kind == "done_never_raised":
        # C7 has no final child: it never completes.
        rows.append("bsc::state<C7> + bsc::event<bsc::done<C7>> = bsc::state<C8>")
        return ["C7"], "never completes", "C7 + done<C7> = C8"
    if kind == "done_of_state_not_in_chart":
        extra.append("struct Ghost;")
        rows.append("bsc::state<C7> + bsc::event<bsc::done<Ghost>> = bsc::state<C8>")
        return ["Ghost"], "is not a state of this chart", "C7 + done<Ghost> = C8"
    if kind == "done_source_inactive":
        extra.append("struct Fin;")
        tree[7].append("bsc::final_state<Fin>")
        rows.append("bsc::state<S7_8> + bsc::event<e7> = bsc::state<Fin>")
        rows.append("bsc::state<S7_3> + bsc::event<bsc::done<C7>> = bsc::state<C8>")
        return ["S7_3", "C7"], "no longer active when State completes", "S7_3 + done<C7> = C8"
    if kind == "guard_is_a_bool_value":
        extra.append("inline constexpr auto plain = [](ctx const&) { return true; };")
        rows.append("bsc::state<S6_6> + bsc::event<e0> [(!plain)] = bsc::state<S6_1>")
        return ([], r"(?s)(?=.*guard is a bool value)(?=.*in_row<big::S6_6, big::e0, big::S6_1)",
                "S6_6 + e0 [guard] = S6_1")
    raise SystemExit(f"unknown defect {kind}")


DEFECTS = ["unreachable_state", "dead_end_state", "conflicting_transitions", "shadowed_transition",
           "transition_between_orthogonal_regions", "state_not_in_chart", "duplicate_state",
           "missing_initial_state", "multiple_initial_states", "initial_not_a_child", "eventless_livelock",
           "not_a_row", "guard_signature_not_supported", "action_signature_not_supported", "dead_transition",
           "empty_parallel_state", "dead_timeout", "local_target_outside_source", "event_in_two_families",
           "initial_action_without_initial_transition", "invalid_history_state", "targets_not_orthogonal",
           "initial_states_not_orthogonal", "invalid_deferral", "done_never_raised", "done_of_state_not_in_chart",
           "done_source_inactive", "guard_is_a_bool_value"]

# Found by constant evaluation of the chart (timeouts are values), not by a bsc::error type. Its
# error is the failed evaluation of the dead row's destruction (dsl/row.hpp, timeout_trigger),
# whose notes name the row's type and, with GCC, the row's line; Clang prints the positions.
VALUE_CHECKS = {"dead_timeout"}


def source(kinds, clang=False):
    tree, rows = base_chart()
    extra, body = [], []
    found = []
    for kind in kinds:
        culprit, message, *row = edit(kind, tree, rows, extra, body)
        found.append((culprit, message, row[0] if row else None))
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
    found = [(c, m, (row, written.index(row) + 1) if row else None) for c, m, row in found]
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
    if body:
        text.append("inline void run() {")
        text += ["    " + b for b in body]
        text.append("}")
    text.append("}  // namespace big")
    return "\n".join(text) + "\n", found, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--compiler", required=True)
    parser.add_argument("--include", required=True, action="append")
    parser.add_argument("--defect", required=True,
                        help="one of DEFECTS, or several joined by '+' (then one error each is expected)")
    parser.add_argument("--keep", help="write the generated source here")
    args = parser.parse_args()

    kinds = args.defect.split("+")
    for kind in kinds:
        if kind not in DEFECTS:
            parser.error(f"unknown defect {kind}; one of {', '.join(DEFECTS)}")
    text, found, rows = source(kinds, "clang" in os.path.basename(args.compiler))
    with tempfile.TemporaryDirectory() as work:
        path = args.keep or os.path.join(work, "big_chart.cpp")
        with open(path, "w") as f:
            f.write(text)
        command = [args.compiler, "-std=c++20", "-fsyntax-only"] + [f"-I{d}" for d in args.include] + [path]
        result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    out = result.stdout + result.stderr

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
        (culprit, message, row), kind = found[0], kinds[0]
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
            line = text.splitlines().index("    " + rows[dead] + (");" if dead == len(rows) - 1 else ",")) + 1
            if not re.search(rf"{re.escape(os.path.basename(path))}:{line}:\d+:   in .constexpr. expansion of .*transition_row<big::S4_4, "
                             rf"bsc::detail::timeout_trigger, [^>]*, big::S4_1>::~transition_row", out):
                failures.append(f"the dead row (line {line}, S4_4 after 2 s to S4_1) not pointed at")
    for (culprit, message, row), kind in zip(found, kinds):
        if kind not in VALUE_CHECKS and f"bsc::error::{kind}<" not in out:
            failures.append(f"bsc::error::{kind} not named")
        if not re.search(message, out):
            failures.append(f"bsc's message ({message}) missing")
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
