"""Turns the JSON lines of bench/run.sh into a table: error against the
reference, wall time, and ratios to Odeint dopri5 and the best SciPy method."""
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
what = sys.argv[2] if len(sys.argv) > 2 else "omega2 (0.5, 0.85, 4 s)"
ref = next(r for r in rows if r["method"] == "reference")["omega2"]
rows = [r for r in rows if r["method"] != "reference"]
for r in rows:
    r["error"] = max(abs(a - b) / abs(b) for a, b in zip(r["omega2"], ref))
odeint = next(r for r in rows if r["method"] == "odeint_dopri5")["wall_s"]
scipy_best = min(r["wall_s"] for r in rows if r["method"].startswith("scipy_"))
print("| method | tolerance | max rel. error of %s | wall [ms] | / odeint dopri5 | / best SciPy |" % what)
print("|---|---|---|---|---|---|")
for r in rows:
    print("| %s | %g | %.2g | %.3g | %.3g | %.3g |" % (r["method"], r["tolerance"], r["error"], 1e3 * r["wall_s"],
                                                    r["wall_s"] / odeint, r["wall_s"] / scipy_best))
