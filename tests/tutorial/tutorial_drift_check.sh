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
