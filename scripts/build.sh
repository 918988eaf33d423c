#!/usr/bin/env bash
# Configures and builds milldyn into build/ (optimised, never with NDEBUG:
# see docs/building.md). Extra arguments go to cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
werror=OFF
[ "${CI:-}" = "true" ] && werror=ON
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMILLDYN_WERROR="$werror" "$@" >/dev/null
cmake --build build -j"$(nproc)"
