#!/usr/bin/env bash
# Configures and builds milldyn into build/ (docs/building.md). Extra
# arguments go to cmake's configure step.
#
# The engine: by default the Release engine (Simbody built from Debian's
# source package by scripts/build-engine.sh, once per machine) with milldyn
# compiled with NDEBUG. Debian's checked libsimbody-dev, without NDEBUG, is
# the fallback, chosen explicitly:
#   scripts/build.sh -DMILLDYN_ENGINE=debian     or   MILLDYN_ENGINE=debian scripts/build.sh
# MILLDYN_BUILD_DIR (default build) names the build directory;
# MILLDYN_BUILD_TARGETS (default: all) the targets to build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${MILLDYN_BUILD_DIR:-build}"
# -Werror when CI=true; otherwise the build directory keeps its setting
# (switching it recompiles everything).
werror_args=()
[ "${CI:-}" = "true" ] && werror_args=(-DMILLDYN_WERROR=ON)

engine="${MILLDYN_ENGINE:-}"
for arg in "$@"; do
  case "$arg" in
    -DMILLDYN_ENGINE=*|-DMILLDYN_ENGINE:STRING=*) engine="${arg#*=}" ;;
  esac
done
# A build directory configured before keeps its engine unless told otherwise.
if [ -z "$engine" ] && [ -f "$build_dir/CMakeCache.txt" ]; then
  engine="$(sed -n 's/^MILLDYN_ENGINE:STRING=//p' "$build_dir/CMakeCache.txt")"
fi
engine="${engine:-release}"

engine_args=(-DMILLDYN_ENGINE="$engine")
if [ "$engine" = "release" ]; then
  prefix="$(scripts/build-engine.sh | tail -n 1)"
  engine_args+=(-DMILLDYN_ENGINE_PREFIX="$prefix")
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${werror_args[@]}" "${engine_args[@]}" "$@" >/dev/null
targets=()
for t in ${MILLDYN_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"
