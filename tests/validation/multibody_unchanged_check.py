"""Guard for issue 31 ("the physics does not change"): `milldyn validate
--json` gives, row by row, the same multibody numbers as the baseline
(tests/testdata/validate_multibody_baseline.json: [case, quantity,
multibody] of every row, written by `milldyn validate --json` at the merge
of 2026-11-27, whose commit names the three rows that moved on purpose from
3eb6c3b: the frozen charge's located release, the jaw crusher's δ from the
trajectory). A regression guard for mechanical moves, not an oracle. Equal means bit-identical: JSON prints a double so that it reads
back to the same double. A change that is meant to move a number (new
physics, a new case) regenerates the file from the new main and says so
in its commit.

usage: multibody_unchanged_check.py MILLDYN SOURCE_DIR"""
import json, os, subprocess, sys

milldyn, src = sys.argv[1], os.path.abspath(sys.argv[2])
baseline = json.load(open(os.path.join(src, "tests/testdata/validate_multibody_baseline.json")))
run = subprocess.run([milldyn, "validate", "--json"], capture_output=True, text=True)
if run.returncode not in (0, 1):  # 1: a row failed its tolerance (still compared)
    sys.exit("validate exited %d: %s" % (run.returncode, run.stderr[-2000:]))
rows = [[r["case"], r["quantity"], r.get("multibody")] for r in json.loads(run.stdout)]


def keyed(table):
    """(case, quantity, n-th of that pair) -> multibody: rows added or
    removed elsewhere do not shift the comparison."""
    out, seen = {}, {}
    for case, quantity, value in table:
        n = seen.get((case, quantity), 0)
        seen[(case, quantity)] = n + 1
        out[(case, quantity, n)] = value
    return out


now, then = keyed(rows), keyed(baseline)
bad = ["%s / %s: missing (main had multibody %r)" % (k[0], k[1], v) for k, v in then.items() if k not in now]
bad += ["%s / %s: multibody %r, main %r" % (k[0], k[1], now[k], v) for k, v in then.items() if k in now and now[k] != v]
added = [k for k in now if k not in then]
for b in bad[:60]:
    print(b)
print("%d rows compared, %d differ or are missing; %d rows new since the baseline" % (len(then), len(bad), len(added)))
sys.exit(1 if bad else 0)
