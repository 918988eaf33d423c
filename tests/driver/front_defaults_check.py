"""Guard for issue 20 item 11: the default integrator and accuracy of every
shipped model with a transient scenario come from its measured front.

For each models/*.yaml whose `scenario:` is a transient this checks that
  - bench/results/front_model_NAME.csv (bench/front.sh) exists, or the
    model is listed as "not measured" in docs/speed-accuracy-fronts.md
    (printed here as unguarded, so the gap stays visible);
  - the point chosen from it by bench/front_report.py's rule (the cheapest
    run whose worst error is within TARGET) exists and has worst <= TARGET;
  - the model's `integrator:` block names that integrator and accuracy and
    cites the front (docs/speed-accuracy-fronts.md) in a comment; or names
    that integrator at a tighter accuracy with a comment "tighter than its
    front: REASON" (more CPU, never less accuracy; printed, so it stays
    visible);
  - docs/speed-accuracy-fronts.md's defaults table lists that same point.
A default edited by hand, a re-measured CSV that moves the choice, or a
doc not regenerated fails here. Reads files only: fast, no runs.

usage: front_defaults_check.py SOURCE_DIR"""
import glob, math, os, re, sys

import yaml

src = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
sys.path.insert(0, os.path.join(src, "bench"))
os.chdir(src)
import front_report  # noqa: E402  (the rule the doc was generated with)

doc = open("docs/speed-accuracy-fronts.md").read()
not_measured = set(re.findall(r"^- not measured: (\S+)$", doc, re.M))
doc_rows = {}
for line in doc.splitlines():
    m = re.match(r"\| ([A-Za-z0-9_]+) \| (\w+) \| ([0-9.e+-]+) \| ([0-9.e+-]+) \|", line)
    if m:
        doc_rows[m.group(1)] = (m.group(2), float(m.group(3)), float(m.group(4)))

failures, checked, unguarded = [], 0, 0
for path in sorted(glob.glob("models/*.yaml")):
    name = os.path.basename(path)[:-5]
    text = open(path).read()
    model = yaml.safe_load(text)
    if (model.get("scenario") or {}).get("analysis") != "transient":
        continue
    checked += 1
    csv_path = "bench/results/front_model_%s.csv" % name
    if not os.path.exists(csv_path) and name in not_measured:
        print("UNGUARDED %s: no front measured (listed in docs/speed-accuracy-fronts.md)" % path)
        unguarded += 1
        continue
    if name in not_measured:
        failures.append("%s: measured, but still listed as not measured (run bench/front_report.py)" % path)
    if not os.path.exists(csv_path):
        failures.append("%s: no measured front %s (bench/front.sh models %s)" % (path, csv_path, name))
        continue
    _, rows = front_report.model_rows(csv_path)
    pick = front_report.choose(rows)
    if pick is None:
        failures.append("%s: no point of its front is within %g" % (path, front_report.TARGET))
        continue
    want = (pick["integrator"], float(pick["accuracy"]))
    integ = model.get("integrator") or {}
    have = (integ.get("name"), float(integ.get("accuracy", "nan")))
    block = re.search(r"^integrator:.*?(?=^\S)", text, re.S | re.M)
    tighter = (block and "tighter than its front:" in block.group(0) and have[0] == want[0]
               and have[1] < want[1])
    if tighter:
        print("TIGHTER %s: %s %g, its front chooses %g (%s)" % (path, have[0], have[1], want[1],
              block.group(0).split("tighter than its front:")[1].split("\n")[0].strip()))
    elif have[0] != want[0] or not math.isclose(have[1], want[1], rel_tol=1e-9):
        failures.append("%s: integrator %s %g, but its front chooses %s %g (worst error %s)"
                        % (path, have[0], have[1], want[0], want[1], pick["worst"]))
    if not block or "speed-accuracy-fronts" not in block.group(0):
        failures.append("%s: the integrator block does not cite docs/speed-accuracy-fronts.md" % path)
    row = doc_rows.get(name)
    if row is None or row[0] != want[0] or not math.isclose(row[1], want[1], rel_tol=1e-9):
        failures.append("%s: docs/speed-accuracy-fronts.md lists %s, the CSV chooses %s %g "
                        "(run bench/front_report.py)" % (path, row, want[0], want[1]))

for f in failures:
    print("FAIL " + f)
if checked == 0:
    print("FAIL no shipped model with a transient scenario found")
    sys.exit(1)
failed_models = len({f.split(":")[0] for f in failures})
print("%d passed, %d failed, %d skipped" % (checked - unguarded - failed_models, failed_models, unguarded))
sys.exit(1 if failures else 0)
