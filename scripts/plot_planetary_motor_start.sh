#!/bin/sh
# Regenerates the plots of docs/will-it-start.md's planetary section from
# models/planetary_gear_500x1000_motor_start.yaml: the start by the motor
# through the slipping V-belt (speeds, belt tensions and slip), the same
# start with a belt that does not slip (pretension 40 kN), and the sweep of
# the pretension. Needs a built milldyn and gnuplot.
# usage: scripts/plot_planetary_motor_start.sh [BUILD_DIR]   (default: build)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build}/milldyn
MODEL=models/planetary_gear_500x1000_motor_start.yaml
OUT=$(mktemp -d)
IMG=docs/images
trap 'rm -rf "$OUT"' EXIT

"$BIN" run "$MODEL" --set outputs.plots=false --out "$OUT/slip" --quiet
"$BIN" run "$MODEL" --set outputs.plots=false --set "elements.belt.pretension=40 kN" --out "$OUT/grip" --quiet

# The column of header "$2" in CSV "$1" (RFC 4180: a quoted name may hold commas).
col() { python3 -c 'import csv, sys; h = next(csv.reader(open(sys.argv[1], newline=""))); print(h.index(sys.argv[2]) + 1 if sys.argv[2] in h else "")' "$1" "$2"; }
S=$OUT/slip/timeseries.csv
G=$OUT/grip/timeseries.csv
WC=$(col "$S" "carrier.speed[rad/s]"); WM=$(col "$S" "motor_shaft.speed[rad/s]")
TT=$(col "$S" "belt.tension_tight[N]"); TS=$(col "$S" "belt.tension_slack[N]")
SV=$(col "$S" "belt.slip_speed[m/s]"); DT=$(col "$S" "belt.driven_torque[N*m]")
GWC=$(col "$G" "carrier.speed[rad/s]"); GDT=$(col "$G" "belt.driven_torque[N*m]")

gnuplot <<GP
set datafile separator ','
set terminal pngcairo size 900,560
set grid
set key bottom right
set output '$IMG/planetary_motor_start_speeds.png'
set title 'Seed-000 planetary mill started by a 200 kW motor through 8 SPC V-belts'
set xlabel 't [s]'; set ylabel 'speed [rad/s]'
plot '$S' every ::1 using 1:(\$$WM/4.42) with lines lw 2 title 'motor shaft / 4.42 (T0 = 11.2 kN)', \
     '$S' every ::1 using 1:$WC with lines lw 2 title 'carrier (T0 = 11.2 kN, belt slips)', \
     '$G' every ::1 using 1:$GWC with lines lw 2 dt 2 title 'carrier (T0 = 40 kN, no slip)'
set output '$IMG/planetary_motor_start_torques.png'
set title 'Torque the belt gives the carrier'
set key top right
set xlabel 't [s]'; set ylabel 'torque on the carrier [kN·m]'
plot '$S' every ::1 using 1:(\$$DT/1000) with lines lw 2 title 'T0 = 11.2 kN (capped at the grip while slipping)', \
     '$G' every ::1 using 1:(\$$GDT/1000) with lines lw 2 dt 2 title 'T0 = 40 kN'
set output '$IMG/planetary_motor_start_belt.png'
set title 'Belt tensions and slip speed, T0 = 11.2 kN'
set ylabel 'tension [kN]'; set y2label 'slip speed [m/s]'; set y2tics; set ytics nomirror
plot '$S' every ::1 using 1:(\$$TT/1000) with lines lw 2 title 'tight span', \
     '$S' every ::1 using 1:(\$$TS/1000) with lines lw 2 title 'slack span', \
     '$S' every ::1 using 1:$SV axes x1y2 with lines lw 2 title 'slip speed'
GP
echo "wrote $IMG/planetary_motor_start_speeds.png, planetary_motor_start_torques.png, planetary_motor_start_belt.png"
