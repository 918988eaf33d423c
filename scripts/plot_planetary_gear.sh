#!/bin/sh
# Regenerates the plots of docs/planetary_gear.md from the shipped model
# files: Fig. 10 reading (a) (initial torque against the acceleration time
# t_p, milldyn sweep of the start instant), the multibody start M(t) of
# both sizes beside the paper's J_pr ε(t) + friction, and the bearing
# reactions over one carrier turn at steady speed (kinetostatics).
# Needs a built milldyn and gnuplot.
# usage: scripts/plot_planetary_gear.sh [BUILD_DIR]   (default: build)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build}/milldyn
OUT=$(mktemp -d)
IMG=docs/images
trap 'rm -rf "$OUT"' EXIT

for size in 100x200 500x1000; do
  M=models/planetary_gear_$size.yaml
  "$BIN" sweep "$M" --grid "elements.drive.acceleration_time=0.2 s:5 s:97" --jobs 1 --out "$OUT/tp_$size" >/dev/null
  "$BIN" sweep "$M" --grid "elements.drive.acceleration_time=1000 s:1000 s:1" --jobs 1 --out "$OUT/tpinf_$size" >/dev/null
  # The start, with journal friction (extrapolated loads, accuracy 1e-8:
  # friction torques within 0.1 %, docs/planetary_gear.md).
  "$BIN" run "$M" --scenario start --set outputs.sample_interval=0.01s \
    --out "$OUT/start_$size" --quiet
  "$BIN" run "$M" --scenario turn --set fidelity.level=held_charge --set elements.charge1.lag=45deg \
    --set elements.charge2.lag=45deg --out "$OUT/turn45_$size" --quiet
  "$BIN" run "$M" --scenario turn --set fidelity.level=held_charge --out "$OUT/turn90_$size" --quiet
  "$BIN" run "$M" --scenario turn --out "$OUT/turnrigid_$size" --quiet
done

# The column of header "$2" in CSV "$1" (RFC 4180: a quoted name may hold commas).
col() { python3 -c 'import csv, sys; h = next(csv.reader(open(sys.argv[1], newline=""))); print(h.index(sys.argv[2]) + 1 if sys.argv[2] in h else "")' "$1" "$2"; }
TP=$(col "$OUT/tp_100x200/sweep.csv" "elements.drive.acceleration_time[s]")
MT=$(col "$OUT/tp_100x200/sweep.csv" "drive.torque.first[N*m]")
MINF_S=$(tail -1 "$OUT/tpinf_100x200/sweep.csv" | cut -d, -f"$MT")
MINF_L=$(tail -1 "$OUT/tpinf_500x1000/sweep.csv" | cut -d, -f"$MT")
S=$OUT/start_100x200/timeseries.csv
DT=$(col "$S" "drive.torque[N*m]")
J_S=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results']['reduced_inertia']['value'])" \
  "$OUT/turnrigid_100x200/summary.json")
RA=$(col "$OUT/turn45_100x200/kinetostatics.csv" "reaction_A.on_carrier_at_axis_magnitude[N]")
RB=$(col "$OUT/turn45_100x200/kinetostatics.csv" "reaction_B2.on_drum2_at_axis_magnitude[N]")
TQ=$(col "$OUT/turn45_100x200/kinetostatics.csv" "drive.torque[N*m]")

gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,560
set grid
set output '$IMG/planetary_gear_fig10_tp.png'
set title 'Fig. 10, reading (a): start torque against the acceleration time t_p (ε0 = ω_y/(1 − e^{−t_p}))'
set xlabel 't_p [s]'; set ylabel 'M(t_p) / M(t_p → ∞)'
set yrange [0:6]
set arrow 1 from 0.3,0 to 0.3,6 nohead dt 2
set arrow 2 from 0.4,0 to 0.4,6 nohead dt 2
set label 1 'paper: peak ≈ 4× at 0.3–0.4 s, steady after ≈ 3 s' at 1.0,3.6
plot '$OUT/tp_100x200/sweep.csv' every ::1 using $TP:(\$$MT/$MINF_S) with points pt 7 ps 0.6 title 'multibody 100 × 200 mm', \
     '$OUT/tp_500x1000/sweep.csv' every ::1 using $TP:(\$$MT/$MINF_L) with points pt 6 ps 1.2 title 'multibody 500 × 1000 mm', \
     1/(1-exp(-x)) with lines lw 1 title '1/(1 − e^{−t_p}) (oracle, friction aside)'
unset arrow 1; unset arrow 2; unset label 1; set yrange [*:*]
set output '$IMG/planetary_gear_start_history.png'
set title 'Fig. 10, reading (b): torque history of one start (t_p = 4.6 s), 100 × 200 mm'
set xlabel 't [s]'; set ylabel 'M [N·m]'
eps0 = 78.5398163397448/(1-exp(-4.6))
plot '$S' every ::1 using 1:$DT with lines lw 2 title 'multibody (gravity, centrifugal loads, journal friction from reactions)', \
     $J_S*eps0*exp(-x) with lines dt 2 title 'paper: J_pr ε0 e^{−t} (friction aside)'
set output '$IMG/planetary_gear_start_history_large.png'
set title 'Torque history of one start (t_p = 4.6 s), 500 × 1000 mm'
S2='$OUT/start_500x1000/timeseries.csv'
plot S2 every ::1 using 1:$DT with lines lw 2 title 'multibody'
set output '$IMG/planetary_gear_reactions_turn.png'
set title 'Bearing reactions over one carrier turn at 750 rpm, 100 × 200 mm (charges held at α)'
set xlabel 'carrier angle φ [deg]'; set ylabel '|R| [kN]'; set xrange [0:360]
plot '$OUT/turn45_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):(\$$RA/1000) with lines lw 2 title 'A, α = 45°', \
     '$OUT/turn45_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):(\$$RB/1000) with lines lw 2 title 'B2, α = 45°', \
     '$OUT/turn90_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):(\$$RA/1000) with lines dt 2 title 'A, α = 90°', \
     '$OUT/turn90_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):(\$$RB/1000) with lines dt 2 title 'B2, α = 90°'
set output '$IMG/planetary_gear_torque_turn.png'
set title 'Carrier torque over one turn at 750 rpm, 100 × 200 mm: the charge-holding torque'
set ylabel 'M [N·m]'
plot '$OUT/turn45_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):$TQ with lines lw 2 title 'charges held at α = 45°', \
     '$OUT/turn90_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):$TQ with lines lw 2 title 'held at α = 90° (straight out)', \
     '$OUT/turnrigid_100x200/kinetostatics.csv' every ::1 using (\$1*180/pi):$TQ with lines dt 2 title 'charges turning with the drums (paper)'
GP
echo "wrote $IMG/planetary_gear_*.png"
