#!/usr/bin/env python3
"""Equal outputs on both engines (docs/building.md).

  compare_engines.py SOURCE_DIR MILLDYN_A MILLDYN_B SCRATCH_DIR

Runs a set of shipped models with two milldyn binaries built against the two
Simbody engines (the Release engine with NDEBUG and Debian's checked
libsimbody without it) and compares every number of their summary.json
(results, derived values, settings and statistics; not the run section,
which holds wall time, host and the engine's name). Prints the largest
difference per model and overall. Exit 0 when every value agrees within
REL_TOL, 1 when one does not, 77 (ctest's skip) when the second binary is
absent: build it with scripts/compare-engines.sh.
"""
import json
import math
import os
import subprocess
import sys

# What the two engines may differ by: round-off. Simbody is compiled with
# -O2 both times (Debian: -O2 plus hardening flags; Release: Simbody's own
# "-DNDEBUG -O2"), milldyn with -O3 both times; NDEBUG removes checks, not
# arithmetic. A difference above this is a finding, not a tolerance to raise.
REL_TOL = 1e-9

# (model, extra arguments): every analysis kind the shipped models use.
CASES = [
    ("models/burr_mill_5p5kW_idle.yaml", []),
    ("models/burr_mill_3p2kW_feed50_70.yaml", []),
    ("models/burr_mill_5p5kW_identify.yaml", []),
    ("models/roll_crusher.yaml", ["--end-time", "1 s"]),
    ("models/planetary_gear_100x200.yaml", ["--scenario", "turn"]),
    ("models/planetary_gear_100x200.yaml", ["--scenario", "start", "--set", "scenarios.start.end_time=1 s"]),
    ("models/planetary_belt_200x1000.yaml", []),
    ("models/bead_mill_5disc_0p1m.yaml", []),
    ("models/bead_mill_5disc_0p1m.yaml", ["--scenario", "modes"]),
]


def numbers(node, path=""):
    """Every number in a JSON tree, by its path."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numbers(v, f"{path}.{k}" if path else k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(node, bool):
        yield path, float(node)
    elif isinstance(node, (int, float)):
        yield path, float(node)


def summary(binary, source, model, extra, out):
    cmd = [binary, "run", os.path.join(source, model), "--quiet", "--set", "outputs.plots=false",
           "--out", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        print(f"FAILED: {' '.join(cmd)} exited {r.returncode}: {r.stderr.strip()}")
        sys.exit(1)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    s.pop("run", None)
    return s


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    source, a, b, scratch = sys.argv[1:]
    if not b or not os.access(b, os.X_OK):
        print(f"skipped: no milldyn of the other engine ('{b}'); scripts/compare-engines.sh builds one")
        return 77
    engines = []
    for binary in (a, b):
        v = subprocess.run([binary, "--version"], capture_output=True, text=True).stdout.strip().splitlines()
        engines.append(v[-1] if v else "?")
    print(f"A: {a} ({engines[0]})\nB: {b} ({engines[1]})")
    if engines[0] == engines[1]:
        print("FAILED: both binaries run the same engine")
        return 1
    worst_all = (0.0, "")
    failed = False
    for i, (model, extra) in enumerate(CASES):
        sa = summary(a, source, model, extra, os.path.join(scratch, f"{i}a"))
        sb = summary(b, source, model, extra, os.path.join(scratch, f"{i}b"))
        na, nb = dict(numbers(sa)), dict(numbers(sb))
        if set(na) != set(nb):
            print(f"FAILED {model} {' '.join(extra)}: the summaries hold different values: "
                  f"{sorted(set(na) ^ set(nb))[:5]}")
            failed = True
            continue
        worst, where, identical = 0.0, "", 0
        for key, va in na.items():
            vb = nb[key]
            if va == vb or (math.isnan(va) and math.isnan(vb)):
                identical += 1
                continue
            rel = abs(va - vb) / max(abs(va), abs(vb))
            if rel > worst:
                worst, where = rel, f"{key}: {va!r} vs {vb!r}"
            if not rel <= REL_TOL:
                print(f"FAILED {model} {' '.join(extra)}: {key}: {va!r} vs {vb!r} (relative {rel:.3g})")
                failed = True
        print(f"{model} {' '.join(extra)}: {len(na)} values, {identical} bit-identical, "
              f"largest relative difference {worst:.3g}{' (' + where + ')' if where else ''}")
        if worst > worst_all[0]:
            worst_all = (worst, f"{model} {where}")
    print(f"largest relative difference over all: {worst_all[0]:.3g} {worst_all[1]}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
