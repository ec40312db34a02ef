#!/usr/bin/env python3
"""Generate the single-header distribution of bsc.

Starting from include/bsc/bsc.hpp, every include that resolves to a file under
include/ is inlined in place, depth-first and only the first time it is seen;
all other includes are kept as they are. The opt-in parts, the explorer (include/bsc/verify.hpp), the diagram exports
(include/bsc/export.hpp), the logger (include/bsc/logger.hpp), the retentive state
(include/bsc/retain.hpp), the VCD recorder (include/bsc/vcd.hpp) and the distributed
systems (include/bsc/net.hpp, and include/bsc/mqtt.hpp over MQTT), the Boost.Hana adapter
(include/bsc/adapt/hana.hpp, as hana.hpp), several observers as one (include/bsc/observers.hpp),
the trace stream (include/bsc/trace.hpp, include/bsc/trace_reader.hpp) and the inspectors
(include/bsc/inspector.hpp, include/bsc/system_inspector.hpp), become files of
their own that include the first and add only what it lacks; a part whose entry
includes another part's entry includes that part's single header instead of a copy of
it (net.hpp includes retain.hpp, mqtt.hpp includes net.hpp); a header two of them
share otherwise is guarded by a macro, so that they can be included together. The output is
deterministic so that it can be checked in and verified with --check.
"""

import argparse
import difflib
import re
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
INCLUDE_DIR = ROOT / "include"
ENTRY = INCLUDE_DIR / "bsc" / "bsc.hpp"
VERIFY_ENTRY = INCLUDE_DIR / "bsc" / "verify.hpp"
EXPORT_ENTRY = INCLUDE_DIR / "bsc" / "export.hpp"
LOGGER_ENTRY = INCLUDE_DIR / "bsc" / "logger.hpp"
RETAIN_ENTRY = INCLUDE_DIR / "bsc" / "retain.hpp"
VCD_ENTRY = INCLUDE_DIR / "bsc" / "vcd.hpp"
NET_ENTRY = INCLUDE_DIR / "bsc" / "net.hpp"
MQTT_ENTRY = INCLUDE_DIR / "bsc" / "mqtt.hpp"
HANA_ENTRY = INCLUDE_DIR / "bsc" / "adapt" / "hana.hpp"
OBSERVERS_ENTRY = INCLUDE_DIR / "bsc" / "observers.hpp"
TRACE_ENTRY = INCLUDE_DIR / "bsc" / "trace.hpp"
TRACE_READER_ENTRY = INCLUDE_DIR / "bsc" / "trace_reader.hpp"
INSPECTOR_ENTRY = INCLUDE_DIR / "bsc" / "inspector.hpp"
SYSTEM_INSPECTOR_ENTRY = INCLUDE_DIR / "bsc" / "system_inspector.hpp"
DEFAULT_OUTPUT = ROOT / "single_include" / "bsc" / "bsc.hpp"
COMMAND = "python3 scripts/amalgamate.py"

INCLUDE_RE = re.compile(r'^\s*#\s*include\s*(?:<(?P<angle>[^>]+)>|"(?P<quote>[^"]+)")')
PRAGMA_ONCE_RE = re.compile(r"^\s*#\s*pragma\s+once\b")

HEADER = f"""\
#pragma once
// bsc - Basic Statecharts, single-header distribution.
// Generated from include/bsc/bsc.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
"""

VERIFY_HEADER = f"""\
#pragma once
// bsc::verify - the state-space explorer, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/verify.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

EXPORT_HEADER = f"""\
#pragma once
// bsc exports - Mermaid, Graphviz, PlantUML and SCXML, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/export.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

LOGGER_HEADER = f"""\
#pragma once
// bsc::logger - records of what a machine does, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/logger.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

RETAIN_HEADER = f"""\
#pragma once
// bsc::save and bsc::restore - retentive state, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/retain.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

HANA_HEADER = f"""\
#pragma once
// bsc::fields for Boost.Hana Structs, single-header distribution (needs bsc.hpp beside it, and Boost).
// Generated from include/bsc/adapt/hana.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

VCD_HEADER = f"""\
#pragma once
// bsc::vcd_recorder - waveforms of a machine's scans, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/vcd.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

NET_HEADER = f"""\
#pragma once
// bsc::net - a system deployed across nodes, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/net.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

MQTT_HEADER = f"""\
#pragma once
// bsc::net over MQTT, single-header distribution (needs bsc.hpp beside it, and libmosquitto).
// Generated from include/bsc/mqtt.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""


OBSERVERS_HEADER = f"""\
#pragma once
// bsc::observers - several observers as one, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/observers.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

TRACE_HEADER = f"""\
#pragma once
// bsc::tracer and bsc::trace_buffer - the trace stream, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/trace.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

TRACE_READER_HEADER = f"""\
#pragma once
// bsc::trace_reader - the trace stream read back, single-header distribution (needs bsc.hpp beside it).
// Generated from include/bsc/trace_reader.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

INSPECTOR_HEADER = f"""\
#pragma once
// bsc::inspector - a live view in the browser, single-header distribution (needs bsc.hpp beside it; POSIX).
// Generated from include/bsc/inspector.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""

SYSTEM_INSPECTOR_HEADER = f"""\
#pragma once
// bsc::system_inspector - a live view of a system in the browser, single-header distribution (needs bsc.hpp and
// inspector.hpp beside it; POSIX).
// Generated from include/bsc/system_inspector.hpp by `{COMMAND}`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
"""


def relative(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


def resolve(line: str, current: Path) -> Path | None:
    """Return the project header an include line refers to, or None to keep the line."""
    match = INCLUDE_RE.match(line)
    if not match:
        return None
    if match["angle"] is not None:
        if not match["angle"].startswith("bsc/"):
            return None
        candidates = [INCLUDE_DIR / match["angle"]]
    else:
        candidates = [current.parent / match["quote"], INCLUDE_DIR / match["quote"]]
    for candidate in candidates:
        candidate = candidate.resolve()
        if candidate.is_file() and candidate.is_relative_to(INCLUDE_DIR):
            return candidate
    if match["angle"] is not None:
        # A missing <bsc/...> header would otherwise leak into the output unnoticed.
        raise SystemExit(f"{relative(current)}: cannot resolve {line.strip()}")
    return None


def guard_macro(path: Path) -> str:
    return "BSC_SINGLE_" + re.sub(r"[^A-Za-z0-9]", "_", relative(path)).upper()


def inline(path: Path, seen: set[Path], out: list[str], guarded: set[Path] = frozenset(),
           parts: dict[Path, tuple[str, frozenset[Path]]] | None = None) -> None:
    """Inline path and what it includes; headers in `guarded` get a macro include guard. An
    include of another part's entry header (in `parts`: its single header's name and what that
    holds) becomes an include of that single header, not a second copy of its content."""
    seen.add(path)
    out.append(f"// begin {relative(path)}\n")
    if path in guarded:
        out.append(f"#ifndef {guard_macro(path)}\n#define {guard_macro(path)}\n")
    for line in path.read_text(encoding="utf-8").splitlines(keepends=True):
        if PRAGMA_ONCE_RE.match(line):
            continue
        target = resolve(line, path)
        if target is None:
            out.append(line if line.endswith("\n") else line + "\n")
        elif parts and target in parts and target not in seen:
            name, holds = parts[target]
            out.append(f'#include "{name}"\n')
            seen |= holds
        elif target not in seen:
            inline(target, seen, out, guarded, parts)
    if path in guarded:
        out.append(f"#endif  // {guard_macro(path)}\n")
    out.append(f"// end {relative(path)}\n")


PARTS = [(VERIFY_ENTRY, VERIFY_HEADER, "verify.hpp"), (EXPORT_ENTRY, EXPORT_HEADER, "export.hpp"),
         (LOGGER_ENTRY, LOGGER_HEADER, "logger.hpp"), (RETAIN_ENTRY, RETAIN_HEADER, "retain.hpp"),
         (VCD_ENTRY, VCD_HEADER, "vcd.hpp"), (NET_ENTRY, NET_HEADER, "net.hpp"),
         (MQTT_ENTRY, MQTT_HEADER, "mqtt.hpp"), (HANA_ENTRY, HANA_HEADER, "hana.hpp"),
         (OBSERVERS_ENTRY, OBSERVERS_HEADER, "observers.hpp"), (TRACE_ENTRY, TRACE_HEADER, "trace.hpp"),
         (TRACE_READER_ENTRY, TRACE_READER_HEADER, "trace_reader.hpp"),
         (INSPECTOR_ENTRY, INSPECTOR_HEADER, "inspector.hpp"),
         (SYSTEM_INSPECTOR_ENTRY, SYSTEM_INSPECTOR_HEADER, "system_inspector.hpp")]


def amalgamate() -> list[tuple[str, str]]:
    """The single header, then each opt-in part's header that includes it: (name, text)."""
    if not ENTRY.is_file():
        raise SystemExit(f"missing entry header {relative(ENTRY)}")
    seen: set[Path] = set()
    out = [HEADER]
    inline(ENTRY.resolve(), seen, out)
    in_single_header = frozenset(seen)
    # Each part in order: a part that includes an earlier one includes its single header. What
    # each part holds, and which headers more than one part inlines (those get a guard).
    parts: dict[Path, tuple[str, frozenset[Path]]] = {}
    uses: dict[Path, int] = {}
    for entry, _, name in PARTS:
        part_seen = set(in_single_header)
        inline(entry.resolve(), part_seen, [], frozenset(), parts)
        parts[entry.resolve()] = (name, frozenset(part_seen))
    owned: dict[Path, frozenset[Path]] = {}
    for entry, _, name in PARTS:
        own = set(in_single_header)
        inline(entry.resolve(), own, [], frozenset(), {k: v for k, v in parts.items() if k != entry.resolve()})
        owned[entry.resolve()] = frozenset(own - in_single_header)
        for path in owned[entry.resolve()]:
            uses[path] = uses.get(path, 0) + 1
    shared = frozenset(path for path, count in uses.items() if count > 1)
    results = [("bsc.hpp", "".join(out))]
    for entry, header, name in PARTS:
        text = [header]
        earlier = {k: v for k, v in parts.items() if k != entry.resolve()}
        inline(entry.resolve(), set(in_single_header), text, shared, earlier)
        results.append((name, "".join(text)))
    return results


def check(content: str, output: Path) -> int:
    with tempfile.TemporaryDirectory() as tmp:
        generated = Path(tmp) / output.name
        generated.write_text(content, encoding="utf-8", newline="\n")
        if not output.is_file():
            print(f"{output} does not exist; run `{COMMAND}`", file=sys.stderr)
            return 1
        expected = generated.read_text(encoding="utf-8").splitlines(keepends=True)
        actual = output.read_text(encoding="utf-8").splitlines(keepends=True)
    if actual == expected:
        print(f"{output} is up to date")
        return 0
    diff = list(difflib.unified_diff(actual, expected, str(output), "regenerated"))
    added = sum(1 for d in diff if d.startswith("+") and not d.startswith("+++"))
    removed = sum(1 for d in diff if d.startswith("-") and not d.startswith("---"))
    print(f"{output} is out of date (+{added} -{removed} lines); run `{COMMAND}`",
          file=sys.stderr)
    sys.stderr.writelines(diff[:40])
    if len(diff) > 40:
        print(f"... {len(diff) - 40} more diff lines", file=sys.stderr)
    return 1


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", type=Path, default=DEFAULT_OUTPUT,
                        help=f"file to write or check (default: {relative(DEFAULT_OUTPUT)})")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 if the output file differs from a fresh amalgamation")
    args = parser.parse_args()

    parts = amalgamate()
    outputs = [(parts[0][1], args.output)] + [(text, args.output.parent / name) for name, text in parts[1:]]
    if args.check:
        return max(check(text, path) for text, path in outputs)
    for text, path in outputs:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8", newline="\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
