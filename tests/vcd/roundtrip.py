#!/usr/bin/env python3
"""Round-trip the manufacturing cell's waveform through GTKWave's FST format (ctest vcd_roundtrip).

  python3 tests/vcd/roundtrip.py --example PATH --work DIR

runs the manufacturing cell example (PATH) with --vcd DIR/cell.vcd, converts the file with
GTKWave's vcd2fst to DIR/cell.fst and back with fst2vcd to DIR/back.vcd, and checks that

  - both files are well-formed VCD: the parser below rejects, with the line, what IEEE 1364
    (section 18) does not allow, so bsc::vcd_recorder's file is checked as well as GTKWave's;
  - GTKWave read the variables bsc::vcd_recorder declared and every value change it wrote;
  - what GTKWave read back is the cell at work (see behaviour()).

vcd2fst exits 0 on a file it cannot read, so the values are read back rather than trusting it.
Exits 0 if all holds, 1 on a failure (each one printed), 77 (skipped) without vcd2fst and fst2vcd.

scripts/waveform.py reads its VCD with read() from this file.
"""

import argparse
import math
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

SKIP = 77  # ctest's SKIP_RETURN_CODE

# ---- A VCD reader ---------------------------------------------------------------------------

# IEEE 1364-2005's variable types, and GTKWave's `string`, which bsc::vcd_recorder uses for state names.
VAR_KINDS = {"event", "integer", "parameter", "real", "realtime", "reg", "supply0", "supply1", "time", "tri",
             "triand", "trior", "trireg", "tri0", "tri1", "wand", "wire", "wor", "string"}
REAL_KINDS = {"real", "realtime"}
TIMESTAMP = re.compile(r"#(\d+)")
VECTOR = re.compile(r"[01xzXZ]+")
# printf's %g, which IEEE 1364 writes reals with (inf and nan too: GTKWave reads them with strtod).
REAL = re.compile(r"[+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf(?:inity)?|nan)", re.I)
TIMESCALE = re.compile(r"(1|10|100)(s|ms|us|ns|ps|fs)")
UNITS_PER_SECOND = {"s": 1.0, "ms": 1e3, "us": 1e6, "ns": 1e9, "ps": 1e12, "fs": 1e15}
TEXT_COMMANDS = {"$comment", "$date", "$version"}
COMMANDS = {"$comment", "$date", "$version", "$timescale", "$scope", "$upscope", "$var", "$enddefinitions",
            "$dumpvars", "$dumpall", "$dumpon", "$dumpoff"}


class VcdError(ValueError):
    """A file that is not well-formed VCD; the message names the file and the line."""


@dataclass
class Variable:
    name: str  # hierarchical: the scopes and the reference, joined by dots ("Cell.data.belt")
    kind: str
    width: int
    ident: str


@dataclass
class Dump:
    timescale: str = ""  # without blanks, e.g. "1ns"
    variables: dict[str, Variable] = field(default_factory=dict)  # by name, in declaration order
    # Value changes by identifier, in file order: (time, value). A value is an int (a scalar or a
    # binary vector), a float (a real), a str (a string's text, "nan", or a vector holding x or z).
    changes: dict[str, list[tuple[int, object]]] = field(default_factory=dict)

    def history(self, name: str) -> list[tuple[int, object]]:
        """The variable's changes as a viewer shows them: the last value at each time, and only
        values that differ from the one before."""
        result: list[tuple[int, object]] = []
        for time, value in self.changes[self.variables[name].ident]:
            if result and result[-1][0] == time:
                result.pop()
            if not result or result[-1][1] != value:
                result.append((time, value))
        return result

    def tick(self) -> float:
        """The time unit in seconds."""
        match = TIMESCALE.fullmatch(self.timescale)
        if match is None:
            raise VcdError(f"no timescale that gives a time unit: {self.timescale!r}")
        return int(match[1]) / UNITS_PER_SECOND[match[2]]

    def last_time(self) -> int:
        return max((changes[-1][0] for changes in self.changes.values() if changes), default=0)


def parse(text: str, source: str = "<vcd>") -> Dump:
    """Reads a VCD file's text; raises VcdError at the first thing IEEE 1364 does not allow."""
    stream = ((number, token) for number, line in enumerate(text.splitlines(), 1) for token in line.split())
    dump = Dump()
    by_ident: dict[str, Variable] = {}
    scopes: list[str] = []
    defined = False  # past $enddefinitions
    time = 0
    open_dump: str | None = None  # the $dumpvars (or $dumpall ...) being read
    line = 0

    def fail(message: str, at: int | None = None):
        raise VcdError(f"{source}:{at or line}: {message}")

    def until_end(keyword: str) -> list[str]:
        start, words = line, []
        for _, word in stream:
            if word == "$end":
                return words
            # Free text may hold anything; elsewhere a command's name means the $end is missing.
            if word in COMMANDS and keyword not in TEXT_COMMANDS:
                break
            words.append(word)
        fail(f"{keyword} without $end", start)

    def declaring(keyword: str):
        if defined:
            fail(f"{keyword} after $enddefinitions")

    for line, token in stream:
        if token in TEXT_COMMANDS:
            until_end(token)
        elif token == "$timescale":
            declaring(token)
            dump.timescale = "".join(until_end(token))
        elif token == "$scope":
            declaring(token)
            words = until_end(token)
            if len(words) != 2:
                fail("$scope needs a type and a name")
            scopes.append(words[1])
        elif token == "$upscope":
            declaring(token)
            if until_end(token):
                fail("$upscope takes no arguments")
            if not scopes:
                fail("$upscope outside a scope")
            scopes.pop()
        elif token == "$var":
            declaring(token)
            words = until_end(token)
            if len(words) < 4:
                fail("$var needs a type, a size, an identifier and a reference")
            kind, size, ident, *reference = words
            if kind not in VAR_KINDS:
                fail(f"unknown variable type {kind!r}")
            if not size.isdigit() or (int(size) == 0 and kind != "string"):
                fail(f"bad size {size!r}")
            name = ".".join(scopes + ["".join(reference)])  # a bit select ("[7:0]") stays with its name
            if name in dump.variables:
                fail(f"{name} declared twice")
            variable = Variable(name, kind, int(size), ident)
            earlier = by_ident.get(ident)
            if earlier is not None and (earlier.kind, earlier.width) != (kind, variable.width):
                fail(f"identifier {ident!r} of {earlier.name} declared again as {kind} {size}")
            dump.variables[name] = variable
            by_ident.setdefault(ident, variable)
            dump.changes.setdefault(ident, [])
        elif token == "$enddefinitions":
            declaring(token)
            until_end(token)
            if scopes:
                fail(f"$enddefinitions inside scope {'.'.join(scopes)}")
            defined = True
        elif token in ("$dumpvars", "$dumpall", "$dumpon", "$dumpoff"):
            if not defined:
                fail(f"{token} before $enddefinitions")
            if open_dump:
                fail(f"{token} inside {open_dump}")
            open_dump = token
        elif token == "$end":
            if not open_dump:
                fail("$end without a command")
            open_dump = None
        elif token.startswith("$"):
            fail(f"unknown command {token}")
        elif token.startswith("#"):
            if not defined:
                fail("timestamp before $enddefinitions")
            if open_dump:
                fail(f"timestamp inside {open_dump}")
            match = TIMESTAMP.fullmatch(token)
            if match is None:
                fail(f"bad timestamp {token!r}")
            if int(match[1]) < time:
                fail(f"time goes back from {time} to {match[1]}")
            time = int(match[1])
        else:
            if not defined:
                fail(f"value change {token!r} before $enddefinitions")
            letter = token[0].lower()
            if letter in "brs":
                text = token[1:]
                ident = next(stream, (line, None))[1]
                if ident is None:
                    fail(f"value {token!r} without an identifier")
            elif letter in "01xz":
                text, ident = letter, token[1:]
                if not ident:
                    fail(f"value {token!r} without an identifier")
            else:
                fail(f"not a value change: {token!r}")
            variable = by_ident.get(ident)
            if variable is None:
                fail(f"value change of unknown identifier {ident!r}")
            dump.changes[ident].append((time, value_of(letter, text, variable, fail)))
    if open_dump:
        fail(f"{open_dump} without $end")
    if not defined:
        fail("no $enddefinitions")
    return dump


def value_of(letter: str, text: str, variable: Variable, fail) -> object:
    """A value change's value, checked against its variable's declaration."""
    where = f"{variable.kind} {variable.name}"
    if letter == "s":
        if variable.kind != "string":
            fail(f"string value for {where}")
        return text
    if letter == "r":
        if variable.kind not in REAL_KINDS:
            fail(f"real value for {where}")
        if not REAL.fullmatch(text):
            fail(f"bad real value {text!r} for {where}")
        number = float(text)
        return "nan" if math.isnan(number) else number  # so that NaN equals NaN
    if variable.kind in REAL_KINDS or variable.kind == "string":
        fail(f"bit value for {where}")
    if letter != "b" and variable.width != 1:
        fail(f"scalar value for {where}, which has {variable.width} bits")
    if not VECTOR.fullmatch(text):
        fail(f"vector value {text!r} for {where} has digits other than 0, 1, x and z")
    if len(text) > variable.width:
        fail(f"vector value of {len(text)} digits for {where}, which has {variable.width} bits")
    if set(text) <= {"0", "1"}:
        return int(text, 2)
    return text.lower().lstrip("0") or "0"


def read(path: Path) -> Dump:
    return parse(path.read_text(encoding="utf-8"), str(path))


# ---- The checks -----------------------------------------------------------------------------

def timeline(dump: Dump, names: list[str]):
    """(time, values by name) after each time at which one of the variables changes."""
    histories = {name: dump.history(name) for name in names}
    values: dict[str, object] = dict.fromkeys(names)
    next_change = dict.fromkeys(names, 0)
    for time in sorted({t for history in histories.values() for t, _ in history}):
        for name, history in histories.items():
            i = next_change[name]
            if i < len(history) and history[i][0] == time:
                values[name] = history[i][1]
                next_change[name] = i + 1
        yield time, values


def describe(change: tuple[int, object] | None) -> str:
    return "nothing" if change is None else f"{change[1]!r} at {change[0]}"


def compare(written: Dump, read_back: Dump) -> list[str]:
    """Where the file GTKWave wrote back differs from the one bsc::vcd_recorder wrote."""
    failures = []
    if written.timescale != read_back.timescale:
        failures.append(f"timescale {written.timescale}, read back as {read_back.timescale}")
    failures += [f"{name}: declared but not read back" for name in written.variables
                 if name not in read_back.variables]
    failures += [f"{name}: read back but never declared" for name in read_back.variables
                 if name not in written.variables]
    for name, ours in written.variables.items():
        theirs = read_back.variables.get(name)
        if theirs is None:
            continue
        # fst2vcd declares every string with size 0.
        if ours.kind != theirs.kind or (ours.width != theirs.width and ours.kind != "string"):
            failures.append(f"{name}: declared {ours.kind} {ours.width}, read back as {theirs.kind} {theirs.width}")
        a, b = written.history(name), read_back.history(name)
        if a != b:
            i = next(i for i in range(max(len(a), len(b))) if i >= len(a) or i >= len(b) or a[i] != b[i])
            failures.append(f"{name}: {len(a)} changes written, {len(b)} read back; change {i + 1} is "
                            f"{describe(a[i] if i < len(a) else None)}, read back as "
                            f"{describe(b[i] if i < len(b) else None)}")
    return failures


PIECES = 2
DRILL_TIME = 3.0  # cell::drill_time, seconds


def rising_edges(history: list[tuple[int, object]]) -> int:
    return sum(1 for (_, before), (_, after) in zip(history, history[1:]) if before == 0 and after == 1)


def behaviour(dump: Dump) -> list[str]:
    """The cell at work, as the file shows it (examples/manufacturing_cell/controller.hpp)."""
    belt, robot, running = "Cell.data.belt", "Cell.data.robot", "Cell.data.T1.running"
    belt_state = "Cell.states.Belt"
    belt_states = ["BeltOff", "BeltOn", "BeltDone"]
    active = {state: f"Cell.states.active.{state}" for state in belt_states}
    names = [belt, robot, running, belt_state, *active.values()]
    missing = [name for name in names if name not in dump.variables]
    if missing:
        return [f"{name}: not in the file" for name in missing]

    failures = []
    for time, values in timeline(dump, names):
        # The belt output is published at the end of the cycle whose transition entered or left
        # BeltOn, so it changes in the same sample as the state.
        if values[belt] != values[active["BeltOn"]]:
            failures.append(f"at {time}: belt is {values[belt]} but BeltOn's wire is {values[active['BeltOn']]}")
        on = [state for state in belt_states if values[active[state]] == 1]
        if len(on) > 1:
            failures.append(f"at {time}: Belt has {len(on)} active children: {', '.join(on)}")
        if values[belt_state] != (on[0] if on else "-"):
            failures.append(f"at {time}: Belt names {values[belt_state]!r} but the active wires say "
                            f"{on[0] if on else '-'!r}")
    stored = rising_edges(dump.history(robot))
    if stored != PIECES:
        failures.append(f"{robot}: rises {stored} times, once per piece expected ({PIECES})")
    # T1.expired never reads 1 in a sample: the cycle in which the timer expires is the one in
    # which g5 (tm1.tm) switches the drill off and resets it (reset clears the elapsed time too).
    # The timer runs from the cycle after DrillOn starts it to that cycle: the drilling time.
    history = dump.history(running)
    rises = [t for (_, before), (t, after) in zip(history, history[1:]) if before == 0 and after == 1]
    falls = [t for (_, before), (t, after) in zip(history, history[1:]) if before == 1 and after == 0]
    limit = round(DRILL_TIME / dump.tick())
    if len(rises) != PIECES or len(falls) != PIECES:
        failures.append(f"{running}: rises {len(rises)} and falls {len(falls)} times, once per piece expected "
                        f"({PIECES})")
    for rise, fall in zip(rises, falls):
        if fall - rise != limit:
            failures.append(f"{running}: high from {rise} to {fall}, the drilling time ({DRILL_TIME:g} s) expected")
    if dump.last_time() <= 0:
        failures.append("no value changes after time 0")
    return failures


# ---- The test ---------------------------------------------------------------------------------

def run(command: list, timeout: float, output: Path | None = None) -> str | None:
    """Runs a step; what went wrong, or None."""
    shown = " ".join(str(c) for c in command)
    try:
        if output is None:
            done = subprocess.run([str(c) for c in command], capture_output=True, text=True, timeout=timeout)
        else:
            with output.open("w", encoding="utf-8") as out:
                done = subprocess.run([str(c) for c in command], stdout=out, stderr=subprocess.PIPE, text=True,
                                      timeout=timeout)
    except subprocess.TimeoutExpired:
        return f"{shown}: no end after {timeout:g} s"
    except OSError as error:
        return f"{shown}: {error}"
    if done.returncode != 0:
        said = ((done.stdout or "") + done.stderr).strip()
        return f"{shown}: exit status {done.returncode}" + (f"\n{said}" if said else "")
    return None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--example", type=Path, required=True, help="the manufacturing_cell executable")
    parser.add_argument("--work", type=Path, required=True, help="a directory for the files")
    args = parser.parse_args()

    missing = [tool for tool in ("vcd2fst", "fst2vcd") if shutil.which(tool) is None]
    if missing:
        print(f"skipped: GTKWave's {' and '.join(missing)} not on PATH (apt-get install gtkwave)", file=sys.stderr)
        return SKIP

    args.work.mkdir(parents=True, exist_ok=True)
    vcd, fst, back = args.work / "cell.vcd", args.work / "cell.fst", args.work / "back.vcd"
    for stale in (vcd, fst, back):  # a step that writes nothing must not pass on an earlier run's file
        stale.unlink(missing_ok=True)
    steps = [([args.example.resolve(), "--quiet", "--pieces", PIECES, "--vcd", vcd], 120, None),
             (["vcd2fst", vcd, fst], 60, None),
             (["fst2vcd", fst], 60, back)]
    for command, timeout, output in steps:
        error = run(command, timeout, output)
        if error:
            print(f"FAILED: {error}", file=sys.stderr)
            return 1

    try:
        written, read_back = read(vcd), read(back)
    except (OSError, UnicodeDecodeError, VcdError) as error:
        print(f"FAILED: {error}", file=sys.stderr)
        return 1
    failures = compare(written, read_back) + behaviour(read_back)
    for failure in failures:
        print(f"FAILED: {failure}", file=sys.stderr)
    if failures:
        return 1

    histories = [written.history(name) for name in written.variables]
    changes = sum(len(history) for history in histories)
    first = min((history[0][0] for history in histories if history), default=0)
    tick = written.tick()
    print(f"{vcd.name} -> {fst.name} -> {back.name}: {len(written.variables)} variables, {changes} value changes "
          f"from {first * tick:g} s to {written.last_time() * tick:g} s read back alike; the cell's behaviour holds")
    return 0


if __name__ == "__main__":
    sys.exit(main())
