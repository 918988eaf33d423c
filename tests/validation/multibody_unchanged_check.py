"""Guard for issue 31 ("the physics does not change"): `milldyn validate
--json` gives, row by row, the same multibody numbers as main at 3eb6c3b
(tests/testdata/validate_multibody_3eb6c3b.json: [case, quantity,
multibody] of every row, written from that commit's `milldyn validate
--json`). Equal means bit-identical: JSON prints a double so that it reads
back to the same double. A change that is meant to move a number (new
physics, a new case) regenerates the file from the new main and says so
in its commit.

usage: multibody_unchanged_check.py MILLDYN SOURCE_DIR"""
import json, os, subprocess, sys

milldyn, src = sys.argv[1], os.path.abspath(sys.argv[2])
baseline = json.load(open(os.path.join(src, "tests/testdata/validate_multibody_3eb6c3b.json")))
run = subprocess.run([milldyn, "validate", "--json"], capture_output=True, text=True)
if run.returncode not in (0, 1):  # 1: a row failed its tolerance (still compared)
    sys.exit("validate exited %d: %s" % (run.returncode, run.stderr[-2000:]))
rows = [[r["case"], r["quantity"], r.get("multibody")] for r in json.loads(run.stdout)]
bad = []
if len(rows) != len(baseline):
    bad.append("%d rows, main had %d" % (len(rows), len(baseline)))
for i, (now, then) in enumerate(zip(rows, baseline)):
    if now[:2] != then[:2]:
        bad.append("row %d is %s / %s, main's is %s / %s" % (i, now[0], now[1], then[0], then[1]))
    elif now[2] != then[2]:
        bad.append("row %d %s / %s: multibody %r, main %r" % (i, now[0], now[1], now[2], then[2]))
for b in bad[:40]:
    print(b)
print("%d rows compared, %d differ" % (len(rows), len(bad)))
sys.exit(1 if bad else 0)
