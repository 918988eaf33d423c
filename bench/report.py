"""Turns the JSON lines of bench/run.sh into a table: error against the
reference, CPU time (wall time beside it), realizations (right-hand-side
calls for Odeint dopri5 and SciPy), CPU time per realization, and ratios
(of CPU times) to
Odeint dopri5, the best SciPy method and bare Simbody with the same
integrator (milldyn_X / simbody_X: milldyn's own overhead)."""
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
# bench/run.sh tags the lines of Simbody programs with their engine
# ("Release": Simbody built with NDEBUG; "checked": Debian's libsimbody):
# both engines side by side, each compared with bare Simbody on its own engine.
for r in rows:
    if "engine" in r and "method" in r:
        r["method"] = "%s [%s]" % (r["method"], r["engine"])
if "configurations_per_s" in rows[0]:
    # bench_kinetostatic: throughput, realizations per configuration, floor.
    # configurations_per_s is per CPU second (per wall second before CPU
    # time was measured: then the wall column stays empty).
    print("| model | level | engine | configurations / CPU s | configurations / wall s | Acceleration realizations / configuration "
          "| CPU µs / realization | floor: configurations / CPU s (1 realization each) | / floor |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        n = r["acceleration_realizations_per_configuration"]
        print("| %s | %s | %s | %.4g | %s | %.3g | %.3g | %.4g | %.3g |" % (
            r["model"], r["level"], r.get("engine", "–"), r["configurations_per_s"],
            "%.4g" % r["configurations_per_wall_s"] if "configurations_per_wall_s" in r else "–",
            n, 1e6 / (r["configurations_per_s"] * n),
            r["floor_configurations_per_s"], r["floor_configurations_per_s"] / r["configurations_per_s"]))
    sys.exit(0)
what = sys.argv[2] if len(sys.argv) > 2 else "omega2 (0.5, 0.85, 4 s)"
ref = next(r for r in rows if r["method"] == "reference")["omega2"]
rows = [r for r in rows if r["method"] != "reference"]
for r in rows:
    r["error"] = max(abs(a - b) / abs(b) for a, b in zip(r["omega2"], ref))
# Times compared: CPU time when every program measured it, else wall time.
key = "cpu_s" if all("cpu_s" in r for r in rows) else "wall_s"
for r in rows:
    r["t"] = r[key]
odeint = next(r for r in rows if r["method"] == "odeint_dopri5")["t"]
scipy_best = min(r["t"] for r in rows if r["method"].startswith("scipy_"))
bare = {r["method"][len("simbody_"):]: r["t"] for r in rows if r["method"].startswith("simbody_")}
# The same method on the checked engine over the Release engine.
by_method = {r["method"]: r["t"] for r in rows}
print("| method | tolerance | max rel. error of %s | %s [ms] | wall [ms] | realizations (rhs calls) | µs each "
      "| / odeint dopri5 | / best SciPy | / bare Simbody | checked / Release |" % (what, "CPU" if key == "cpu_s" else "wall"))
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    integrator = r["method"][len("milldyn_"):] if r["method"].startswith("milldyn_") else None
    other = r["method"].replace("[Release]", "[checked]")
    speedup = "%.3g" % (by_method[other] / r["t"]) if other != r["method"] and other in by_method else "–"
    print("| %s | %g | %.2g | %.3g | %.3g | %s | %s | %.3g | %.3g | %s | %s |" % (
        r["method"], r["tolerance"], r["error"], 1e3 * r["t"], 1e3 * r["wall_s"],
        r.get("realizations", "–"), "%.3g" % (1e6 * r["t"] / r["realizations"]) if r.get("realizations") else "–",
        r["t"] / odeint, r["t"] / scipy_best,
        "%.3g" % (r["t"] / bare[integrator]) if integrator in bare else "–", speedup))
