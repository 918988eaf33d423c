#!/usr/bin/env bash
# The error-cost front of every shipped transient scene (issue #7, part 1),
# on demand, never a test:
#   bench/front.sh [SCENE...]     scenes: models (default: the shipped models'
#                                 defaults, issue 20 item 11), and the studies
#                                 burr burr_3p2kW_feed roll planetary_gear
#                                 planetary_gear_dynamic planetary_belt
#                                 planetary_gear_iterated (on request)
#   bench/front.sh models [MODEL...]   only these models/*.yaml (stem names)
# models: every shipped model whose scenario is a transient, as shipped,
# RungeKuttaMerson/RungeKutta3/CPodes/Verlet at 1e-3 ... 1e-8 against
# RungeKuttaMerson 1e-10; errors of peaks, ripple, steady speed, start and
# run-out times, energy balance (bench/front.cpp); CPU time the median of 3
# alternated rounds. Writes bench/results/front_model_NAME.csv.
# Writes bench/results/front_SCENE.csv (one row per run) and regenerates
# docs/speed-accuracy.md's tables and docs/images/front_SCENE.png
# (bench/front_report.py). Each run is stopped after BUDGET wall seconds
# (default 2) and that integrator's tighter accuracies are skipped.
# A new machine (the bead mill) adds one case below and one entry in
# bench/front_report.py's SCENES.
set -euo pipefail
cd "$(dirname "$0")/.."
BUDGET=${BUDGET:-2}
BUILD=${BUILD:-build}
cmake -S . -B "$BUILD" -DMILLDYN_BENCH=ON >/dev/null
cmake --build "$BUILD" -j2 --target bench_front >/dev/null
mkdir -p bench/results
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(models)
if [ "${scenes[0]}" = models ]; then
  names=("${scenes[@]:1}")
  if [ ${#names[@]} -eq 0 ]; then
    for f in models/*.yaml; do
      # the models whose own scenario is a transient (not scenarios: entries)
      awk '/^scenario:/{s=1;next} s&&/^[^ #]/{s=0} s&&/^  analysis: *transient/{f=1} END{exit !f}' "$f" \
        && names+=("$(basename "$f" .yaml)")
    done
  fi
  for name in "${names[@]}"; do
    out=bench/results/front_model_$name.csv
    echo "front of models/$name.yaml -> $out (load: $(cut -d' ' -f1-3 /proc/loadavg))" >&2
    # a drive switched off: the steady window ends there (bench/front.cpp)
    off=$(sed -n 's/^ *switch_off_time: *\([0-9.e+-]*\) *s\b.*/\1/p' "models/$name.yaml" | head -n 1)
    "$BUILD"/bench_front "models/$name.yaml" ${off:+--steady-end "$off"} --budget "${MODEL_BUDGET:-20}" --repeat "${REPEAT:-3}" \
      --set outputs.plots=false \
      --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-10" \
      --integrators "${INTEGRATORS:-RungeKuttaMerson,RungeKutta3,CPodes,Verlet}" \
      --accuracies "${ACCURACIES:-1e-3,1e-4,1e-5,1e-6,1e-7,1e-8}" > "$out.tmp" && mv "$out.tmp" "$out"
  done
  /usr/bin/python3 bench/front_report.py
  exit 0
fi
# Integrators and accuracies: all (CPodesAdams too) at 1e-2 ... 1e-10,
# trimmed where a scene is slow (said in docs/speed-accuracy.md).
ALL_ACC=1e-2,1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10
SLOW_ACC=1e-2,1e-4,1e-6,1e-8,1e-10
# The journal-reaction mode of the planetary gear's three JournalFrictions.
reaction() { echo "elements.friction_A.reaction=$1;elements.friction_B1.reaction=$1;elements.friction_B2.reaction=$1"; }
for scene in "${scenes[@]}"; do
  out=bench/results/front_$scene.csv
  echo "front of $scene -> $out (load: $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  case $scene in
    burr)  # the MMP-50 5.5 kW start to steady running, 4 s (switch-off moved out)
      "$BUILD"/bench_front models/burr_mill_5p5kW_idle.yaml --budget "$BUDGET" \
        --set "scenario.end_time=4 s" --set "elements.motor.switch_off_time=100 s" --set outputs.plots=false \
        --columns motor_shaft.speed,millstone.speed,belt.torque \
        --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-11" \
        --accuracies $ALL_ACC > "$out" ;;
    burr_3p2kW_feed)  # the 3.2 kW mill with feed 130-150 kg/h: do the 5.5 kW presets hold?
      "$BUILD"/bench_front models/burr_mill_3p2kW_feed130_150.yaml --budget "$BUDGET" \
        --set "scenario.end_time=4 s" --set "elements.motor.switch_off_time=100 s" --set outputs.plots=false \
        --columns motor_shaft.speed,millstone.speed,belt.torque \
        --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-11" \
        --accuracies $ALL_ACC > "$out" ;;
    roll)  # 10 s of crushing from steady running; 2-mass vs 10-mass
      "$BUILD"/bench_front models/roll_crusher.yaml --budget "$BUDGET" --set outputs.plots=false \
        --columns motor.speed,reducer.torque \
        --ref "fidelity.level=10-mass;integrator.name=RungeKuttaMerson;integrator.accuracy=1e-10" \
        --variant "10-mass:fidelity.level=10-mass" --variant "2-mass:fidelity.level=2-mass" \
        --accuracies $ALL_ACC > "$out" ;;
    planetary_gear)  # the start, trimmed to its first 1 s (the torque peak). With rigid
      # charges it has no free degree of freedom: milldyn replays it (no
      # integration, journal loads consistent at each instant: the
      # reference); the integrated variants measure what integrating costs.
      "$BUILD"/bench_front models/planetary_gear_100x200.yaml --budget "$BUDGET" \
        --set use_scenario=start --set "scenarios.start.end_time=1 s" --set outputs.plots=false \
        --columns drive.torque,friction_A.torque,friction_B1.torque \
        --ref "scenarios.start.zero_dof=replay" \
        --variant "extrapolated:scenarios.start.zero_dof=integrate;$(reaction extrapolated)" \
        --variant "lagged:scenarios.start.zero_dof=integrate;$(reaction lagged)" \
        --variant "lagged_max1e-4:scenarios.start.zero_dof=integrate;integrator.max_step=1e-4 s;$(reaction lagged)" \
        --accuracies $SLOW_ACC > "$out" ;;
    planetary_gear_dynamic)  # charges on their own pins, dragged by the wall: integrated
      "$BUILD"/bench_front models/planetary_gear_100x200.yaml --budget "$BUDGET" \
        --set use_scenario=start --set "scenarios.start.end_time=1 s" --set outputs.plots=false \
        --set fidelity.level=dynamic_charge \
        --columns drive.torque,charge1.lag,friction_B1.torque \
        --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-11" \
        --variant "extrapolated:$(reaction extrapolated)" --accuracies $SLOW_ACC > "$out" ;;
    planetary_gear_iterated)  # iterated reactions (CPodes with them: minutes per run, see docs)
      "$BUILD"/bench_front models/planetary_gear_100x200.yaml --budget "$BUDGET" \
        --set use_scenario=start --set "scenarios.start.end_time=1 s" --set outputs.plots=false \
        --columns drive.torque,friction_A.torque,friction_B1.torque \
        --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-10;integrator.max_step=1e-5 s;$(reaction lagged)" \
        --variant "iterated:$(reaction iterated)" \
        --variant "iterated_max1e-4:integrator.max_step=1e-4 s;$(reaction iterated)" \
        --accuracies $SLOW_ACC > "$out" ;;
    planetary_belt)  # elastic-belt start, trimmed to its first 2 s
      "$BUILD"/bench_front models/planetary_belt_200x1000.yaml --budget "$BUDGET" \
        --set fidelity.level=elastic --set use_scenario=start --set "scenarios.start.end_time=2 s" \
        --set outputs.plots=false \
        --columns drive.torque,belt1.tension_tight \
        --ref "integrator.name=RungeKuttaMerson;integrator.accuracy=1e-10" \
        --variant "elastic:" --accuracies $SLOW_ACC > "$out" ;;
    *) echo "unknown scene $scene" >&2; exit 2 ;;
  esac
done
/usr/bin/python3 bench/front_report.py
