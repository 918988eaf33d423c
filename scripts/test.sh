#!/usr/bin/env bash
# Set-up from nothing, then the whole test suite (unit and validation).
# Cases labelled "slow" are left out (today: report_full, the full validation report in
# headless Chromium); run them with: cd build && ctest -L slow
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" -LE slow
