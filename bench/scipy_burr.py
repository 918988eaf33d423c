"""Baseline: the burr-mill start with SciPy's solve_ivp (RK45, Radau, LSODA).
Same equations as bench/burr_equations.h. Prints one JSON line per method."""
import json, math, sys, time
import numpy as np
from scipy.integrate import solve_ivp

J1, J2, c, b = 190.7e-4, 982.4e-4, 537.0, 0.293
Mn, wn, wc, lam = 36.3, 1446 * 2 * math.pi / 60, 1500 * 2 * math.pi / 60, 2.2
Mc, ws = 16.2, 0.01
sk = (wc - wn) / wc * (lam + math.sqrt(lam * lam - 1))

def rhs(t, x):
    s = (wc - x[2]) / wc
    M = 2 * lam * Mn * s * sk / (s * s + sk * sk)
    T = c * (x[0] - x[1]) + b * (x[2] - x[3])
    return [x[2], x[3], (M - T) / J1, (T - Mc * math.tanh(x[3] / ws)) / J2]

tol = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-6
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
times = [0.5, 0.85, 4.0]
for method in ("RK45", "Radau", "LSODA"):
    walls, cpus = [], []  # wall and CPU time (the process's, as bench/clocks.h)
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        sol = solve_ivp(rhs, (0, 4.0), [0, 0, 0, 0], method=method, rtol=tol, atol=tol * 1e-3, t_eval=times)
        walls.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    walls.sort()
    cpus.sort()
    print(json.dumps({"method": "scipy_" + method, "tolerance": tol, "wall_s": walls[len(walls) // 2], "cpu_s": cpus[len(cpus) // 2], "realizations": int(sol.nfev),
                      "omega2": [float(v) for v in sol.y[3]]}))
