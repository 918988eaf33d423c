#!/usr/bin/env bash
# Benchmarks, run on demand (never as timed tests): the burr-mill start and
# the roll crusher 2-mass run by milldyn's integrators, by the same Simbody
# integrators on a bare Simbody system of the same equations (the floor of a
# Simbody-based tool), by hand with Boost.Odeint and with SciPy, all at one
# tolerance, in one run; errors against a tight Odeint reference and speed
# ratios against Odeint dopri5, the best SciPy method and bare Simbody.
#   bench/run.sh [TOL] [REPEATS]
# MILLDYN_BENCH_SCENES (default "burr roll kinetostatic trajectory") picks the parts run,
# e.g. MILLDYN_BENCH_SCENES=roll for the roll crusher alone.
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
# Both engines side by side (docs/building.md): the Release engine in build/,
# Debian's checked library in build-debian/ (MILLDYN_BENCH_ENGINES=release
# for one). Odeint (built with NDEBUG in either) and SciPy run once.
engines="${MILLDYN_BENCH_ENGINES:-release debian}"
dir_of() { [ "$1" = release ] && echo build || echo build-debian; }
for e in $engines; do
  MILLDYN_BUILD_DIR="$(dir_of "$e")" MILLDYN_ENGINE="$e" \
    MILLDYN_BUILD_TARGETS="bench_odeint bench_milldyn bench_bare_simbody bench_kinetostatic bench_trajectory" \
    scripts/build.sh -DMILLDYN_BENCH=ON
done
first="$(dir_of "${engines%% *}")"
# Every program single-threaded (configurations/s and times are per core;
# NumPy's BLAS would otherwise start threads) and timed by its CPU time
# (bench/clocks.h, time.process_time), the wall time beside it.
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
# Each line of an engine's programs gets its engine's name ("Release", "checked").
engine_runs() {  # engine_runs PROGRAM ARGS...: every engine, lines tagged
  local p=$1; shift
  for e in $engines; do
    local d tag
    d="$(dir_of "$e")"
    tag="$([ "$e" = release ] && echo Release || echo checked)"   # as milldyn --version says
    "$d/$p" "$@" | sed "s/^{/{\"engine\": \"$tag\", /"
  done
}
scenes=" ${MILLDYN_BENCH_SCENES:-burr roll kinetostatic trajectory} "
runs() { [[ "$scenes" == *" $1 "* ]]; }
echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg), $(getconf _NPROCESSORS_ONLN) cores, engines: $engines"  # getconf: nproc obeys OMP_NUM_THREADS
if runs burr; then
out=$(mktemp)
"$first"/bench_odeint burr 1e-12 1 dopri5 | sed 's/odeint_dopri5/reference/' > "$out"
"$first"/bench_odeint burr "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/scipy_burr.py "$tol" 3 >> "$out"
engine_runs bench_bare_simbody burr "$tol" "$repeats" >> "$out"
engine_runs bench_milldyn burr "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/report.py "$out"
fi
# The roll crusher 2-mass level, rows in phase (bench/roll_equations.h).
if runs roll; then
out=$(mktemp)
"$first"/bench_odeint roll 1e-12 1 dopri5 | sed 's/odeint_dopri5/reference/' > "$out"
"$first"/bench_odeint roll "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/scipy_roll.py "$tol" 3 >> "$out"
engine_runs bench_bare_simbody roll "$tol" "$repeats" >> "$out"
engine_runs bench_milldyn roll "$tol" "$repeats" >> "$out"
/usr/bin/python3 bench/report.py "$out" "motor speed (2.5, 5, 10 s)"
fi
# Kinetostatic throughput (bench/kinetostatic.cpp): configurations/s per
# core of the planetary-gear `turn` scenario and of its floor.
if runs kinetostatic; then
out=$(mktemp)
engine_runs bench_kinetostatic 2000 3 > "$out"
/usr/bin/python3 bench/report.py "$out"
fi
# What judging transients from every integration step costs against the
# rows alone (bench/trajectory_cost.cpp; issue 26): one JSON line per start.
if runs trajectory; then
engine_runs bench_trajectory "$repeats"
fi
echo "# done $(date -u '+%H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)"
