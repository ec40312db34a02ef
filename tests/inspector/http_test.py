#!/usr/bin/env python3
"""The inspector's server without a browser: `mcs --inspect 0` serves the page, the trace and the
commands on 127.0.0.1 as docs/inspector.md says, refuses what it must, and the program's own
output records what the page did.

    http_test.py --program build/.../mcs [--commands]

Without --commands the program must refuse every command (read-only). Bounded in time; the
program is stopped (end of its input, then a kill) whatever happens.
"""

import argparse
import os
import re
import subprocess
import sys
import time
import urllib.error
import urllib.request

DEADLINE = 30  # seconds for the whole test


def request(url, body=None, origin=None, as_page=True):
    """As the page's script asks: a command with the X-Bsc-Command header (as_page)."""
    headers = {"Origin": origin} if origin else {}
    if body is not None and as_page:
        headers["X-Bsc-Command"] = "1"
    req = urllib.request.Request(url, data=body.encode() if body is not None else None, headers=headers)
    try:
        with urllib.request.urlopen(req, timeout=5) as r:
            return r.status, dict(r.headers), r.read()
    except urllib.error.HTTPError as e:
        return e.code, dict(e.headers), e.read()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--program", required=True)
    parser.add_argument("--commands", action="store_true")
    args = parser.parse_args()
    command = [args.program, "--inspect", "0"] + (["--commands"] if args.commands else [])
    program = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True)
    failures = []
    checks = 0

    def check(condition, what):
        nonlocal checks
        checks += 1
        if not condition:
            failures.append(what)

    output = []
    try:
        start = time.monotonic()
        url = None
        while url is None and time.monotonic() - start < DEADLINE:
            line = program.stdout.readline()
            if not line:
                break
            output.append(line)
            found = re.search(r"inspect: (http://127\.0\.0\.1:\d+/)", line)
            if found:
                url = found.group(1)
        if url is None:
            print("http_test: the program printed no address:\n" + "".join(output), file=sys.stderr)
            return 1

        status, headers, body = request(url + "info")
        check(status == 200 and b'"chart": "MCS"' in body, f"/info: {status} {body!r}")
        check((b'"commands": true' in body) == args.commands, f"/info commands: {body!r}")

        status, headers, trace = request(url + "trace?from=0")
        check(status == 200 and trace[:1] == b"\xb5" and trace[1:2] == b"\x01", "/trace starts with a hello frame")
        check(headers.get("X-Trace-End") == str(len(trace)), f"X-Trace-End {headers.get('X-Trace-End')} != {len(trace)}")
        status, headers, rest = request(url + f"trace?from={len(trace)}")
        check(status == 200 and rest == b"", "/trace from its end is empty")

        status, _, _ = request(url + "index.html/../../etc/passwd")
        check(status == 404, f"a path outside the page's folder: {status}")
        status, _, _ = request(url + ".hidden")
        check(status == 404, f"a hidden file: {status}")

        status, _, body = request(url + "command", "dispatch ON_P")
        if args.commands:
            check(status == 200 and body == b"ok ON_P: consumed", f"dispatch ON_P: {status} {body!r}")
            status, _, body = request(url + "command", "dispatch ON_P")
            check(status == 200 and body == b"ok ON_P: ignored", f"ON_P again: {status} {body!r}")
            status, _, body = request(url + "command", "dispatch NOPE")
            check(status == 400 and b"no event of this chart is named 'NOPE'" in body, f"NOPE: {status} {body!r}")
            status, _, body = request(url + "command", "dispatch ESTOP_P", origin="http://example.com")
            check(status == 403 and b"another origin" in body, f"another origin: {status} {body!r}")
            status, _, body = request(url + "command", "dispatch ESTOP_P", as_page=False)
            check(status == 403, f"a command without the page's header: {status} {body!r}")
            status, _, body = request(url + "command", "set error 1")
            check(status == 400 and b"not an input channel" in body, f"set a non-input: {status} {body!r}")
            status, _, body = request(url + "command", "step")
            check(status == 409, f"step without stepping: {status} {body!r}")
            status, _, body = request(url + "command", "dance")
            check(status == 400 and body.startswith(b"commands:"), f"unknown command: {status} {body!r}")
            status, headers, more = request(url + f"trace?from={len(trace)}")
            check(b"\xb5\x10" in more, "the dispatch is in the trace after the command")
        else:
            check(status == 403 and b"read-only" in body, f"a command to a read-only view: {status} {body!r}")

        # A line on standard input still pushes a button, beside the page.
        program.stdin.write("mdi_p\nquit\n")
        program.stdin.flush()
        rest, _ = program.communicate(timeout=DEADLINE)
        output.append(rest)
        text = "".join(output)
        check(program.returncode == 0, f"exit status {program.returncode}")
        if args.commands:
            check(re.search(r"page: dispatch ON_P +-> MCS On Auto Mem .*\(ok ON_P: consumed\)", text) is not None,
                  "the program's output records the page's push")
            check(re.search(r"MDI_P +-> MCS On Auto Mdi", text) is not None, "the line read from input pushed MDI_P")
        else:
            check(re.search(r"MDI_P +-> MCS Off .*ignored", text) is not None, "MDI_P from input, ignored while Off")
    finally:
        if program.poll() is None:
            program.kill()
            program.wait()
    for f in failures:
        print("FAILED: " + f, file=sys.stderr)
    if failures:
        print("".join(output), file=sys.stderr)
        return 1
    print(f"inspector http: {checks} checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
