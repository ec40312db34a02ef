#!/usr/bin/env python3
"""Regenerate the waveform of the manufacturing cell (docs/examples/manufacturing_cell_waveform.svg).

  python3 scripts/waveform.py [--example PATH] [--out FILE]

runs examples/manufacturing_cell with one piece and --vcd (bsc::vcd_recorder), reads the value
change dump and draws it as a self-contained SVG: the sensors, the actuators, E1..E4, the timers
and the five components' states over the run, with a time axis in seconds. The same input gives
the same bytes.

--example PATH uses a manufacturing_cell already built instead of compiling one with $CXX
(default c++). The VCD is read with the parser of tests/vcd/roundtrip.py, the one the round-trip
test checks against GTKWave.
"""

import argparse
import importlib.util
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from xml.sax.saxutils import escape

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE_SOURCE = ROOT / "examples" / "manufacturing_cell" / "main.cpp"
DEFAULT_OUT = ROOT / "docs" / "examples" / "manufacturing_cell_waveform.svg"
PARSER = ROOT / "tests" / "vcd" / "roundtrip.py"
COMMAND = "python3 scripts/waveform.py"

# The rows, top to bottom: (group, colour, [(label, variable)]). Bits are drawn as square waves,
# the components' states (strings) as labelled boxes.
# The timers show `running`, not `expired`: a device stops and resets its timer in the very cycle
# the timer expires, so `expired` never reads 1 at the end of a cycle.
GROUPS = [
    ("sensors", "#1f63a8", [(name, f"Cell.data.{name}") for name in ("IN", "P1", "P2", "P3", "P4", "S1")]),
    ("actuators", "#b8322a", [(name, f"Cell.data.{name}") for name in ("belt", "drill", "test", "robot", "valve")]),
    ("variables", "#5f6b73", [(name, f"Cell.data.{name}") for name in ("E1", "E2", "E3", "E4")]),
    ("timers", "#7b3fa0", [(f"{name} running", f"Cell.data.{name}.running") for name in ("T1", "T2", "T3")]),
    ("states", "#333333", [(name, f"Cell.states.{name}") for name in ("Belt", "Drill", "Test", "Robot", "Table")]),
]
STATE_FILLS = ["#dbe8f6", "#fce3c8", "#dcefd6", "#eddbe6", "#fff1c6", "#d6e7ea"]

WIDTH = 1200
LEFT = 170  # the names' column
RIGHT = 24
TOP = 46
ROW = 22
GROUP_GAP = 10
AXIS = 44
FONT = 12
CHAR = 0.6 * FONT  # a monospace character's advance


def number(x: float) -> str:
    """A coordinate, rounded so that the output does not depend on float noise."""
    text = f"{x:.1f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def vcd_parser():
    spec = importlib.util.spec_from_file_location("vcd_roundtrip", PARSER)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def build_example(work: Path) -> Path:
    compiler = os.environ.get("CXX", "c++")
    example = work / "manufacturing_cell"
    print(f"compiling {EXAMPLE_SOURCE.relative_to(ROOT)} with {compiler}")
    subprocess.run([compiler, "-std=c++20", "-O1", f"-I{ROOT / 'include'}", f"-I{ROOT / 'examples'}",
                    str(EXAMPLE_SOURCE), "-o", str(example)], check=True)
    return example


def segments(history: list, end: int) -> list[tuple[int, int, object]]:
    """(from, to, value): the value held over each interval up to `end`."""
    result = []
    for i, (time, value) in enumerate(history):
        until = history[i + 1][0] if i + 1 < len(history) else end
        if time < end:
            result.append((time, min(until, end), value))
    return result


def common_prefix(names: list[str]) -> str:
    """The words the names begin with ("Drill" of DrillOff and DrillOn, not "DrillO")."""
    prefix = os.path.commonprefix(names) if len(names) > 1 else ""
    while prefix and not all(len(name) > len(prefix) and name[len(prefix)].isupper() for name in names):
        prefix = prefix[:-1]
    return prefix


class Drawing:
    def __init__(self, end: int, tick: float):
        self.end = end
        self.tick = tick
        self.scale = (WIDTH - LEFT - RIGHT) / end
        self.shapes: list[str] = []

    def x(self, time: int) -> str:
        return number(LEFT + time * self.scale)

    def second(self, s: int) -> str:
        return self.x(round(s / self.tick))

    def text(self, x, y, content: str, anchor="start", extra=""):
        self.shapes.append(f'<text x="{number(x)}" y="{number(y)}" text-anchor="{anchor}"{extra}>'
                           f'{escape(content)}</text>')

    def wave(self, top: float, history: list, colour: str):
        high, low = top + 4, top + ROW - 4
        path = []
        for start, stop, value in segments(history, self.end):
            level = low if value == 0 else high if value == 1 else (high + low) / 2  # x or z: half way
            if value == 1:
                self.shapes.append(f'<rect x="{self.x(start)}" y="{number(high)}" '
                                   f'width="{number((stop - start) * self.scale)}" height="{number(low - high)}" '
                                   f'fill="{colour}" fill-opacity="0.14"/>')
            path.append(f"V{number(level)}" if path else f"M{self.x(start)} {number(level)}")
            path.append(f"H{self.x(stop)}")
        if path:
            self.shapes.append(f'<path d="{" ".join(path)}" fill="none" stroke="{colour}" stroke-width="1.5"/>')

    def states(self, top: float, history: list, colour: str):
        parts = segments(history, self.end)
        names = list(dict.fromkeys(value for _, _, value in parts if value != "-"))  # in order of appearance
        prefix = common_prefix(names)  # "Belt" of BeltOff, BeltOn, BeltDone: the row names the component
        fills = {name: STATE_FILLS[i % len(STATE_FILLS)] for i, name in enumerate(names)}
        y, height = top + 3, ROW - 6
        for start, stop, value in parts:
            width = (stop - start) * self.scale
            if value == "-":  # the component is not active
                self.shapes.append(f'<path d="M{self.x(start)} {number(top + ROW / 2)} H{self.x(stop)}" '
                                   f'stroke="{colour}" stroke-width="1"/>')
                continue
            seconds = f"{start * self.tick:g} s to {stop * self.tick:g} s"
            self.shapes.append(f'<rect x="{self.x(start)}" y="{number(y)}" width="{number(width)}" '
                               f'height="{number(height)}" fill="{fills[value]}" stroke="{colour}" '
                               f'stroke-width="0.8"><title>{escape(f"{value}: {seconds}")}</title></rect>')
            shown = value[len(prefix):]
            if len(shown) * CHAR + 6 <= width:
                self.text(LEFT + (start + stop) / 2 * self.scale, y + height / 2 + FONT * 0.35, shown, "middle")

    def svg(self, height: float, title: str) -> str:
        head = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{number(height)}" '
                f'viewBox="0 0 {WIDTH} {number(height)}" font-family="monospace" font-size="{FONT}">',
                # No "--" in a comment: XML forbids it.
                f"<!-- Generated by `{COMMAND}` from a run of examples/manufacturing_cell; do not edit. -->",
                f"<title>{escape(title)}</title>",
                f'<rect width="{WIDTH}" height="{number(height)}" fill="#ffffff"/>',
                f'<text x="12" y="24" font-size="{FONT + 2}" font-weight="bold">{escape(title)}</text>']
        return "\n".join(head + self.shapes + ["</svg>"]) + "\n"


def draw(dump) -> tuple[str, int, int]:
    """The SVG of a run, its number of rows and the seconds it shows."""
    tick = dump.tick()
    last = dump.last_time() * tick
    end = round((math.floor(last) + 1) / tick)  # whole seconds, with room after the last change
    drawing = Drawing(end, tick)
    shapes = drawing.shapes

    seconds = range(0, round(end * tick) + 1)
    rows = sum(len(signals) for _, _, signals in GROUPS)
    bottom = TOP + rows * ROW + (len(GROUPS) - 1) * GROUP_GAP
    for s in seconds:  # the grid, under the signals
        shapes.append(f'<path d="M{drawing.second(s)} {TOP - 4} V{number(bottom + 4)}" stroke="#e4e4e4" '
                      f'stroke-width="1"/>')

    top = TOP
    for group, colour, signals in GROUPS:
        drawing.text(12, top + ROW / 2 + FONT * 0.35, group, extra=' fill="#888888" font-style="italic"')
        for label, name in signals:
            if name not in dump.variables:
                raise SystemExit(f"{name} is not in the waveform")
            drawing.text(LEFT - 10, top + ROW / 2 + FONT * 0.35, label, "end", f' fill="{colour}"')
            history = dump.history(name)
            if dump.variables[name].kind == "string":
                drawing.states(top, history, colour)
            else:
                drawing.wave(top, history, colour)
            top += ROW
        top += GROUP_GAP
    top += 4 - GROUP_GAP

    shapes.append(f'<path d="M{LEFT} {number(top)} H{WIDTH - RIGHT}" stroke="#333333" stroke-width="1"/>')
    for s in seconds:
        x = drawing.second(s)
        shapes.append(f'<path d="M{x} {number(top)} V{number(top + 5)}" stroke="#333333" stroke-width="1"/>')
        drawing.text(float(x), top + 6 + FONT, str(s), "middle")
    drawing.text(LEFT - 10, top + 6 + FONT, "t [s]", "end")
    title = "Manufacturing cell: one piece through the cell (bsc::vcd_recorder)"
    return drawing.svg(top + AXIS, title), rows, seconds[-1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--example", type=Path, help="a manufacturing_cell executable to use")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT,
                        help=f"the SVG to write (default: {DEFAULT_OUT.relative_to(ROOT)})")
    args = parser.parse_args()
    reader = vcd_parser()
    with tempfile.TemporaryDirectory() as tmp:
        example = args.example.resolve() if args.example else build_example(Path(tmp))
        vcd = Path(tmp) / "cell.vcd"
        run = subprocess.run([str(example), "--quiet", "--pieces", "1", "--vcd", str(vcd)], capture_output=True,
                             text=True)
        if run.returncode != 0:
            sys.stderr.write(run.stdout + run.stderr)
            print(f"{example.name} exited with status {run.returncode}", file=sys.stderr)
            return 1
        try:
            dump = reader.read(vcd)
        except reader.VcdError as error:
            print(error, file=sys.stderr)
            return 1
    svg, rows, seconds = draw(dump)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(svg, encoding="utf-8", newline="\n")
    out = args.out.resolve()
    shown = out.relative_to(ROOT) if out.is_relative_to(ROOT) else out
    print(f"wrote {shown}: {rows} rows, 0 to {seconds} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
