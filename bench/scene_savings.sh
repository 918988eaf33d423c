#!/usr/bin/env bash
# What building only what a scene needs saves (issue #7 §3), on demand,
# never a test: builds milldyn and runs bench/scene_savings.py, which prints
# the table of docs/speed-accuracy.md section 3 (wall time, realizations,
# and how much the kept outputs moved, for each saving against its baseline).
#   bench/scene_savings.sh [REPEATS]      (default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" >/dev/null
cmake --build "$BUILD" -j2 --target milldyn >/dev/null
exec /usr/bin/python3 bench/scene_savings.py "$BUILD" "${1:-3}"
