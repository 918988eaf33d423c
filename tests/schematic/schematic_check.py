#!/usr/bin/env python3
"""System test of `milldyn run MODEL --schematic` (docs/schematic.md).

For the seed-000 and seed-002 models: the SVGs parse (xml.dom.minidom), hold
the expected shapes (drums, charges, arrows, ...), and every reaction arrow's
length is its reaction's magnitude, read from the same run's table, times one
scale that the legend's reference arrow shows too. Bad input exits 2 with a
one-line error.

usage: schematic_check.py MILLDYN SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import xml.dom.minidom

milldyn, source, work = sys.argv[1:4]
models = os.path.join(source, "models")
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(args):
    return subprocess.run([milldyn] + args, capture_output=True, text=True)


def table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return [h.split("[")[0] for h in rows[0]], [[float(v) for v in r] for r in rows[1:]]


def by_class(doc, tag, cls):
    return [e for e in doc.getElementsByTagName(tag) if cls in e.getAttribute("class").split()]


def check_picture(svg_path, csv_path, expect, label):
    doc = xml.dom.minidom.parse(svg_path)  # raises if not well-formed
    root = doc.documentElement
    for (tag, cls), n in expect.items():
        got = len(by_class(doc, tag, cls))
        check(got == n, f"{label}: {n} <{tag} class={cls}> expected, found {got}")
    key = float(root.getAttribute("data-key"))
    px_per_n = float(root.getAttribute("data-px-per-m")) * float(root.getAttribute("data-m-per-n"))
    check(px_per_n > 0, f"{label}: a positive arrow scale")
    names, rows = table(csv_path)
    row = min(rows, key=lambda r: abs(r[0] - key))
    check(abs(row[0] - key) <= 1e-9 * max(1, abs(key)), f"{label}: the drawn instant {key} is a row of the table")
    groups = by_class(doc, "g", "arrow")
    for g in groups:
        name = g.getAttribute("data-name")
        col = [i for i, n in enumerate(names) if n.startswith(name + ".on_") and n.endswith("_magnitude")]
        check(len(col) == 1, f"{label}: arrow {name} has one magnitude column")
        if len(col) != 1:
            continue
        magnitude = row[col[0]]
        line = g.getElementsByTagName("line")[0]
        length = math.hypot(float(line.getAttribute("x2")) - float(line.getAttribute("x1")),
                            float(line.getAttribute("y2")) - float(line.getAttribute("y1")))
        check(magnitude > 0, f"{label}: {name} carries a load")
        check(abs(length - magnitude * px_per_n) <= 1e-6 * magnitude * px_per_n,
              f"{label}: arrow {name} is {length:.6f} px, {magnitude} N x {px_per_n} px/N = "
              f"{magnitude * px_per_n:.6f} px")
    legend = by_class(doc, "g", "legend-arrow")
    check(len(legend) == 1, f"{label}: one reference arrow in the legend")
    if legend:
        ref = float(legend[0].getAttribute("data-force"))
        line = legend[0].getElementsByTagName("line")[0]
        length = float(line.getAttribute("x2")) - float(line.getAttribute("x1"))
        check(abs(length - ref * px_per_n) <= 1e-6 * ref * px_per_n, f"{label}: reference arrow to scale")
    return len(groups)


shutil.rmtree(work, ignore_errors=True)

# Seed 000: a carrier turn with the charges held at their lag, at three angles.
out = os.path.join(work, "gear")
r = run(["run", os.path.join(models, "planetary_gear_100x200.yaml"), "--quiet", "--out", out, "--scenario", "turn",
         "--set", "fidelity.level=held_charge", "--set", "scenarios.turn.angle_points=13",
         "--schematic-at", "0,90 deg,3.14159265358979"])
check(r.returncode == 0, "gear: run --schematic exits 0: " + r.stderr)
for i in (1, 2, 3):
    svg = os.path.join(out, f"schematic_{i}.svg")
    check(os.path.exists(svg), f"gear: {svg} written")
    if os.path.exists(svg):
        check_picture(svg, os.path.join(out, "kinetostatics.csv"),
                      {("circle", "drum"): 2, ("path", "charge"): 2, ("circle", "fixed_gear"): 1,
                       ("line", "carrier"): 2, ("g", "arrow"): 3}, f"gear picture {i}")
check(not os.path.exists(os.path.join(out, "schematic_4.svg")), "gear: three pictures for three angles")
# Lags labelled in their convention (issue 20 item 13): on a carrier, from the carrier radius.
if os.path.exists(os.path.join(out, "schematic_1.svg")):
    text = open(os.path.join(out, "schematic_1.svg")).read()
    check(re.search(r"lag -?\d+ deg from carrier radius<", text) is not None, "gear: lag labelled from the carrier radius")
if shutil.which("rsvg-convert"):
    png = os.path.join(out, "schematic_1.png")
    check(os.path.exists(png) and os.path.getsize(png) > 1000, "gear: PNG written by rsvg-convert")

# Seed 000, a transient: the start, at 0.5 s (a sample) and 0.304 s (nearest sample 0.3 s).
out = os.path.join(work, "gear_start")
r = run(["run", os.path.join(models, "planetary_gear_100x200.yaml"), "--quiet", "--out", out, "--scenario", "start",
         "--set", "scenarios.start.end_time=1 s", "--schematic-at", "0.5 s,0.304"])
check(r.returncode == 0, "gear start: run --schematic exits 0: " + r.stderr)
if r.returncode == 0:
    check_picture(os.path.join(out, "schematic_1.svg"), os.path.join(out, "timeseries.csv"),
                  {("circle", "drum"): 2, ("path", "charge"): 2, ("g", "arrow"): 3}, "gear start 0.5 s")
    doc = xml.dom.minidom.parse(os.path.join(out, "schematic_2.svg"))
    check(abs(float(doc.documentElement.getAttribute("data-key")) - 0.3) < 1e-9, "gear start: nearest sample drawn")
    check("nearest" in open(os.path.join(out, "schematic_2.svg")).read(), "gear start: the caption says so")

# A tumbling mill on a fixed axis: its lag is labelled from the vertical.
out = os.path.join(work, "tumbling")
r = run(["run", os.path.join(models, "tumbling_ball_mill_3x4m.yaml"), "--quiet", "--out", out, "--scenario", "running",
         "--set", "scenarios.running.end_time=0.2 s", "--schematic-at", "0.1 s"])
check(r.returncode == 0, "tumbling: run --schematic exits 0: " + r.stderr)
if r.returncode == 0:
    text = open(os.path.join(out, "schematic_1.svg")).read()
    check(re.search(r"lag -?\d+ deg from vertical<", text) is not None, "tumbling: lag labelled from the vertical")

# Seed 002: the Fig. 3 turn at two angles.
out = os.path.join(work, "belt")
r = run(["run", os.path.join(models, "planetary_belt_200x1000.yaml"), "--quiet", "--out", out,
         "--schematic-at", "0 deg,330 deg"])
check(r.returncode == 0, "belt: run --schematic exits 0: " + r.stderr)
for i in (1, 2):
    svg = os.path.join(out, f"schematic_{i}.svg")
    check(os.path.exists(svg), f"belt: {svg} written")
    if os.path.exists(svg):
        check_picture(svg, os.path.join(out, "kinetostatics.csv"),
                      {("circle", "drum"): 2, ("path", "charge"): 2, ("circle", "sheave"): 3, ("line", "belt"): 4,
                       ("line", "carrier"): 2, ("g", "arrow"): 3}, f"belt picture {i}")

# Default instants: four over the turn.
out = os.path.join(work, "belt_default")
r = run(["run", os.path.join(models, "planetary_belt_200x1000.yaml"), "--quiet", "--out", out, "--schematic"])
check(r.returncode == 0 and os.path.exists(os.path.join(out, "schematic_4.svg")), "belt: four default pictures")

# Bad input: one line, exit 2, nothing drawn.
bad = [
    (["run", os.path.join(models, "planetary_belt_200x1000.yaml"), "--out", os.path.join(work, "bad1"),
      "--schematic-at", "400 deg"], "outside the run"),
    (["run", os.path.join(models, "planetary_gear_100x200.yaml"), "--out", os.path.join(work, "bad2"),
      "--scenario", "start", "--set", "scenarios.start.end_time=1 s", "--schematic-at", "2 s"], "outside the run"),
    (["run", os.path.join(models, "planetary_gear_100x200.yaml"), "--out", os.path.join(work, "bad3"),
      "--schematic-at", "fast"], "is not a carrier angle"),
    (["run", os.path.join(models, "burr_mill_5p5kW_idle.yaml"), "--out", os.path.join(work, "bad4"), "--schematic"],
     "nothing to draw"),
    (["info", os.path.join(models, "planetary_gear_100x200.yaml"), "--schematic"], "--schematic goes with run"),
]
for args, message in bad:
    r = run(args)
    first = r.stderr.splitlines()[0] if r.stderr else ""
    check(r.returncode == 2, f"{message}: exit 2, got {r.returncode}")
    check(message in first and first.startswith("milldyn: error:"), f"{message}: one-line error, got '{first}'")
    if "--out" in args:
        d = args[args.index("--out") + 1]
        drawn = os.path.isdir(d) and any(f.startswith("schematic") for f in os.listdir(d))
        check(not drawn, f"{message}: nothing drawn")

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("schematic checks passed")
