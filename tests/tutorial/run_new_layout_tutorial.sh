#!/usr/bin/env bash
# Follows docs/new-layout.md step by step, as a reader would, against a
# built milldyn:
#   tests/tutorial/run_new_layout_tutorial.sh SOURCE_DIR MILLDYN_BINARY SCRATCH_DIR [DOC]
# (DOC: another copy of the tutorial, for the test that the runner catches drift)
# In the tutorial, in document order:
#   ```sh tutorial                 a shell step, run with bash -e -o pipefail in
#                                  SCRATCH_DIR (MILLDYN_SRC and MILLDYN set); it
#                                  must exit 0
#   ```yaml tutorial file=NAME     a file the reader writes: written to SCRATCH_DIR/NAME
#   ```text tutorial-output        what the step before prints: each line must appear
#                                  in its output, in this order (other lines may come
#                                  between); "..." inside a line matches any text, a
#                                  line that is only "..." stands for zero or more lines
# Fails (exit 1) at the first step that fails or prints something else, and
# shows that step's output.
set -uo pipefail

if [ $# -ne 3 ] && [ $# -ne 4 ]; then
  echo "usage: $0 SOURCE_DIR MILLDYN_BINARY SCRATCH_DIR [DOC]" >&2
  exit 2
fi
src=$(cd "$1" && pwd)
binary=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
scratch=$3
doc=${4:-$src/docs/new-layout.md}
doc=$(cd "$(dirname "$doc")" && pwd)/$(basename "$doc")

rm -rf "$scratch"
mkdir -p "$scratch/.steps"
# Split the tutorial into numbered step files: N.sh, N.file (+ N.name), N.expect.
awk -v dir="$scratch/.steps" '
  BEGIN { n = 0; mode = "" }
  mode == "" && /^```sh tutorial$/ { n++; mode = "sh"; out = dir "/" n ".sh"; printf "" > out; next }
  mode == "" && /^```yaml tutorial file=/ {
    n++; mode = "file"; out = dir "/" n ".file"; printf "" > out
    name = $0; sub(/^```yaml tutorial file=/, "", name); print name > (dir "/" n ".name"); next }
  mode == "" && /^```text tutorial-output$/ { mode = "expect"; out = dir "/" n ".expect"; printf "" > out; next }
  mode != "" && /^```$/ { mode = ""; close(out); next }
  mode != "" { print > out }
' "$doc"

steps=$(ls "$scratch/.steps" | sed 's/\..*//' | sort -n | uniq)
[ -n "$steps" ] || { echo "no tutorial steps found in $doc" >&2; exit 1; }

# "..." is a wildcard; everything else is literal. A line of only "..." is
# skipped: the match is already in order with any lines between, so it means
# "zero or more lines" (it used to consume exactly one line, and broke when a
# summary line it stood for moved away).
matches() {  # matches OUTPUT_FILE EXPECT_FILE
  python3 - "$1" "$2" <<'PY'
import re, sys
out = open(sys.argv[1]).read().splitlines()
expect = [l for l in open(sys.argv[2]).read().splitlines() if l.strip() and l.strip() != "..."]
i = 0
for e in expect:
    pattern = re.compile("^" + ".*".join(re.escape(part) for part in e.rstrip().split("...")) + "$")
    while i < len(out) and not pattern.match(out[i].rstrip()):
        i += 1
    if i == len(out):
        print("expected line not found (in order): " + e)
        sys.exit(1)
    i += 1
PY
}

count=0
for n in $steps; do
  if [ -f "$scratch/.steps/$n.file" ]; then
    name=$(cat "$scratch/.steps/$n.name")
    mkdir -p "$(dirname "$scratch/$name")"
    cp "$scratch/.steps/$n.file" "$scratch/$name"
    echo "step $n: wrote $name"
  fi
  if [ -f "$scratch/.steps/$n.sh" ]; then
    echo "step $n: $(head -n 1 "$scratch/.steps/$n.sh")"
    if ! (cd "$scratch" && MILLDYN_SRC=$src MILLDYN=$binary bash -e -o pipefail "$scratch/.steps/$n.sh") \
        >"$scratch/.steps/$n.out" 2>&1; then
      echo "FAILED: step $n exited non-zero; its output:"
      cat "$scratch/.steps/$n.out"
      exit 1
    fi
  fi
  if [ -f "$scratch/.steps/$n.expect" ]; then
    if [ ! -f "$scratch/.steps/$n.out" ]; then
      echo "FAILED: tutorial-output block after step $n, which is not a shell step"
      exit 1
    fi
    if ! matches "$scratch/.steps/$n.out" "$scratch/.steps/$n.expect"; then
      echo "FAILED: step $n printed something else than the tutorial says; its output:"
      cat "$scratch/.steps/$n.out"
      exit 1
    fi
  fi
  count=$((count + 1))
done
echo "tutorial followed: $count steps passed"
