#!/usr/bin/env python3
"""Checks the files written by `export_diagrams --all DIR` (ctests exports.*).

  check_exports.py scxml DIR   each .scxml is well-formed XML, an SCXML 1.0 document whose ids
                               are unique and whose targets and initial states exist, whose
                               internal transitions with a target stay inside their source, and
                               whose done.state.X events name states
  check_exports.py dot DIR     each .dot renders with Graphviz (dot -Tsvg) without a warning;
                               exits 77 (the ctest counts it as skipped) when dot is not installed
"""

import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

SCXML = "{http://www.w3.org/2005/07/scxml}"
SKIPPED = 77


def check_scxml(path: Path) -> list[str]:
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        return [f"not well-formed: {error}"]
    errors = []
    if root.tag != SCXML + "scxml":
        errors.append(f"root element is {root.tag}, not <scxml> in the SCXML namespace")
    if root.get("version") != "1.0":
        errors.append("<scxml> has no version=\"1.0\"")
    ids: dict[str, ET.Element] = {}
    for element in root.iter():
        if element.get("id") is not None:
            if element.get("id") in ids:
                errors.append(f"id {element.get('id')} is used twice")
            ids[element.get("id")] = element
    parent = {child: element for element in root.iter() for child in element}
    for element in root.iter():
        tag = element.tag.removeprefix(SCXML)
        for attribute in ("target", "initial"):
            for ref in (element.get(attribute) or "").split():
                if ref not in ids:
                    errors.append(f"<{tag}> {attribute}={ref!r} names no state")
        if tag in ("state", "parallel", "final") and element.get("initial"):
            if parent.get(ids.get(element.get("initial"))) is not element:
                errors.append(f"<{tag} id={element.get('id')!r}> has an initial state that is not its child")
    for element in root.iter(SCXML + "transition"):
        source = parent.get(element)
        # type="internal" with a target: the target lies below the source (else SCXML takes it
        # as an external transition, and the export meant something else).
        if element.get("type") == "internal" and element.get("target"):
            target = ids.get(element.get("target"))
            below = target is not None and any(node is target for node in source.iter() if node is not source)
            if not below:
                errors.append(f"internal transition of {source.get('id')!r} targets {element.get('target')!r}, not a descendant")
        # done.state.X names a state.
        for descriptor in (element.get("event") or "").split():
            if descriptor.startswith("done.state.") and descriptor.removeprefix("done.state.") not in ids:
                errors.append(f"event {descriptor!r} names no state")
    if root.get("initial") not in ids:
        errors.append("<scxml> has no initial state")
    return errors


def check_dot(path: Path, dot: str) -> list[str]:
    run = subprocess.run([dot, "-Tsvg", str(path)], capture_output=True, text=True)
    errors = []
    if run.returncode != 0:
        errors.append(f"dot exited with {run.returncode}")
    if run.stderr.strip():
        errors.append("dot said: " + run.stderr.strip())
    if "<svg" not in run.stdout:
        errors.append("dot wrote no SVG")
    return errors


def main() -> int:
    if len(sys.argv) != 3 or sys.argv[1] not in ("scxml", "dot"):
        print(__doc__, file=sys.stderr)
        return 2
    kind, directory = sys.argv[1], Path(sys.argv[2])
    files = sorted(directory.glob(f"*.{kind}"))
    if not files:
        print(f"no .{kind} files in {directory}", file=sys.stderr)
        return 1
    if kind == "dot":
        dot = shutil.which("dot")
        if dot is None:
            print("Graphviz's dot is not installed (Debian package graphviz): skipped")
            return SKIPPED
    failed = 0
    for path in files:
        errors = check_scxml(path) if kind == "scxml" else check_dot(path, dot)
        for error in errors:
            print(f"{path.name}: {error}", file=sys.stderr)
        failed += 1 if errors else 0
    print(f"{len(files)} .{kind} files checked, {failed} with errors")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
