#!/usr/bin/env bash
# Benchmarks, run on demand (never as timed tests): the burr-mill start and
# the roll crusher 2-mass run by milldyn's integrators, by the same Simbody
# integrators on a bare Simbody system of the same equations (the floor of a
# Simbody-based tool), by hand with Boost.Odeint and with SciPy, all at one
# tolerance, in one run; errors against a tight Odeint reference and speed
# ratios against Odeint dopri5, the best SciPy method and bare Simbody.
#   bench/run.sh [TOL] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
tol="${1:-1e-6}"
repeats="${2:-5}"
scripts/install-deps.sh
missing=()
for p in libboost-dev python3-scipy python3-numpy; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
cmake -S . -B build -DMILLDYN_BENCH=ON >/dev/null
cmake --build build -j"$(nproc)" --target bench_odeint bench_milldyn bench_bare_simbody \
  bench_kinetostatic
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
out=$(mktemp)
build/bench_odeint burr 1e-12 1 dopri5 | sed 's/odeint_dopri5/reference/' > "$out"
build/bench_odeint burr "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/scipy_burr.py "$tol" 3 >> "$out"
build/bench_bare_simbody burr "$tol" "$repeats" >> "$out"
build/bench_milldyn burr "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/report.py "$out"
# The roll crusher 2-mass level, rows in phase (bench/roll_equations.h).
out=$(mktemp)
build/bench_odeint roll 1e-12 1 dopri5 | sed 's/odeint_dopri5/reference/' > "$out"
build/bench_odeint roll "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/scipy_roll.py "$tol" 3 >> "$out"
build/bench_bare_simbody roll "$tol" "$repeats" >> "$out"
build/bench_milldyn roll "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/report.py "$out" "motor speed (2.5, 5, 10 s)"
# Kinetostatic throughput (bench/kinetostatic.cpp): configurations/s per
# core of the planetary-gear `turn` scenario and of its floor.
out=$(mktemp)
build/bench_kinetostatic 2000 3 > "$out"
/usr/bin/python3 bench/report.py "$out"
echo "# done $(date -u '+%H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
