#!/usr/bin/env python3
"""What "model only what a scene requires" saves (issue #7 §3), measured in
one run: each pair runs the same scene with and without one saving through
`milldyn run` and compares wall time (best of REPEATS, from summary.json),
Simbody realizations, and the largest relative difference of the compared
columns (the saving must not change what is kept beyond the stated reason).

    bench/scene_savings.py [BUILD_DIR] [REPEATS]      (bench/scene_savings.sh builds first)

Prints a Markdown table (docs/speed-accuracy.md, section 3)."""
import csv, json, os, subprocess, sys, tempfile, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 5
MILLDYN = os.path.join(BUILD, "milldyn")

GEAR = ["models/planetary_gear_100x200.yaml", "--set", "use_scenario=start"]
GEAR_TURN = ["models/planetary_gear_100x200.yaml", "--set", "use_scenario=turn",
             "--set", "scenarios.turn.angle_points=2001"]
BURR = ["models/burr_mill_5p5kW_idle.yaml"]
ROLL = ["models/roll_crusher.yaml"]

# (saving, scene, baseline args, saving args, compared columns)
PAIRS = [
    ("no free DOF: replay instead of integration (RungeKuttaMerson 1e-8, the model's)",
     "planetary gear start, 5 s", GEAR + ["--set", "scenarios.start.zero_dof=integrate"], GEAR,
     ["drive.torque", "friction_A.torque", "reaction_A.on_carrier_at_axis_magnitude"]),
    ("no free DOF: replay instead of integration at 1e-10",
     "planetary gear start, 5 s",
     GEAR + ["--set", "scenarios.start.zero_dof=integrate", "--set", "integrator.accuracy=1e-10"], GEAR,
     ["drive.torque", "friction_A.torque", "reaction_A.on_carrier_at_axis_magnitude"]),
    ("2-mass level: no shaft chain (9 bodies, 9 couplings not built)",
     "roll crusher, 10 s", ROLL + ["--set", "fidelity.level=10-mass"], ROLL + ["--set", "fidelity.level=2-mass"],
     ["motor.speed"]),
    ("outputs.energy_balance: false (no energy meter states)",
     "burr mill 5.5 kW, start, idle, run-out (CPodes 1e-6)", BURR, BURR + ["--set", "outputs.energy_balance=false"],
     ["millstone.speed", "belt.torque"]),
    ("outputs.energy_balance: false (no energy meter states)",
     "roll crusher 10-mass, 10 s (CPodes 1e-6)", ROLL, ROLL + ["--set", "outputs.energy_balance=false"],
     ["motor.speed", "reducer.torque"]),
    ("outputs.columns: drive.torque (6 JointReaction outputs and 16 other outputs not built or evaluated)",
     "planetary gear start, 5 s, replayed", GEAR, GEAR + ["--set", "outputs.columns=drive.torque"],
     ["drive.torque"]),
    ("outputs.columns: drive.torque",
     "planetary gear, one carrier turn, 2001 angles (kinetostatic)", GEAR_TURN,
     GEAR_TURN + ["--set", "outputs.columns=drive.torque"], ["drive.torque"]),
]


def run(args):
    best = None
    for _ in range(REPEATS):
        out = tempfile.mkdtemp(prefix="milldyn_saving_")
        subprocess.run([MILLDYN, "run", *args, "--set", "outputs.plots=false", "--quiet", "--out", out],
                       cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
        summary = json.load(open(os.path.join(out, "summary.json")))
        table = next(f for f in os.listdir(out) if f.endswith(".csv"))
        rows = list(csv.reader(open(os.path.join(out, table))))
        header = [h.split("[")[0] for h in rows[0]]
        data = {h: [float(r[i]) for r in rows[1:]] for i, h in enumerate(header)}
        wall = summary["run"]["wall_time"]
        if best is None or wall < best[0]:
            best = (wall, summary["statistics"]["realizations"], data)
    return best


def difference(a, b, columns):
    worst = 0.0
    for c in columns:
        scale = max(abs(x) for x in a[c]) or 1.0
        worst = max(worst, max(abs(x - y) for x, y in zip(a[c], b[c])) / scale)
    return worst


print("Measured %s, load average %s at the start, best of %d runs each." %
      (time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), open("/proc/loadavg").read().split()[0], REPEATS))
print()
print("| saving | scene | wall before [s] | wall after [s] | after/before | realizations before | after | "
      "max rel. difference of %s |" % "compared columns")
print("|---|---|---|---|---|---|---|---|")
for saving, scene, before_args, after_args, columns in PAIRS:
    w0, r0, d0 = run(before_args)
    w1, r1, d1 = run(after_args)
    print("| %s | %s | %.3g | %.3g | %.2f | %d | %d | %.1e (%s) |" %
          (saving, scene, w0, w1, w1 / w0, r0, r1, difference(d0, d1, columns), ", ".join(columns)))
    sys.stdout.flush()
print()
print("Load average at the end: %s." % open("/proc/loadavg").read().split()[0])
