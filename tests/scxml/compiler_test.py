#!/usr/bin/env python3
"""scxml.compiler: what bsc-scxml tells its user.

    compiler_test.py BSC_SCXML CXX INCLUDE_DIR WORK_DIR

Each case writes a document, runs the compiler and checks its exit status and message: errors
name the file, the line and the element; a C++ error in an expression points at the document's
line (#line); a finding is a warning with its line, and a chart that does not allow it does
not compile (bsc's check), while one that allows it does.
"""

import os
import re
import subprocess
import sys

COMPILER, CXX, INCLUDE, WORK = sys.argv[1:5]
os.makedirs(WORK, exist_ok=True)
HEAD = '<scxml xmlns="http://www.w3.org/2005/07/scxml" xmlns:bsc="urn:bsc:scxml" version="1.0" datamodel="cpp"'
failures = []


def document(name, text):
    path = os.path.join(WORK, name + ".scxml")
    with open(path, "w") as f:
        f.write(text)
    return path


def compile_document(name, text, *options):
    path = document(name, text)
    header = os.path.join(WORK, name + ".hpp")
    r = subprocess.run([sys.executable, COMPILER, path, "-o", header, *options], capture_output=True, text=True)
    return r, header


def compile_cpp(name, header):
    main = os.path.join(WORK, name + ".cpp")
    with open(main, "w") as f:
        f.write(f'#include "{os.path.basename(header)}"\nint main() {{ {name}::machine m{{{name}::chart}}; '
                f'return m.halted() ? 0 : 1; }}\n')
    return subprocess.run([CXX, "-std=c++20", "-fsyntax-only", "-I", INCLUDE, "-I", WORK, main],
                          capture_output=True, text=True)


def build_and_run(name, source):
    """Builds name_main.cpp with `source` against the headers of WORK and runs it: (the
    compiler's result, the run's result or None if it did not build)."""
    main = os.path.join(WORK, name + "_main.cpp")
    with open(main, "w") as f:
        f.write(source)
    program = os.path.join(WORK, name + "_main")
    c = subprocess.run([CXX, "-std=c++20", "-I", INCLUDE, "-I", WORK, main, "-o", program], capture_output=True,
                       text=True)
    return c, subprocess.run([program]) if c.returncode == 0 else None


def expect(case, condition, detail):
    if not condition:
        failures.append(f"{case}: {detail}")
    print(("ok   " if condition else "FAIL ") + case)


# An unknown target: the file, the line and the element.
r, _ = compile_document("unknown_target", HEAD + ' initial="a">\n<state id="a">\n'
                        '  <transition event="go" target="nowhere"/>\n</state>\n</scxml>\n')
expect("unknown target", r.returncode == 1 and re.search(
    r"unknown_target\.scxml:3: error: <transition> no state has the id 'nowhere'", r.stderr), r.stderr)

# An element bsc does not run.
r, _ = compile_document("invoke", HEAD + '>\n<state id="a">\n  <invoke type="scxml" src="child.scxml"/>\n'
                        '</state>\n</scxml>\n')
expect("unsupported element", r.returncode == 1 and re.search(r"invoke\.scxml:3: error: <invoke> is not supported",
                                                               r.stderr), r.stderr)

# A document that is not XML.
r, _ = compile_document("not_xml", HEAD + '>\n<state id="a">\n</scxml>\n')
expect("malformed XML", r.returncode == 1 and re.match(r"\S*not_xml\.scxml:3: error: not well-formed", r.stderr),
       r.stderr)

# Another datamodel than C++.
r, _ = compile_document("ecmascript", HEAD.replace('datamodel="cpp"', 'datamodel="ecmascript"') +
                        '>\n<state id="a"/>\n</scxml>\n')
expect("datamodel", r.returncode == 1 and re.search(r"ecmascript\.scxml:1: error: <scxml> datamodel=\"ecmascript\"",
                                                     r.stderr), r.stderr)

# A C++ error in a cond points at the document's line, and the header's own lines stay its own.
r, header = compile_document("bad_cond", HEAD + ' initial="a">\n<datamodel><data id="n" expr="0"/></datamodel>\n'
                             '<state id="a">\n  <transition event="go" cond="n +* 2 )" target="b"/>\n</state>\n'
                             '<final id="b"/>\n</scxml>\n')
expect("bad cond compiles to a header", r.returncode == 0, r.stderr)
c = compile_cpp("bad_cond", header)
expect("C++ error at the SCXML line", c.returncode != 0 and re.search(r"bad_cond\.scxml:4:", c.stderr), c.stderr[:2000])

# A state never entered: a warning with its line; bsc's check rejects the chart unless allowed.
never = HEAD + '{allow} initial="a">\n<state id="a">\n  <transition event="go" target="b"/>\n</state>\n' \
               '<state id="lost">\n  <transition event="go" target="b"/>\n</state>\n<final id="b"/>\n</scxml>\n'
r, header = compile_document("never", never.format(allow=""))
expect("finding warned", r.returncode == 0 and re.search(
    r"never\.scxml:5: warning: <state> state 'lost' is never entered \(not allowed", r.stderr), r.stderr)
c = compile_cpp("never", header)
expect("finding not allowed: bsc's check", c.returncode != 0 and "unreachable" in c.stderr, c.stderr[:2000])
r, header = compile_document("never", never.format(allow=' bsc:allow="unreachable_state"'))
expect("finding allowed in the document", r.returncode == 0 and "(allowed)" in r.stderr, r.stderr)
with open(header) as f:
    expect("allowance shown in the header", "bsc::allow<bsc::error::unreachable_state>" in f.read(), "no allow")
c = compile_cpp("never", header)
expect("finding allowed: compiles", c.returncode == 0, c.stderr[:2000])

# An allowance that is no finding.
r, _ = compile_document("bad_allow", never.format(allow=' bsc:allow="duplicate_state"'))
expect("bad allowance", r.returncode == 1 and "not a finding a chart may allow" in r.stderr, r.stderr)

# Hooks: the application's functions, which the document calls through the datamodel's member
# `hooks` (bsc:hooks, bsc:include); the application reaches the machine's hooks through the
# datamodel it starts the machine with.
with open(os.path.join(WORK, "panel_hooks.hpp"), "w") as f:
    f.write("#pragma once\nnamespace app {\nstruct panel { bool obstacle = false; int motor_runs = 0; };\n"
            "struct hooks {\n    panel* p = nullptr;\n    bool clear() const { return !p->obstacle; }\n"
            "    void run_motor() { ++p->motor_runs; }\n};\n}  // namespace app\n")
r, header = compile_document("hooked", HEAD + ' bsc:hooks="app::hooks" bsc:include="panel_hooks.hpp" initial="closed">\n'
                             '<state id="closed">\n  <transition event="open" cond="hooks.clear()" target="opened"/>\n'
                             '</state>\n<state id="opened">\n  <onentry><script>hooks.run_motor();</script></onentry>\n'
                             '  <transition event="close" target="closed"/>\n</state>\n</scxml>\n')
expect("hooks compile", r.returncode == 0, r.stderr)
c, run = build_and_run("hooked", '#include "hooked.hpp"\nint main() {\n    app::panel panel{true, 0};\n    hooked::datamodel d;\n'
            '    d.hooks.p = &panel;\n    hooked::machine m{hooked::chart, d};\n'
            '    m.dispatch(hooked::events::open{});  // an obstacle: the guard holds the door\n'
            '    bool ok = m.is<hooked::states::closed>();\n    panel.obstacle = false;\n'
            '    m.dispatch(hooked::events::open{});\n'
                      '    return ok && m.is<hooked::states::opened>() && panel.motor_runs == 1 ? 0 : 1;\n}\n')
expect("hooks called", run is not None and run.returncode == 0, c.stderr[:2000])

# What a document means survives the compiler: a cond with || is evaluated whole (C++'s
# precedence), an <onexit> reads the event being taken in _event, and a state may have the id
# that the root's name has.
r, header = compile_document("meaning", HEAD + ' name="door" initial="door" bsc:allow="dead_end_state">\n'
                             '<datamodel><data id="n" expr="0"/><data id="seen"/></datamodel>\n'
                             '<state id="door">\n  <state id="a">\n'
                             '    <onexit><assign location="seen" expr="_event.name"/></onexit>\n'
                             '    <transition event="go" cond="n == 0 || n == 1 &amp;&amp; n &gt; 5" target="b"/>\n'
                             '  </state>\n  <state id="b"/>\n</state>\n</scxml>\n')
expect("meaning compiles", r.returncode == 0, r.stderr)
c, run = build_and_run("meaning", '#include "meaning.hpp"\nint main() {\n    meaning::machine m{meaning::chart};\n'
            '    m.dispatch(meaning::events::go{});\n'
                      '    return m.is<meaning::states::b>() && m.context().seen == "go" ? 0 : 1;\n}\n')
expect("|| in a cond, _event in <onexit>, a state named as the root", run is not None and run.returncode == 0,
       c.stderr[:2000])

if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
