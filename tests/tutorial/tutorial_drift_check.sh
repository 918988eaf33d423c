#!/usr/bin/env bash
# The tutorial runner must fail when a step prints something else than the
# tutorial says, and when a step fails: run it on copies of
# docs/new-layout.md with step 1's expected output changed, and with step 1's
# command broken (both stop at step 1, before the plugin is compiled).
#   tests/tutorial/tutorial_drift_check.sh SOURCE_DIR MILLDYN_BINARY SCRATCH_DIR
set -uo pipefail
src=$1 binary=$2 scratch=$3
runner=$src/tests/tutorial/run_new_layout_tutorial.sh
rm -rf "$scratch" && mkdir -p "$scratch"

check() {  # check NAME SED_EXPRESSION EXPECTED_MESSAGE
  local doc=$scratch/$1.md
  sed "$2" "$src/docs/new-layout.md" >"$doc"
  if cmp -s "$doc" "$src/docs/new-layout.md"; then
    echo "FAIL: $1: the edit '$2' changed nothing (has step 1 of the tutorial changed?)"
    exit 1
  fi
  local out status
  out=$("$runner" "$src" "$binary" "$scratch/$1" "$doc" 2>&1)
  status=$?
  if [ "$status" -ne 1 ] || ! grep -qF "$3" <<<"$out"; then
    echo "FAIL: $1: the runner exited $status without '$3'; it printed:"
    echo "$out"
    exit 1
  fi
  echo "ok: $1"
}

check changed_output 's/^PlanetaryLayoutPlugin.cpp$/PlanetaryLayoutPlugin.cc/' \
  "FAILED: step 1 printed something else than the tutorial says"
check failing_step 's/^ls my_layout$/ls my_layout\/no_such_file/' "FAILED: step 1 exited non-zero"

# A line of only "..." stands for zero or more lines: a one-step tutorial
# whose output "a" is followed directly by "b" matches "a / ... / b" and
# "a / b / ...", and still fails when the order is wrong.
wildcard_doc() {  # wildcard_doc NAME EXPECTED_LINES...
  local doc=$scratch/$1.md
  shift
  { printf '```sh tutorial\nprintf '"'"'a\\nb\\n'"'"'\n```\n\n```text tutorial-output\n'
    printf '%s\n' "$@"
    printf '```\n'; } >"$doc"
  echo "$doc"
}
for expect in "a ... b" "a b ..." "... a ... ... b ..."; do
  # shellcheck disable=SC2086
  doc=$(wildcard_doc "dots_$(tr -c 'a-z' _ <<<"$expect")" $expect)
  if ! out=$("$runner" "$src" "$binary" "${doc%.md}" "$doc" 2>&1); then
    echo "FAIL: a '...' line must match zero lines (expected: $expect); the runner printed:"
    echo "$out"
    exit 1
  fi
done
doc=$(wildcard_doc dots_wrong_order b ... a)
if out=$("$runner" "$src" "$binary" "${doc%.md}" "$doc" 2>&1) || ! grep -qF "expected line not found" <<<"$out"; then
  echo "FAIL: 'b ... a' must not match output a, b; the runner printed:"
  echo "$out"
  exit 1
fi
echo "ok: a line of '...' matches zero or more lines"
