#!/usr/bin/env python3
"""The code samples of the documentation, as translation units (tests/doc_samples.cmake).

  doc_samples.py extract ROOT PAGE PREFIX OUTDIR
      writes OUTDIR/<name>.cpp for the ```cpp blocks of ROOT/PAGE and OUTDIR/<PREFIX>.cmake,
      which declares their targets and tests (run by CMake at configure time)
  doc_samples.py check ROOT PAGE...
      fails if a page of ROOT (README.md, docs/**/*.md) has a C++ block that none of the PAGEs
      covers: a ```cpp block on a page that is not listed, a C++ block fenced as ```c++ (or
      cxx, cc, hpp, h), an unlabelled block that looks like C++, or a malformed marker
      (ctest doc.samples_covered)

Every ```cpp block of a listed page is compiled. By default a block is a complete program: it
is compiled, linked and run, and must exit with status 0. An HTML comment on the line just
before the fence says otherwise (the syntax is documented in tests/doc_samples.cmake):

  <!-- sample: prelude -->        the block is put before every later block of the page
  <!-- sample: in NAME -->        the block is pasted into tests/doc_samples/NAME.cpp.in
  <!-- sample: fails defect=TYPE -->
                                 the block shows an error and its fix, marked line by line;
                                 the error is a defect of tests/defects/catalogue.py, whose
                                 regex it must match (`fails defect=dead_end_state<cf::Stuck>`)
  <!-- sample: fails REGEX -->    the same, for a diagnostic that is no check's message
  <!-- sample: in NAME; fails defect=TYPE -->
"""

import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "defects"))
import catalogue  # noqa: E402

FENCE = re.compile(r"^```(?P<info>[^\n`]*)\n(?P<code>.*?)^```[ \t]*$", re.S | re.M)
MARKER = re.compile(r"^<!-- sample: (?P<options>.*?) -->$")
CPP_INFOS = {"cpp", "c++", "cxx", "cc", "hpp", "h++", "h", "c"}
ERROR_LINE = re.compile(r"//\s*Error\b")
FIX_LINE = re.compile(r"//\s*Fix\b")
NUMBERED = re.compile(r"@SAMPLE_(\d+)@")


class SampleError(Exception):
    pass


def blocks(text):
    """(info, code, first line of the code, marker options or None) for each fenced block."""
    for m in FENCE.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        before = text[: m.start()].rstrip("\n").rsplit("\n", 1)[-1] if m.start() else ""
        marker = MARKER.match(before)
        yield m.group("info").strip(), m.group("code"), line + 1, marker.group("options") if marker else None


def parse_options(options, page, line):
    """The options of a marker: {'prelude': True} or {'in': NAME, 'fails': REGEX}, where
    `fails defect=TYPE` gives the catalogue's regex for TYPE."""
    result = {}
    for part in (p.strip() for p in options.split(";")):
        word, _, value = part.partition(" ")
        value = value.strip()
        if word == "prelude" and not value:
            result["prelude"] = True
        elif word == "in" and re.fullmatch(r"[\w-]+", value):
            result["in"] = value
        elif word == "fails" and value.startswith("defect="):
            try:
                result["fails"] = catalogue.regex(value[len("defect="):])
            except catalogue.CatalogueError as e:
                raise SampleError(f"{page}:{line - 2}: {e}") from None
        elif word == "fails" and value:
            result["fails"] = value
        else:
            raise SampleError(f"{page}:{line - 2}: unknown sample option `{part}` "
                              "(expected `prelude`, `in NAME`, `fails defect=TYPE` or `fails REGEX`)")
    if "prelude" in result and len(result) > 1:
        raise SampleError(f"{page}:{line - 2}: a prelude takes no other option")
    return result


def located(code, page, line):
    """The code with a #line directive, so that diagnostics name the page and its line."""
    return f'#line {line} "{page}"\n{code}'


def variant(code, drop):
    """The code without the lines that `drop` matches (kept blank, so lines still match the page)."""
    return "".join("\n" if drop.search(l) else l for l in code.splitlines(keepends=True))


def write_if_changed(path, text):
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def extract(root, page, prefix, outdir):
    root, outdir = Path(root), Path(outdir)
    text = (root / page).read_text()
    outdir.mkdir(parents=True, exist_ok=True)
    wrappers_dir = root / "tests" / "doc_samples"

    prelude = ""
    programs = []  # (name, code)
    failing = []   # (name, code, regex)
    fixes = {}     # wrapper -> [(index, code)]
    grouped = {}   # wrapper with numbered placeholders -> [(index, code)]
    used_wrappers = set()
    index = 0

    def wrapper_text(name, line):
        path = wrappers_dir / f"{name}.cpp.in"
        if not path.exists():
            raise SampleError(f"{page}:{line - 2}: no wrapper tests/doc_samples/{name}.cpp.in")
        used_wrappers.add(path)
        return path.read_text()

    def wrapped(name, code):
        """The wrapper NAME with its @SAMPLE@ replaced by the code."""
        wrapper = (wrappers_dir / f"{name}.cpp.in").read_text()
        path = f"tests/doc_samples/{name}.cpp.in"
        before, _, after = wrapper.partition("@SAMPLE@\n")
        after_line = before.count("\n") + 2
        return f'#line 1 "{path}"\n{before}{code}#line {after_line} "{path}"\n{after}'

    for info, code, line, options in blocks(text):
        if info != "cpp":
            if options is not None:
                raise SampleError(f"{page}:{line - 2}: a sample marker before a ```{info} block")
            continue
        index += 1
        opts = parse_options(options, page, line) if options is not None else {}
        name = f"{prefix}_{index}"
        if opts.get("prelude"):
            prelude += located(code, page, line)
            continue
        wrapper = opts.get("in")
        if wrapper:
            body = wrapper_text(wrapper, line)
            numbered = set(NUMBERED.findall(body))
            if numbered and "fails" in opts:
                raise SampleError(f"{page}:{line - 2}: a failing sample needs a wrapper with @SAMPLE@")
            if numbered:
                grouped.setdefault(wrapper, []).append((index, located(code, page, line)))
                continue
            if "@SAMPLE@\n" not in body:
                raise SampleError(f"tests/doc_samples/{wrapper}.cpp.in has no @SAMPLE@ line")
        if "fails" in opts:
            if not FIX_LINE.search(code) or not ERROR_LINE.search(code):
                raise SampleError(f"{page}:{line}: a failing sample needs lines marked `// Error` "
                                  "and lines marked `// Fix`")
            error = located(variant(code, FIX_LINE), page, line)
            fix = located(variant(code, ERROR_LINE), page, line)
            failing.append((name, prelude + (wrapped(wrapper, error) if wrapper else error), opts["fails"]))
            fixes.setdefault(wrapper, []).append((index, fix))
            continue
        programs.append((name, prelude + (wrapped(wrapper, located(code, page, line)) if wrapper
                                          else located(code, page, line))))

    # The blocks pasted into one wrapper at numbered placeholders: one program.
    for wrapper, parts in grouped.items():
        body = (wrappers_dir / f"{wrapper}.cpp.in").read_text()
        wanted = sorted(int(n) for n in set(NUMBERED.findall(body)))
        if wanted != list(range(1, len(parts) + 1)):
            raise SampleError(f"tests/doc_samples/{wrapper}.cpp.in has placeholders {wanted}, "
                              f"but {page} has {len(parts)} blocks marked `in {wrapper}`")
        path = f"tests/doc_samples/{wrapper}.cpp.in"
        out = f'#line 1 "{path}"\n'
        for number, wrapper_line in enumerate(body.splitlines(keepends=True), 1):
            m = re.fullmatch(r"@SAMPLE_(\d+)@\n", wrapper_line)
            out += f'{parts[int(m.group(1)) - 1][1]}#line {number + 1} "{path}"\n' if m else wrapper_line
        programs.append(("_".join([prefix] + [str(i) for i, _ in parts]), prelude + out))

    # The fixed versions of the failing blocks: one program per wrapper, each fix in a namespace.
    for wrapper, parts in fixes.items():
        code = "".join(f"namespace sample_{i} {{\n{fix}}}  // namespace sample_{i}\n" for i, fix in parts)
        name = f"{prefix}_fixes" + (f"_{wrapper}" if len(fixes) > 1 and wrapper else "")
        programs.append((name, prelude + (wrapped(wrapper, code) if wrapper else code + "int main() {}\n")))

    if index == 0:
        raise SampleError(f"{page} has no ```cpp sample")

    cmake = [f"# Generated by tests/doc_samples/doc_samples.py from {page}; do not edit."]
    for name, code in programs:
        write_if_changed(outdir / f"{name}.cpp", code)
        cmake.append(f"bsc_doc_sample_program({name} ${{CMAKE_CURRENT_BINARY_DIR}}/doc_samples/{name}.cpp)")
    for name, code, regex in failing:
        write_if_changed(outdir / f"{name}.cpp", code)
        cmake.append(f"bsc_doc_sample_failing({name} ${{CMAKE_CURRENT_BINARY_DIR}}/doc_samples/{name}.cpp "
                     f"[==[{regex}]==])")
    depends = sorted(str(p) for p in used_wrappers)
    cmake.append("set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "
                 + " ".join(f"[==[{d}]==]" for d in depends) + ")" if depends else "")
    write_if_changed(outdir / f"{prefix}.cmake", "\n".join(cmake) + "\n")


def looks_like_cpp(code):
    return "#include" in code or "bsc::" in code


def check(root, pages):
    root = Path(root)
    listed = set(pages)
    problems = []
    for path in sorted([root / "README.md", *root.glob("docs/**/*.md")]):
        page = path.relative_to(root).as_posix()
        for info, code, line, options in blocks(path.read_text()):
            where = f"{page}:{line - 1}"
            if info == "cpp":
                if page not in listed:
                    problems.append(f"{where}: a ```cpp block on a page that tests/doc_samples.cmake does not "
                                    "pass to bsc_add_doc_samples")
                elif options is not None:
                    try:
                        parse_options(options, page, line)
                    except SampleError as e:
                        problems.append(str(e))
            elif info.lower() in CPP_INFOS:
                problems.append(f"{where}: a C++ block fenced as ```{info}: fence it as ```cpp so that "
                                "it is compiled")
            elif not info and looks_like_cpp(code):
                problems.append(f"{where}: an unlabelled block that looks like C++: fence it as ```cpp "
                                "(or ```text if it is not C++)")
            if info != "cpp" and options is not None:
                problems.append(f"{where}: a sample marker before a ```{info} block")
    for page in pages:
        if not (root / page).exists():
            problems.append(f"{page}: listed, but there is no such page")
    for p in problems:
        print(p, file=sys.stderr)
    if not problems:
        print(f"every C++ block of README.md and docs/ is compiled ({len(pages)} pages)")
    return 1 if problems else 0


def main(argv):
    try:
        if len(argv) == 5 and argv[0] == "extract":
            extract(*argv[1:])
            return 0
        if len(argv) >= 2 and argv[0] == "check":
            return check(argv[1], argv[2:])
    except SampleError as e:
        print(f"doc_samples.py: {e}", file=sys.stderr)
        return 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
