#!/usr/bin/env python3
"""Runs the ```python blocks of a Markdown file (docs/python.md) in order, in
one namespace, as a reader would paste them, so the worked study cannot
drift: a block that raises fails the test, and a ```text block right after a
python block is what that block must print, line for line.

    run_doc_blocks.py DOC.md WORKDIR

WORKDIR is emptied and made the working directory, with `models` linked to
the repository's models/ (the study is written as run from the repository's
top, with PYTHONPATH=build/python).
"""

import contextlib
import io
import os
import re
import shutil
import sys


def blocks(text):
    """[(language, code)] of the fenced blocks, in order."""
    return [(m.group(1), m.group(2)) for m in re.finditer(r"^```(\w*)\n(.*?)^```\s*$", text, re.S | re.M)]


def main():
    doc, workdir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    repo = os.path.dirname(os.path.dirname(doc))
    with open(doc) as f:
        found = blocks(f.read())
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    os.symlink(os.path.join(repo, "models"), os.path.join(workdir, "models"))
    os.chdir(workdir)
    namespace = {"__name__": "__main__"}
    ran = 0
    for i, (lang, code) in enumerate(found):
        if lang != "python":
            continue
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            try:
                exec(compile(code, "%s, python block %d" % (doc, ran + 1), "exec"), namespace)
            except BaseException:
                sys.stdout.write(printed.getvalue())
                raise
        ran += 1
        sys.stdout.write(printed.getvalue())
        if i + 1 < len(found) and found[i + 1][0] == "text":
            expected = found[i + 1][1].rstrip("\n").split("\n")
            got = printed.getvalue().rstrip("\n").split("\n")
            if got != expected:
                print("FAIL: python block %d of %s printed something else than the text after it:" % (ran, doc))
                for e, g in zip(expected + [""] * len(got), got + [""] * len(expected)):
                    if e != g:
                        print("  expected: %s\n  printed:  %s" % (e, g))
                return 1
    if ran == 0:
        print("FAIL: no python blocks in %s" % doc)
        return 1
    print("ok: %d python blocks of %s ran and printed what the text says" % (ran, doc))
    return 0


if __name__ == "__main__":
    sys.exit(main())
