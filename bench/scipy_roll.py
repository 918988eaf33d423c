"""Baseline: the roll-crusher 2-mass run (rows in phase) with SciPy's solve_ivp
(RK45, Radau, LSODA). Same equations as bench/roll_equations.h. Prints one
JSON line per method (key "omega2" holds the motor speed at 2.5, 5, 10 s, the
key bench/report.py reads)."""
import json, math, sys, time
from scipy.integrate import solve_ivp

Jm, Jr, u, c, b = 3.5, 639.0, 125.0, 716.54, 0.487
Mn, wn, wc = 893.2, 588 * 2 * math.pi / 60, 600 * 2 * math.pi / 60
M00, b0 = Mn * wc / (wc - wn), Mn / (wc - wn)
Mbar, P1, ws = 7440.0, 3.973, 0.01
amp = (4464.0, 2232.0, 1488.0, 1116.0)

def rhs(t, x):
    T = c * (x[0] - u * x[1]) + b * (x[2] - u * x[3])
    load = Mbar * math.tanh(x[3] / ws) + sum(a * math.sin((k + 1) * P1 * t) for k, a in enumerate(amp))
    return [x[2], x[3], (M00 - b0 * x[2] - T) / Jm, (u * T - 9 * load) / Jr]

def steady():
    w = (M00 - 9 * Mbar / u) / b0
    for _ in range(50):
        th = math.tanh(w / (u * ws))
        f = M00 - b0 * w - 9 * Mbar * th / u
        df = -b0 - 9 * Mbar * (1 - th * th) / (u * u * ws)
        w -= f / df
    T = M00 - b0 * w
    return [0.0, -(T / c) / u, w, w / u]

tol = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-6
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
times = [2.5, 5.0, 10.0]
for method in ("RK45", "Radau", "LSODA"):
    walls, cpus = [], []  # wall and CPU time (the process's, as bench/clocks.h)
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        sol = solve_ivp(rhs, (0, 10.0), steady(), method=method, rtol=tol, atol=tol * 1e-3, t_eval=times)
        walls.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    walls.sort()
    cpus.sort()
    print(json.dumps({"method": "scipy_" + method, "tolerance": tol, "wall_s": walls[len(walls) // 2], "cpu_s": cpus[len(cpus) // 2], "realizations": int(sol.nfev),
                      "omega2": [float(v) for v in sol.y[2]]}))
