#!/usr/bin/env bash
# Set-up from nothing, then the default model: the MMP-50 burr mill with its
# 5.5 kW motor, started, run idle and switched off.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/milldyn run models/burr_mill_5p5kW_idle.yaml --out out/demo
