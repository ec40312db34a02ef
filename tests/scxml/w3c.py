#!/usr/bin/env python3
"""The W3C SCXML 1.0 IRP suite, run on bsc.

    w3c.py generate IRP_DIR OUT_DIR   transforms each mandatory automatic test that applies to
                                      bsc into an SCXML document with the C++ datamodel, compiles
                                      it with tools/bsc-scxml, and writes the translation units
                                      that run them (a few tests each) and their list
    w3c.py table IRP_DIR              the table of docs/scxml.md: every mandatory automatic test,
                                      what it checks, and whether it runs or why it does not
    w3c.py doc IRP_DIR PAGE [--check] writes that table into PAGE between its markers (or checks
                                      that PAGE holds it)

The transformation of the suite's datamodel-neutral `conf:` vocabulary into C++ is this
project's own, modelled on the W3C's confEcma.xsl: `conf:idVal="1=0"` becomes `cond="Var1 == 0"`,
`conf:illegalExpr` an expression that throws bsc::scxml::execution_error, and so on. The suite
itself is read where it lies (its README: it is not copied).
"""

import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generated_files import write_if_changed  # noqa: E402
import xml.etree.ElementTree as ET

SCXML = "http://www.w3.org/2005/07/scxml"
CONF = "http://www.w3.org/2005/scxml-conformance"
HERE = os.path.dirname(os.path.abspath(__file__))
COMPILER = os.path.join(HERE, "..", "..", "tools", "bsc-scxml")
TESTS_PER_UNIT = 12

# The reasons a mandatory automatic test does not apply to bsc: a short fixed list.
INVOKE = "needs <invoke> (another session run by this one)"
IO_PROCESSOR = "needs an external event I/O processor or its system variables"
ECMASCRIPT = "needs ECMAScript"
# Tests that do not apply for another reason than <invoke> (which reason_not_applicable finds in
# the document): none today; IO_PROCESSOR and ECMASCRIPT are the reasons such a test would give.
NOT_APPLICABLE = {}

# What the tests of each section of the specification check, in this project's words.
SECTIONS = {
    "3.2": "<scxml>: the initial configuration",
    "3.3": "<state>: default initial states",
    "3.7": "<final>: done events",
    "3.8": "<onentry>: order and blocks",
    "3.9": "<onexit>: order and blocks",
    "3.10": "<history>: default and restored configurations",
    "3.12": "events: names, descriptors, error events",
    "3.13": "selecting and executing transitions",
    "4.2": "<raise>: the internal queue",
    "4.3": "<if>/<elseif>/<else>",
    "4.6": "<foreach>",
    "4.9": "errors in executable content",
    "5.3": "<data>: initial values, binding",
    "5.4": "<assign>",
    "5.5": "<donedata>",
    "5.6": "<content>",
    "5.7": "<param>",
    "5.8": "<script>",
    "5.9": "expressions: conditions, locations",
    "5.10": "system variables: _event, _sessionid, _name, _ioprocessors",
    "6.2": "<send>: targets, delays, ids, data",
    "6.3": "<cancel>",
    "6.4": "<invoke>",
    "C.1": "the null datamodel: In()",
    "D.1": "the SCXML event I/O processor: targets, origin, queues",
}


def cond_of(spec, op_map, left, right):
    m = re.fullmatch(r"([0-9]+)([=<>]=?)(.*)", spec)
    if not m:
        raise ValueError(spec)
    op = {"=": "=="}.get(m.group(2), m.group(2))
    return f"{left(m.group(1))} {op} {right(m.group(3))}"


def quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def var(n):
    return f"Var{n}"


# conf: attributes: name -> function(value) -> (attribute, value) or None
ATTRIBUTES = {
    "datamodel": lambda v: ("datamodel", "cpp"),
    "targetpass": lambda v: ("target", "pass"),
    "targetfail": lambda v: ("target", "fail"),
    "id": lambda v: ("id", var(v)),
    "name": lambda v: ("name", var(v)),
    "location": lambda v: ("location", var(v)),
    "invalidLocation": lambda v: ("location", "bsc::scxml::invalid_location()"),
    "systemVarLocation": lambda v: ("location", v),
    "expr": lambda v: ("expr", quoted(v[1:-1]) if re.fullmatch(r"'[^']*'", v) else v if v.strip()
                       else "bsc::scxml::value()"),
    "targetVar": lambda v: ("targetexpr", var(v)),
    "quoteExpr": lambda v: ("expr", quoted(v)),
    "varExpr": lambda v: ("expr", var(v)),
    "varChildExpr": lambda v: ("expr", var(v)),
    "systemVarExpr": lambda v: ("expr", v),
    "illegalExpr": lambda v: ("expr", "bsc::scxml::invalid_expression()"),
    "illegalTarget": lambda v: ("target", "baz"),
    "unreachableTarget": lambda v: ("target", "#_scxml_foo"),
    "invalidSessionID": lambda v: ("expr", "27"),
    "invalidSendType": lambda v: ("type", "27"),
    "invalidSendTypeExpr": lambda v: ("expr", "27"),
    "eventName": lambda v: ("expr", "_event.name"),
    "eventType": lambda v: ("expr", "_event.type"),
    "eventSendid": lambda v: ("expr", "_event.sendid"),
    "eventField": lambda v: ("expr", f"_event.{v}"),
    "eventDataFieldValue": lambda v: ("expr", f"_event.data[{quoted(v)}]"),
    "eventDataParamValue": lambda v: ("expr", f"_event.data[{quoted(v)}]"),
    "eventDataNamelistValue": lambda v: ("expr", f"_event.data[{quoted(var(v))}]"),
    "scxmlEventIOLocation": lambda v: (
        "expr", '_ioprocessors["http://www.w3.org/TR/scxml/#SCXMLEventProcessor"]["location"]'),
    "eventExpr": lambda v: ("eventexpr", var(v)),
    "targetExpr": lambda v: ("targetexpr", var(v)),
    "typeExpr": lambda v: ("typeexpr", var(v)),
    "delayFromVar": lambda v: ("delayexpr", var(v)),
    "delay": lambda v: ("delay", f"{v}s"),
    "idlocation": lambda v: ("idlocation", var(v)),
    "sendIDExpr": lambda v: ("sendidexpr", var(v)),
    "srcExpr": lambda v: ("srcexpr", var(v)),
    "namelist": lambda v: ("namelist", var(v)),
    "invalidNamelist": lambda v: ("namelist", '"foo'),
    "idVal": lambda v: ("cond", cond_of(v, None, var, lambda r: r)),
    "varIdVal": lambda v: ("cond", cond_of(v, None, var, var)),
    "namelistIdVal": lambda v: ("cond", cond_of(v, None, var, lambda r: r)),
    "VarEqVar": lambda v: ("cond", "{} == {}".format(*[var(x) for x in re.findall(r"[0-9]+", v)])),
    "VarEqVarStruct": lambda v: ("cond", "{} == {}".format(*[var(x) for x in re.findall(r"[0-9]+", v)])),
    "idQuoteVal": lambda v: ("cond", cond_of(v, None, var, quoted)),
    "compareIDVal": lambda v: ("cond", cond_of(v, None, var, var)),
    "idSomeVal": lambda v: ("cond", f"{var(v)} == 123"),
    "eventNameVal": lambda v: ("cond", f"_event.name == {quoted(v)}"),
    "eventvarVal": lambda v: ("cond", cond_of(v, None, lambda n: f"_event.data[{quoted(var(n))}]", lambda r: r)),
    "idSystemVarVal": lambda v: ("cond", cond_of(v, None, var, lambda r: r)),
    "eventdataVal": lambda v: ("cond", "_event.data == " + (quoted(v[1:-1]) if v.startswith("'") else v)),
    "eventdataSomeVal": lambda v: ("cond", "_event.data == 123"),
    "emptyEventData": lambda v: ("cond", "_event.data.is_undefined()"),
    "nameVarVal": lambda v: ("cond", f"_name == {quoted(v)}"),
    "varPrefix": lambda v: ("cond", "bsc::scxml::starts_with({1}, {0})".format(*[var(x) for x in v.split()])),
    "inState": lambda v: ("cond", f"In('{v}')"),
    "nonBoolean": lambda v: ("cond", "bsc::scxml::invalid_expression()"),
    "isBound": lambda v: ("cond", f"!{var(v)}.is_undefined()"),
    "unboundVar": lambda v: ("cond", f"{var(v)}.is_undefined()"),
    "systemVarIsBound": lambda v: ("cond", f"!{v}.is_undefined()"),
    "noValue": lambda v: ("cond", f"!static_cast<bool>({var(v)})"),
    "true": lambda v: ("cond", "true"),
    "false": lambda v: ("cond", "false"),
    # The C++ datamodel's _event has every field SCXML names: that it compiles is the test.
    "eventFieldsAreBound": lambda v: ("cond", "bsc::scxml::has_event_fields(_event)"),
    "eventFieldHasNoValue": lambda v: ("cond", f"_event.{v}.is_undefined()"),
    "originTypeEq": lambda v: ("cond", f"_event.origintype == {quoted(v)}"),
    "arrayVar": lambda v: ("array", var(v)),
    "arrayTextVar": lambda v: ("array", var(v)),
    "illegalArray": lambda v: ("expr", "7"),
    "item": lambda v: ("item", var(v)),
    "illegalItem": lambda v: ("item", "bsc::scxml::invalid_location()"),
    "index": lambda v: ("index", var(v)),
}


def element(tag, **attrs):
    e = ET.Element(f"{{{SCXML}}}{tag}")
    for k, v in attrs.items():
        e.set(k, v)
    return e


def assign(location, expr):
    return element("assign", location=location, expr=expr)


def transform_element(e, declared):
    """The replacement of a conf: element (a list of elements, or a text)."""
    tag = e.tag.split("}")[1]
    if tag == "pass":
        return [element("final", id="pass")]
    if tag == "fail":
        return [element("final", id="fail")]
    if tag == "incrementID":
        return [assign(var(e.get("id")), f"{var(e.get('id'))} + 1")]
    if tag in ("concatVars", "sumVars"):
        a, b = var(e.get("id1")), var(e.get("id2"))
        return [assign(a, f"{a} + {b}")]
    if tag == "extendArray":
        v = var(e.get("id"))
        return [assign(v, f"bsc::scxml::appended({v}, 4)")]
    if tag == "contentFoo":
        c = element("content")
        c.text = "foo"
        return [c]
    if tag == "someInlineVal":
        return "123"
    if tag == "array123":
        return "[1,2,3]"
    if tag == "script":
        # ECMAScript's `var Var1 = 1` creates the variable; C++ declares it in the datamodel.
        declared.add("Var1")
        s = element("script")
        s.text = "Var1 = 1;"
        return [s]
    if tag == "sendToSender":
        return [element("send", event=e.get("name"), targetexpr="_event.origin", typeexpr="_event.origintype")]
    raise KeyError(f"conf:{tag}")


def transform(tree_root):
    declared = set()

    def walk(e):
        # attributes
        for key in list(e.attrib):
            if key.startswith(f"{{{CONF}}}"):
                name = key.split("}")[1]
                value = e.attrib.pop(key)
                if name not in ATTRIBUTES:
                    raise KeyError(f"conf:{name}")
                attr, text = ATTRIBUTES[name](value)
                e.set(attr, text)
        # children
        out = []
        for c in list(e):
            if isinstance(c.tag, str) and c.tag.startswith(f"{{{CONF}}}"):
                r = transform_element(c, declared)
                if isinstance(r, str):
                    e.text = (e.text or "") + r
                else:
                    for x in r:
                        x.tail = c.tail
                        walk(x)
                    out += r
            else:
                walk(c)
                out.append(c)
        for c in list(e):
            e.remove(c)
        for c in out:
            e.append(c)

    walk(tree_root)
    # A string literal written in ECMAScript's quotes, in the suite's plain expr attributes.
    for e in tree_root.iter():
        if re.fullmatch(r"'[^']*'", e.get("expr") or ""):
            e.set("expr", quoted(e.get("expr")[1:-1]))
    # ECMAScript creates a variable that an <assign> names; C++ declares it in the datamodel.
    for e in tree_root.iter():
        for attr in ("location", "item", "index"):
            if re.fullmatch(r"Var[0-9]+", e.get(attr) or ""):
                declared.add(e.get(attr))
    have_data = {d.get("id") for d in tree_root.iter(f"{{{SCXML}}}data")}
    declared -= have_data
    if declared:
        dm = tree_root.find(f"{{{SCXML}}}datamodel")
        if dm is None:
            dm = element("datamodel")
            tree_root.insert(0, dm)
        have = {d.get("id") for d in dm}
        for name in sorted(declared - have):
            dm.append(element("data", id=name))
    tree_root.set("datamodel", "cpp")


def reason_not_applicable(irp, tid, uris):
    """Why a test does not apply to bsc (None: it runs): a test with <invoke> needs it; the others
    are listed in NOT_APPLICABLE."""
    for uri in uris:
        with open(os.path.join(irp, "txml", os.path.basename(uri))) as f:
            if "<invoke" in f.read():
                return INVOKE
    return NOT_APPLICABLE.get(tid)


def mandatory_tests(irp):
    manifest = ET.parse(os.path.join(irp, "manifest.xml")).getroot()
    out = []
    for a in manifest.iter("assert"):
        text = " ".join((a.text or "").split())
        for t in a.iter("test"):
            if t.get("conformance") == "mandatory" and t.get("manual") == "false":
                out.append((t.get("id"), [s.get("uri") for s in t.iter("start")], a.get("specnum"), text))
    return out


def generate(irp, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    ET.register_namespace("", SCXML)
    runnable = []
    for tid, uris, _spec, _text in mandatory_tests(irp):
        if reason_not_applicable(irp, tid, uris):
            continue
        for uri in uris:
            # A test of several documents (403a, 403b, 403c) passes when each does.
            name = os.path.splitext(os.path.basename(uri))[0][len("test"):]
            compile_document(irp, uri, name, out_dir)
            runnable.append(name)
    units = [runnable[i:i + TESTS_PER_UNIT] for i in range(0, len(runnable), TESTS_PER_UNIT)]
    names = []
    for k, unit in enumerate(units):
        name = f"w3c_unit_{k}.cpp"
        lines = ['#include "w3c_runner.hpp"', ""]
        lines += [f'#include "test{t}.hpp"' for t in unit]
        lines += ["", f"void register_unit_{k}(bsc_w3c::registry& tests) {{"]
        lines += [f'    tests.add<w3c{t}::machine, bsc::table::machine<bsc::chart_ref<w3c{t}::chart>, '
                  f'bsc::scxml::policy>, w3c{t}::chart>("{t}");' for t in unit]
        lines += ["}"]
        write_if_changed(os.path.join(out_dir, name), "\n".join(lines) + "\n")
        names.append(name)
    main = ['#include "w3c_runner.hpp"', ""]
    main += [f"void register_unit_{k}(bsc_w3c::registry&);" for k in range(len(units))]
    main += ["", "int main(int argc, char** argv) {", "    bsc_w3c::registry tests;"]
    main += [f"    register_unit_{k}(tests);" for k in range(len(units))]
    main += ["    return tests.run(argc, argv);", "}"]
    write_if_changed(os.path.join(out_dir, "w3c_main.cpp"), "\n".join(main) + "\n")
    write_if_changed(os.path.join(out_dir, "units.txt"), "\n".join(names + ["w3c_main.cpp"]) + "\n")


def compile_document(irp, uri, name, out_dir):
    source = os.path.join(irp, "txml", os.path.basename(uri))
    root = ET.parse(source).getroot()
    transform(root)
    document = os.path.join(out_dir, f"test{name}.scxml")
    ET.ElementTree(root).write(document, encoding="utf-8", xml_declaration=True)
    # Files the test reads (src=) lie beside the document.
    for d in root.iter(f"{{{SCXML}}}data"):
        if d.get("src"):
            file = os.path.basename(d.get("src").removeprefix("file:"))
            with open(os.path.join(irp, "txml", file)) as f_in:
                write_if_changed(os.path.join(out_dir, file), f_in.read())
    header = os.path.join(out_dir, f"test{name}.hpp")
    # SCXML's leniency, in the open: the findings SCXML accepts are allowed.
    allow = ("unreachable_state,dead_end_state,shadowed_transition,dead_transition,conflicting_transitions,"
             "done_never_raised,eventless_livelock")
    r = subprocess.run([sys.executable, COMPILER, document, "-o", header, "--namespace", f"w3c{name}",
                        "--allow", allow], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"test {name}: bsc-scxml failed:\n{r.stderr}")


BEGIN = "<!-- w3c table: begin -->"
END = "<!-- w3c table: end -->"


def document_page(irp, page, check):
    """Writes the table between the markers of `page` (docs/scxml.md), or with check, fails if
    the page does not hold what would be written."""
    import contextlib
    import io
    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        table(irp)
    with open(page) as f:
        text = f.read()
    if BEGIN not in text or END not in text:
        raise SystemExit(f"{page}: the markers {BEGIN} and {END} are missing")
    head, rest = text.split(BEGIN, 1)
    _old, tail = rest.split(END, 1)
    new = head + BEGIN + "\n" + buffer.getvalue() + END + tail
    if check:
        if new != text:
            raise SystemExit(f"{page}: the W3C table is not what tests/scxml/w3c.py writes; run "
                             f"python3 tests/scxml/w3c.py doc {irp} {page}")
        return
    with open(page, "w") as f:
        f.write(new)


def table(irp):
    rows = ["| test | what it checks (section of the specification) | on bsc |", "| --- | --- | --- |"]
    runs = 0
    tests = mandatory_tests(irp)
    for tid, uris, spec, _text in tests:
        reason = reason_not_applicable(irp, tid, uris)
        if reason is None:
            runs += 1
        documents = f" ({len(uris)} documents)" if len(uris) > 1 else ""
        rows.append(f"| {tid}{documents} | {spec} {SECTIONS.get(spec, '')} | "
                    f"{'passes' if reason is None else 'not applicable: ' + reason} |")
    print(f"{runs} of the {len(tests)} mandatory automatic tests apply to bsc, and pass on both back ends; "
          f"{len(tests) - runs} do not apply.\n")
    print("\n".join(rows))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "generate":
        generate(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == "table":
        table(sys.argv[2])
    elif len(sys.argv) in (4, 5) and sys.argv[1] == "doc":
        document_page(sys.argv[2], sys.argv[3], check=sys.argv[4:] == ["--check"])
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
