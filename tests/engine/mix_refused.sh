#!/usr/bin/env bash
# The configure-time check of cmake/Engine.cmake refuses any mix of NDEBUG
# settings between milldyn and the Simbody it finds (docs/building.md):
#   tests/engine/mix_refused.sh SOURCE_DIR SCRATCH_DIR RELEASE_PREFIX DEBIAN_SIMBODY_DIR
# A: MILLDYN_ENGINE=debian (no NDEBUG) pointed at the Release engine;
# B: MILLDYN_ENGINE=release (NDEBUG) given a prefix whose Simbody is Debian's.
# Each configuration must fail with "Engine mix refused". A is skipped when
# no Release engine is installed (a fallback-only machine).
set -uo pipefail
src=$1 scratch=$2 release_prefix=$3 debian_dir=$4
rm -rf "$scratch"
mkdir -p "$scratch"
status=0
expect_refusal() {  # expect_refusal NAME CMAKE_ARGS...
  local name=$1; shift
  if cmake -S "$src" -B "$scratch/$name" "$@" >"$scratch/$name.log" 2>&1; then
    echo "FAILED $name: configuration succeeded: $*"; status=1
  elif ! grep -q "Engine mix refused" "$scratch/$name.log"; then
    echo "FAILED $name: failed for another reason:"; cat "$scratch/$name.log"; status=1
  else
    echo "ok $name: $(grep -A1 'Engine mix refused' "$scratch/$name.log" | tr -s ' \n' ' ')"
  fi
}
if [ -f "$release_prefix/.milldyn-engine-stamp" ]; then
  expect_refusal debian_on_release -DMILLDYN_ENGINE=debian -DSimbody_DIR="$release_prefix/lib/cmake/simbody"
else
  echo "skipped debian_on_release: no Release engine at '$release_prefix'"
fi
if [ -f "$debian_dir/SimbodyConfig.cmake" ]; then
  mkdir -p "$scratch/fake_engine/lib/cmake"
  touch "$scratch/fake_engine/.milldyn-engine-stamp"
  ln -s "$debian_dir" "$scratch/fake_engine/lib/cmake/simbody"
  expect_refusal release_on_debian -DMILLDYN_ENGINE=release -DMILLDYN_ENGINE_PREFIX="$scratch/fake_engine"
else
  echo "FAILED: no Debian Simbody package at '$debian_dir' (libsimbody-dev is a dependency)"; status=1
fi
rm -rf "$scratch"
exit $status
