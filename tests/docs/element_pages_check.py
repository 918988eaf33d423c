#!/usr/bin/env python3
"""Element reference pages against the element schemas, and the docs' links.

    python3 tests/docs/element_pages_check.py MILLDYN_BINARY SOURCE_DIR

Checks (issue 29 item 7; docs/elements/README.md):
  1. every type of `MILLDYN_BINARY elements --json` has docs/elements/TYPE.md
     with the sections `## Conventions`, `## Outputs` and `## Keys`;
  2. the Keys table (`| key | unit | default | meaning |`) lists exactly the
     schema's keys less the generic ones (type, name, fidelity), each with the
     schema's unit: "[... in UNIT ...]" -> UNIT, "(dimensionless)" -> 1,
     anything else (body names, choices, text, schedules) -> blank;
  3. every relative markdown link in README.md, docs/*.md and
     docs/elements/*.md names an existing file, and its #anchor is a heading
     of the target (GitHub slugs: lowercase, spaces to '-', punctuation other
     than '-' and '_' dropped, unicode letters kept, duplicates -1, -2, ...);
  4. docs/elements/README.md links every element page (and schedules.md).
Exit 0 when all hold, 1 on any difference (each printed with its file and
line), 2 on bad usage or a binary that does not answer.
"""
import glob
import json
import os
import re
import subprocess
import sys
import unicodedata
from urllib.parse import unquote

GENERIC_KEYS = {"type", "name", "fidelity"}


def schema_unit(description):
    """The unit the schema's description states for a key ('' if none)."""
    m = re.search(r"\[([^\[\]]*)\]\s*$", description or "")
    if not m:
        return ""
    bracket = m.group(1)
    if "(dimensionless)" in bracket:
        return "1"
    u = re.search(r"\bin ([^,\]]+)", bracket)
    if u and bracket.lstrip().startswith(("number", "list of numbers")):
        return u.group(1).strip()
    return ""


FENCE = re.compile(r"^\s*(```|~~~)")


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    inside = False
    for i, line in enumerate(text.splitlines(), 1):
        if FENCE.match(line):
            inside = not inside
            continue
        if not inside:
            yield i, line


def slug(heading):
    text = heading.strip().lower()
    # inline markup GitHub drops from the anchor: links keep their text
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"<[^>]+>", "", text)
    out = []
    for ch in text:
        if ch in "-_" or ch == " ":
            out.append("-" if ch == " " else ch)
        elif unicodedata.category(ch)[0] in ("L", "N") or unicodedata.category(ch) == "Mn":
            out.append(ch)
        # everything else (punctuation, symbols) is dropped
    return "".join(out)


def anchors(path, cache={}):
    if path in cache:
        return cache[path]
    with open(path, encoding="utf-8") as f:
        text = f.read()
    seen = {}
    result = set()
    for _, line in prose_lines(text):
        m = re.match(r"^\s{0,3}(#{1,6})\s+(.*?)\s*#*\s*$", line)
        if m:
            base = slug(m.group(2))
            n = seen.get(base, 0)
            result.add(base if n == 0 else "%s-%d" % (base, n))
            seen[base] = n + 1
        for a in re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", line):
            result.add(a)
    cache[path] = result
    return result


LINK = re.compile(r"(?<!\!)\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFDEF = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\"[^\"]*\")?\s*$")


def links(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for n, line in prose_lines(text):
        stripped = re.sub(r"`[^`]*`", "", line)
        targets = [m.group(1) for m in LINK.finditer(stripped)]
        m = REFDEF.match(stripped)
        if m:
            targets.append(m.group(1))
        for t in targets:
            yield n, t


def check_links(source, files, errors):
    for path in files:
        rel = os.path.relpath(path, source)
        for n, target in links(path):
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):  # http:, mailto:, ...
                continue
            file_part, _, anchor = target.partition("#")
            file_part = unquote(file_part)
            if file_part:
                dest = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
            else:
                dest = path
            if not os.path.exists(dest):
                errors.append("%s:%d: link %s: no file %s" % (rel, n, target, os.path.relpath(dest, source)))
                continue
            if anchor and dest.endswith(".md") and os.path.isfile(dest):
                if unquote(anchor).lower() not in anchors(dest):
                    errors.append("%s:%d: link %s: no heading #%s in %s"
                                  % (rel, n, target, anchor, os.path.relpath(dest, source)))


def sections(text):
    return {line.strip() for _, line in prose_lines(text) if line.startswith("## ")}


def keys_table(text):
    """{key: unit} of the table under '## Keys', and the line of each row."""
    rows = {}
    lines = list(prose_lines(text))
    start = None
    for idx, (n, line) in enumerate(lines):
        if line.strip() == "## Keys":
            start = idx + 1
            break
    if start is None:
        return None
    header_seen = False
    for n, line in lines[start:]:
        if line.startswith("## "):
            break
        s = line.strip()
        if not s.startswith("|"):
            if header_seen and rows:
                break
            continue
        cells = [c.strip() for c in s.strip("|").split("|")]
        if not header_seen:
            if [c.lower() for c in cells[:4]] != ["key", "unit", "default", "meaning"]:
                return "bad header: %s" % s
            header_seen = True
            continue
        if set(cells[0]) <= set("-: "):
            continue
        key = cells[0].strip("`")
        unit = cells[1].strip("`") if len(cells) > 1 else ""
        rows.setdefault(key, []).append((n, unit))
    return rows


def main(argv):
    if len(argv) != 3:
        print(__doc__)
        return 2
    binary, source = argv[1], os.path.abspath(argv[2])
    try:
        out = subprocess.run([binary, "elements", "--json"], check=True,
                             stdout=subprocess.PIPE, universal_newlines=True).stdout
        schemas = json.loads(out)
    except (OSError, subprocess.CalledProcessError, ValueError) as e:
        print("cannot read the element schemas from %s: %s" % (binary, e))
        return 2
    errors = []
    pages_dir = os.path.join(source, "docs", "elements")
    for etype in sorted(schemas):
        page = os.path.join(pages_dir, etype + ".md")
        rel = os.path.relpath(page, source)
        if not os.path.isfile(page):
            errors.append("%s: missing (element type %s)" % (rel, etype))
            continue
        with open(page, encoding="utf-8") as f:
            text = f.read()
        have = sections(text)
        for s in ("## Conventions", "## Outputs", "## Keys"):
            if s not in have:
                errors.append("%s: no section '%s'" % (rel, s))
        props = schemas[etype].get("properties", {})
        want = {k: schema_unit(v.get("description", "")) for k, v in props.items()
                if k not in GENERIC_KEYS}
        rows = keys_table(text)
        if rows is None:
            continue
        if isinstance(rows, str):
            errors.append("%s: Keys table %s" % (rel, rows))
            continue
        for key in sorted(set(want) - set(rows)):
            errors.append("%s: Keys table lacks key '%s' (schema unit '%s')" % (rel, key, want[key]))
        for key in sorted(set(rows) - set(want)):
            errors.append("%s:%d: Keys table has key '%s', which %s's schema does not"
                          % (rel, rows[key][0][0], key, etype))
        for key in sorted(set(rows) & set(want)):
            if len(rows[key]) > 1:
                errors.append("%s:%d: key '%s' listed %d times"
                              % (rel, rows[key][1][0], key, len(rows[key])))
            n, unit = rows[key][0]
            if unit != want[key]:
                errors.append("%s:%d: key '%s': unit '%s', schema says '%s'"
                              % (rel, n, key, unit, want[key]))
    # the index lists every page
    index = os.path.join(pages_dir, "README.md")
    if not os.path.isfile(index):
        errors.append("docs/elements/README.md: missing")
    else:
        listed = {os.path.normpath(os.path.join(pages_dir, t.partition("#")[0]))
                  for _, t in links(index) if t.partition("#")[0]}
        for page in sorted(glob.glob(os.path.join(pages_dir, "*.md"))):
            if os.path.basename(page) != "README.md" and page not in listed:
                errors.append("docs/elements/README.md: does not list %s" % os.path.basename(page))
    files = [os.path.join(source, "README.md")]
    files += sorted(glob.glob(os.path.join(source, "docs", "*.md")))
    files += sorted(glob.glob(os.path.join(pages_dir, "*.md")))
    check_links(source, [f for f in files if os.path.isfile(f)], errors)
    for e in errors:
        print(e)
    print("element_pages: %d element types, %d problem(s)" % (len(schemas), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
