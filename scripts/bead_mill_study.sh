#!/usr/bin/env bash
# Makes the tables and the convergence plot of docs/bead_mill.md: the
# FlexibleRotor chain against the beam oracle over the segment count (with
# run times) and over L_p for both shipped rotors, plus the deflection line.
#   scripts/bead_mill_study.sh [OUTDIR]      (default out/bead_mill_study)
# Run times depend on the machine and its load: they are reported, never
# asserted.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-out/bead_mill_study}"
mkdir -p "$out"
cmake -S . -B build -DMILLDYN_STUDIES=ON >/dev/null
cmake --build build -j"$(nproc)" --target study_bead_mill milldyn
build/study_bead_mill "$out"
for rotor in 5disc_0p1m 8disc_0p3m; do
  build/milldyn run "models/bead_mill_${rotor}.yaml" --out "$out/line_${rotor}" --quiet
done
gnuplot <<GP
set terminal pngcairo size 1000,420 font ",10"
set output "$out/bead_mill_convergence.png"
set datafile separator ","
set multiplot layout 1,2
set logscale xy
set grid
set key bottom left
set xlabel "shaft segments"
set ylabel "relative error vs beam oracle"
set title "error vs segment count (slope -2: O(h^2))"
plot "$out/convergence_5disc_0p1m.csv" skip 1 u 2:4 w lp t "end deflection, 5 x 0.1 m", \
     "" skip 1 u 2:5 w lp t "1st bending freq., 5 x 0.1 m", \
     "$out/convergence_8disc_0p3m.csv" skip 1 u 2:4 w lp t "end deflection, 8 x 0.3 m", \
     "" skip 1 u 2:5 w lp t "1st bending freq., 8 x 0.3 m"
set xlabel "run time [s] (static + linearize, this machine)"
set title "speed / accuracy"
plot "$out/convergence_5disc_0p1m.csv" skip 1 u (\$6+\$7):4 w lp t "end deflection, 5 x 0.1 m", \
     "" skip 1 u (\$6+\$7):5 w lp t "1st bending freq., 5 x 0.1 m", \
     "$out/convergence_8disc_0p3m.csv" skip 1 u (\$6+\$7):4 w lp t "end deflection, 8 x 0.3 m", \
     "" skip 1 u (\$6+\$7):5 w lp t "1st bending freq., 8 x 0.3 m"
unset multiplot
set output "$out/bead_mill_deflection_lines.png"
set terminal pngcairo size 800,420 font ",10"
unset logscale
set xlabel "position from bearing A [m]"
set ylabel "deflection along gravity [um]"
set title "static deflection under gravity, L_p = 0.267 m (bearings at 0 and 0.267 m)"
plot "$out/line_5disc_0p1m/deflection_line.csv" skip 1 u 1:(\$2*1e6) w l lw 2 t "5 discs x 0.1 m, d = 19.5 mm", \
     "$out/line_8disc_0p3m/deflection_line.csv" skip 1 u 1:(\$2*1e6) w l lw 2 t "8 discs x 0.3 m, d = 37.9 mm"
GP
echo "wrote $out/{convergence,span}_*.csv, $out/bead_mill_convergence.png, $out/bead_mill_deflection_lines.png"
