#!/usr/bin/env bash
# Equal outputs on both engines (docs/building.md): builds milldyn against
# Debian's checked libsimbody into build-debian/ (the milldyn target only) (beside the default build/,
# against the Release engine), then runs the test that compares every summary
# value of a set of shipped models between the two.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
MILLDYN_BUILD_DIR=build-debian MILLDYN_ENGINE=debian MILLDYN_BUILD_TARGETS=milldyn scripts/build.sh
MILLDYN_ENGINE=release MILLDYN_BUILD_TARGETS=milldyn scripts/build.sh -DMILLDYN_OTHER_ENGINE_MILLDYN="$PWD/build-debian/milldyn"
cd build
ctest --output-on-failure -R '^engine_equal_outputs$'
