"""Turns bench/results/front_SCENE.csv (bench/front.sh) into
docs/speed-accuracy-fronts.md (a table per scene, front points marked) and
docs/images/front_SCENE.png (error against wall time, log-log, gnuplot)."""
import csv, glob, math, os, subprocess, tempfile

# The largest worst error a shipped model's default may have (issue 20
# item 11): 1e-3 on every peak torque, ripple, steady speed, start/run-out
# time and the energy balance (bench/front.cpp defines them).
TARGET = 1e-3

SCENES = [  # (scene, title, what the error compares)
    ("burr", "Burr mill MMP-50 5.5 kW, start to steady running (4 s)",
     "motor and millstone speed, belt torque vs RungeKuttaMerson 1e-11"),
    ("burr_3p2kW_feed", "Burr mill MMP-50 3.2 kW, feed 130-150 kg/h, start to steady running (4 s)",
     "motor and millstone speed, belt torque vs RungeKuttaMerson 1e-11"),
    ("roll", "Roll crusher, 10 s of crushing from steady running (2-mass and 10-mass levels)",
     "motor speed and reducer torque vs the 10-mass level, RungeKuttaMerson 1e-10"),
    ("planetary_gear", "Planetary gear mill 100x200, rigid charges, start (first 1 s of the 5 s scenario): replayed, and integrated on request",
     "drive torque, friction torque at A and B1 vs the replay (no integration; journal loads consistent at each instant)"),
    ("planetary_gear_dynamic", "Planetary gear mill 100x200, dynamic charges (own pins, wall drag), start (first 1 s)",
     "drive torque, charge lag, friction torque at B1 vs RungeKuttaMerson 1e-11"),
    ("planetary_gear_iterated", "Planetary gear mill 100x200, start (1 s): lagged and iterated reactions (first run, before main's extrapolated mode)",
     "drive torque, friction torque at A and B1 vs lagged, max_step 1e-5 s, RungeKuttaMerson 1e-10"),
    ("planetary_belt", "Planetary belt mill 200x1000, elastic-belt start (first 2 s of 8 s)",
     "carrier drive torque and tight-side tension vs RungeKuttaMerson 1e-10"),
]


def load(scene):
    path = "bench/results/front_%s.csv" % scene
    if not os.path.exists(path):
        return None, []
    rows = list(csv.DictReader(open(path)))
    for r in rows:  # a study re-run since CPU time replaced wall time
        r.setdefault("wall_s", r.get("cpu_s", ""))
    ref = next((r for r in rows if r["variant"] == "reference"), None)
    return ref, [r for r in rows if r["variant"] != "reference"]


def front(rows, error="error", cost="wall_s"):
    """Runs no other run beats in both error and cost (the studies: trace
    error and wall time; the shipped models: worst error and CPU time)."""
    ok = [r for r in rows if r["status"] == "ok" and r[error] and math.isfinite(float(r[error]))]
    ok.sort(key=lambda r: float(r[cost]))
    best, out = math.inf, []
    for r in ok:
        if float(r[error]) < best:
            best = float(r[error])
            out.append(r)
    return out


def plot(scene, title, rows, pareto, ref=None):
    os.makedirs("docs/images", exist_ok=True)
    tmp = tempfile.mkdtemp()
    series = []
    for key in sorted({(r["variant"], r["integrator"]) for r in rows}):
        pts = [r for r in rows if (r["variant"], r["integrator"]) == key and r["status"] == "ok"
               and math.isfinite(float(r["error"])) and float(r["error"]) > 0]
        if not pts:
            continue
        f = os.path.join(tmp, "%d.dat" % len(series))
        with open(f, "w") as out:
            for r in pts:
                out.write("%g %g\n" % (1e3 * float(r["wall_s"]), float(r["error"])))
        series.append((f, "%s %s" % key))
    fp = os.path.join(tmp, "front.dat")
    with open(fp, "w") as out:
        for r in pareto:
            out.write("%g %g\n" % (1e3 * float(r["wall_s"]), max(float(r["error"]), 1e-300)))
    cmds = ["set terminal pngcairo noenhanced size 1000,640 font 'DejaVu Sans,10'",
            "set output 'docs/images/front_%s.png'" % scene, "set logscale xy", "set grid",
            "set title '%s'" % title.replace("'", ""), "set xlabel 'wall time [ms]'",
            "set ylabel 'max relative error'", "set key outside right top"]
    if ref is not None and ref["integrator"] == "replay":
        # The replay is the reference (error 0, off a log scale): a line at its time.
        x = 1e3 * float(ref["wall_s"])
        cmds += ["set arrow from %g, graph 0 to %g, graph 1 nohead dt 2 lw 2 lc rgb 'red'" % (x, x),
                 "set label 'replay (the reference), %.3g ms' at %g, graph 0.03 left offset 0.5,0 tc rgb 'red'" % (x, x)]
    parts = ["'%s' with points pt %d title '%s'" % (f, 1 + i % 13, t) for i, (f, t) in enumerate(series)]
    parts.append("'%s' with lines lw 2 lc rgb 'black' title 'front'" % fp)
    cmds.append("plot " + ", ".join(parts))
    subprocess.run(["gnuplot"], input="\n".join(cmds), text=True, check=True)


def fmt(x, digits=2):
    return "" if x == "" else "%.*g" % (digits, float(x))


def model_rows(path):
    rows = list(csv.DictReader(open(path)))
    ref = next((r for r in rows if r["variant"] == "reference"), None)
    return ref, [r for r in rows if r["variant"] != "reference"]


def choose(rows):
    """The cheapest run (median CPU) whose worst error is within TARGET and
    whose energy balance passes the project's own checks: |residual| <=
    10 x accuracy (tests/driver/EnergyBalanceTest.cpp, every shipped model;
    Verlet can miss it at an error within TARGET) and <= 1e-6 (the start
    validation cases, validation/cases/StartCases.cpp)."""
    good = [r for r in rows if r["status"] == "ok" and r["worst"] and float(r["worst"]) <= TARGET
            and float(r["energy"]) <= min(10 * float(r["accuracy"]), 1e-6)]
    return min(good, key=lambda r: float(r["cpu_s"])) if good else None


def apply_defaults():
    """Writes each measured model's chosen point into its integrator block
    (the name and accuracy lines only, with a comment citing the front)."""
    import re
    for f in sorted(glob.glob("bench/results/front_model_*.csv")):
        name = os.path.basename(f)[len("front_model_"):-len(".csv")]
        path = "models/%s.yaml" % name
        _, rows = model_rows(f)
        pick = choose(rows)
        if pick is None or not os.path.exists(path):
            print("%s: no point within %g: left as it is" % (path, TARGET))
            continue
        lines = open(path).read().split("\n")
        start = next(i for i, l in enumerate(lines) if re.match(r"integrator:", l))
        end = next((i for i in range(start + 1, len(lines)) if re.match(r"\S", lines[i])), len(lines))
        for i in range(start + 1, end):
            if re.match(r"  name:", lines[i]):
                lines[i] = ("  name: %s" % pick["integrator"]).ljust(28) + \
                    "# the cheapest point of its front within %g (docs/speed-accuracy-fronts.md)" % TARGET
            elif re.match(r"  accuracy:", lines[i]):
                acc = re.sub(r"e([+-])0*(\d)", r"e\1\2", "%g" % float(pick["accuracy"])).replace("e+", "e")
                lines[i] = ("  accuracy: %s" % acc).ljust(28) + \
                    "# worst error %s (peaks, ripple, speed, times, energy)" % fmt(pick["worst"])
        open(path, "w").write("\n".join(lines))
        print("%s: %s %s" % (path, pick["integrator"], pick["accuracy"]))


def models_section():
    """The shipped models' fronts and the default chosen from each."""
    files = sorted(glob.glob("bench/results/front_model_*.csv"))
    if not files:
        return []
    table = ["## Defaults of the shipped models", "",
             "Chosen by `choose()` in bench/front_report.py: the cheapest point (median CPU time)",
             "whose worst error is at most %g and whose energy balance is within 10 x its accuracy" % TARGET,
             "and 1e-6 (the checks of tests/driver/EnergyBalanceTest.cpp and validation/cases/StartCases.cpp).",
             "tests/driver/front_defaults_check.py checks that",
             "each model's `integrator:` block is the point below and that the point is still",
             "the one the CSV gives.", "",
             "| model | integrator | accuracy | worst | peak | ripple | speed | time | energy | CPU [ms] | realizations | reference CPU [ms] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    detail = []
    for f in files:
        name = os.path.basename(f)[len("front_model_"):-len(".csv")]
        ref, rows = model_rows(f)
        if ref is None:
            continue
        pick = choose(rows)
        ids = {id(r) for r in front(rows, "worst", "cpu_s")}
        if pick is None:
            table.append("| %s | none within %g | | | | | | | | | | %.3g |" % (name, TARGET, 1e3 * float(ref["cpu_s"])))
        else:
            table.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %.3g | %s | %.3g |" % (
                name, pick["integrator"], pick["accuracy"], fmt(pick["worst"]), fmt(pick["peak_error"]),
                fmt(pick["ripple_error"]), fmt(pick["speed_error"]), fmt(pick["time_error"]), fmt(pick["energy"]),
                1e3 * float(pick["cpu_s"]), pick["realizations"], 1e3 * float(ref["cpu_s"])))
        detail += ["### models/%s.yaml" % name, "",
                   "Reference %s %s: %.3g s CPU, %s steps, energy balance %s." % (
                       ref["integrator"], ref["accuracy"], float(ref["cpu_s"]), ref["steps"], fmt(ref["energy"])), "",
                   "| integrator | accuracy | status | worst | peak | ripple | speed | time | energy | CPU [ms] | realizations | |",
                   "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in rows:
            cpu = "" if r["cpu_s"] == "" else "%.3g" % (1e3 * float(r["cpu_s"]))
            mark = "**default**" if r is pick else ("front" if id(r) in ids else "")
            detail.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                r["integrator"], r["accuracy"], r["status"], fmt(r["worst"]), fmt(r["peak_error"]),
                fmt(r["ripple_error"]), fmt(r["speed_error"]), fmt(r["time_error"]), fmt(r["energy"]), cpu,
                r["realizations"], mark))
        detail.append("")
    missing = [n for n in transient_models() if not os.path.exists("bench/results/front_model_%s.csv" % n)]
    if missing:
        table += ["", "**Not measured** (no front yet: their defaults are the hand-chosen ones, not guarded;",
                  "`bench/front.sh models NAME` measures one):", ""]
        table += ["- not measured: %s" % n for n in missing]
    return table + [""] + detail


def transient_models():
    """Stems of models/*.yaml whose own scenario is a transient."""
    import yaml
    out = []
    for path in sorted(glob.glob("models/*.yaml")):
        model = yaml.safe_load(open(path))
        if (model.get("scenario") or {}).get("analysis") == "transient":
            out.append(os.path.basename(path)[:-5])
    return out


def main():
  out = ["# Error-cost fronts (generated by bench/front_report.py: do not edit)", "",
       "Produced by `bench/front.sh`; read docs/speed-accuracy.md first (§1 defines the",
       "errors). Shipped models: one row per run of the model as shipped; worst = the",
       "largest of the errors of the peak torques, the torque ripple over the steady",
       "window, the steady speed, the start and run-out times, and the run's own",
       "energy-balance residual, each against a RungeKuttaMerson 1e-10 run; CPU = median",
       "process CPU time of 3 alternated rounds; front = no other run is both cheaper",
       "and more accurate.", ""]
  out += models_section()
  out += ["## Studies (trace error)", "",
          "The scene studies before the shipped-model fronts: error = largest relative",
          "deviation from the reference over the compared columns (max over samples of",
          "|x - x_ref| / max |x_ref|); wall = one run in process, best of three when",
          "under 0.2 s; **front** = no other run is both faster and more accurate.", ""]
  for scene, title, what in SCENES:
      ref, rows = load(scene)
      if ref is None:
          continue
      pareto = front(rows)
      ids = {id(r) for r in pareto}
      png = "docs/images/front_%s.png" % scene
      if not os.path.exists(png) or os.path.getmtime(png) < os.path.getmtime("bench/results/front_%s.csv" % scene):
          plot(scene, title, rows, pareto, ref)  # only a study measured again
      out += ["### %s" % title, "", "Error: %s. Reference run: %s s wall, %s steps." % (what, fmt(ref["wall_s"], 3), ref["steps"]),
              "", "![front](images/front_%s.png)" % scene, "",
              "| variant | integrator | accuracy | status | error | wall [ms] | steps | realizations | front |",
              "|---|---|---|---|---|---|---|---|---|"]
      for r in rows:
          wall = "" if r["wall_s"] == "" else "%.3g" % (1e3 * float(r["wall_s"]))
          out.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
              r["variant"], r["integrator"], r["accuracy"], r["status"], fmt(r["error"]), wall, r["steps"],
              r["realizations"], "**front**" if id(r) in ids else ""))
      out.append("")
  open("docs/speed-accuracy-fronts.md", "w").write("\n".join(out) + "\n")
  print("wrote docs/speed-accuracy-fronts.md and docs/images/front_*.png")


if __name__ == "__main__":
    import sys
    if "--apply" in sys.argv[1:]:
        apply_defaults()
    else:
        main()
