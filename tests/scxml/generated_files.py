"""What the generators of tests/scxml share: a file is written only when its text changes, so
that a build does not redo what depends on it."""

import os


def write_if_changed(path, text):
    if os.path.exists(path):
        with open(path) as f:
            if f.read() == text:
                return
    with open(path, "w") as f:
        f.write(text)
