#!/bin/sh
# Regenerates the plots of docs/planetary_belt.md from the shipped model file:
# R_A(φ) (Cartesian and polar) and the belt tensions over a carrier turn
# (kinetostatics), the maps R_A,max vs Ω, γ, r0 (milldyn sweep), and the
# elastic-belt start. Needs a built milldyn and gnuplot.
# usage: scripts/plot_planetary_belt.sh [BUILD_DIR]   (default: build)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build}/milldyn
MODEL=models/planetary_belt_200x1000.yaml
OUT=$(mktemp -d)
IMG=docs/images
trap 'rm -rf "$OUT"' EXIT

"$BIN" run "$MODEL" --out "$OUT/turn" --quiet
"$BIN" run "$MODEL" --set fidelity.level=elastic --scenario start --out "$OUT/start" --quiet
"$BIN" sweep "$MODEL" --grid "scenario.carrier_speed=30 rad/s:80 rad/s:11" --jobs 1 --out "$OUT/omega" >/dev/null
"$BIN" sweep "$MODEL" --grid "elements.charge1.half_angle=30 deg:120 deg:10" --jobs 1 --out "$OUT/gamma" >/dev/null
"$BIN" sweep "$MODEL" --grid "elements.belt1.fixed_sheave_radius=0.02 m:0.16 m:15" --jobs 1 --out "$OUT/c" >/dev/null

# Column numbers by name (gnuplot reads CSV by position).
# The column of header "$2" in CSV "$1" (RFC 4180: a quoted name may hold commas).
col() { python3 -c 'import csv, sys; h = next(csv.reader(open(sys.argv[1], newline=""))); print(h.index(sys.argv[2]) + 1 if sys.argv[2] in h else "")' "$1" "$2"; }
T=$OUT/turn/kinetostatics.csv
RA=$(col "$T" "reaction_A1.on_drum1_at_axis_magnitude[N]")
TT=$(col "$T" "belt1.tension_tight[N]"); TS=$(col "$T" "belt1.tension_slack[N]")
S=$OUT/start/timeseries.csv
SR=$(col "$S" "reaction_A1.on_drum1_at_axis_magnitude[N]")
ST=$(col "$S" "belt1.tension_tight[N]"); SS=$(col "$S" "belt1.tension_slack[N]")
MAX="reaction_A1.on_drum1_at_axis_magnitude.max[N]"

gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,560
set grid
set output '$IMG/planetary_belt_reaction.png'
set title 'Fig. 3 case (Ω = 30 rad/s, γ = 90°, k = 0.1, b = 1, c = 0.5): drum-axle reaction over a carrier turn'
set xlabel 'carrier angle φ [deg]'; set ylabel 'R_A [kN]'
set yrange [60:85]
set object 1 rect from 0,73 to 360,82 fc rgb '#dddddd' behind
set label 1 'printed 73–82 kN' at 10,80.5
plot '$T' every ::1 using (\$1*180/pi):(\$$RA/1000) with lines lw 2 title 'multibody (= rebuilt oracle to 1e-15)'
unset object 1; unset label 1; set yrange [*:*]
set output '$IMG/planetary_belt_reaction_polar.png'
set title 'R_A(φ) in polar form [kN], radius from 0'
set polar; set angles radians; set size square; unset xlabel; unset ylabel
set rrange [0:85]; set grid polar
plot '$T' every ::1 using 1:(\$$RA/1000) with lines lw 2 title 'multibody'
unset polar; set size nosquare; unset rrange; set grid nopolar; set autoscale; set xrange [*:*]; set yrange [*:*]
set output '$IMG/planetary_belt_tensions.png'
set title 'Belt tensions over a carrier turn (rigid belt, T1 = 2 T2)'
set xlabel 'carrier angle φ [deg]'; set ylabel 'tension [kN]'
plot '$T' every ::1 using (\$1*180/pi):(\$$TT/1000) with lines lw 2 title 'tight span', \
     '$T' every ::1 using (\$1*180/pi):(\$$TS/1000) with lines lw 2 title 'slack span'
set output '$IMG/planetary_belt_start.png'
set title 'Start from rest, elastic belt (T0 = 24.4 kN), charge dragged by the wall'
set xlabel 't [s]'; set ylabel '[kN]'
plot '$S' every ::1 using 1:(\$$SR/1000) with lines title 'R_A', \
     '$S' every ::1 using 1:(\$$ST/1000) with lines title 'tight span', \
     '$S' every ::1 using 1:(\$$SS/1000) with lines title 'slack span'
set output '$IMG/planetary_belt_maps.png'
set multiplot layout 1,3 title 'R_A,max over a turn (multibody, milldyn sweep)'
set ylabel 'R_A,max [kN]'
set xlabel 'Ω [rad/s]'; set title 'Fig. 4'
plot '$OUT/omega/sweep.csv' every ::1 using 2:(column($(col "$OUT/omega/sweep.csv" "$MAX"))/1000) with linespoints notitle
set xlabel 'γ [deg]'; set title 'Fig. 5 (Ω = 30)'; set xtics 30
plot '$OUT/gamma/sweep.csv' every ::1 using 2:(column($(col "$OUT/gamma/sweep.csv" "$MAX"))/1000) with linespoints notitle
set xlabel 'c = r0/r_A'; set title 'c at k = 0.1 (Ω = 30)'; set xtics 0.4
plot '$OUT/c/sweep.csv' every ::1 using (\$2/0.1):(column($(col "$OUT/c/sweep.csv" "$MAX"))/1000) with linespoints notitle
unset multiplot
GP
echo "plots written to $IMG"
