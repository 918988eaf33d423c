"""Issue 29 item 5, second round: Python as its users expect.

A run that did not do what was asked says so (Result.verdict from the CLI's
own rule, a warning class, an option to raise), sweeps mark and warn about
such points, unknown names get the CLI reader's suggestion, matrices carry
their row and column labels, repr(Result) is a few lines, and Value
arithmetic ends in the unit a designer reads (W, N*m/rad, ...).

Run by ctest (test `python`), as test_milldyn.py.
"""

import os
import subprocess
import types
import warnings

import numpy as np
import pytest

import milldyn

SRC = os.environ.get("MILLDYN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("MILLDYN_BINARY", os.path.join(SRC, "build", "milldyn"))
BENCH = os.path.join(SRC, "models", "start_bench_dol.yaml")
IDLE = os.path.join(SRC, "models", "burr_mill_5p5kW_idle.yaml")
NO_PLOTS = {"outputs.plots": "false"}
# Kloss gives 2*Mk*sk/(1 + sk^2) = 46.2 N*m at standstill for the bench's
# 15 kW motor (tests/driver/StartVerdictTest.cpp): a 60 N*m load never
# moves, the start stalls (the CLI exits 3).
STALL = {"elements.load.constant_torque": "60 N*m", "scenario.end_time": "1 s", "outputs.plots": "false"}
# The 1.5 s run ends mid-acceleration: the start is unfinished (exit 0).
UNFINISHED = {"scenario.end_time": "1.5 s", "outputs.plots": "false"}

TWO_MASS = """format_version: 1
name: two masses
bodies:
  - {name: a, inertia: 2 kg*m^2, joint: {type: pin, parent: ground}}
  - {name: b, inertia: 3 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: TorsionalCoupling, name: shaft, bodies: [a, b], stiffness: 1000 N*m/rad, damping: 2 N*m*s/rad}
scenario: {analysis: linearize}
outputs: {plots: false}
"""


@pytest.fixture
def two_mass(tmp_path):
    """Two inertias joined by a torsional shaft (linearize)."""
    path = tmp_path / "two_mass.yaml"
    path.write_text(TWO_MASS)
    return str(path)


def cli(args):
    return subprocess.run([BIN] + args, capture_output=True, text=True)


def sets(overrides):
    out = []
    for k, v in overrides.items():
        out += ["--set", "%s=%s" % (k, v)]
    return out


# ---- 1. a run that did not do what was asked says so ---------------------------

def test_a_stalled_start_warns_with_the_verdict_the_cli_prints(tmp_path):
    model = milldyn.Model(BENCH, set=STALL)
    with pytest.warns(milldyn.StartNotCompletedWarning, match="start stalled") as caught:
        r = model.run()
    assert issubclass(milldyn.StartNotCompletedWarning, UserWarning)
    assert caught[0].message.result is r
    # The warning names this file (the caller of run), not milldyn's.
    assert caught[0].filename == __file__
    assert r.verdict == "stalled" and r.verdict.kind == "stalled" and not r.verdict.ok
    assert r.verdict.exit_code == 3
    # The drive and load torques at the stall: the Kloss value at standstill.
    assert "motor.torque = 46.2" in r.verdict.text, r.verdict.text
    assert "start_time" not in r.summary
    # The CLI prints the same verdict and exits 3.
    p = cli(["run", BENCH] + sets(STALL) + ["--out", str(tmp_path / "cli")])
    assert p.returncode == 3, p.stderr
    assert "  verdict: %s\n" % r.verdict.text in p.stdout


def test_on_failure_raises_or_ignores(tmp_path):
    model = milldyn.Model(BENCH, set=STALL)
    with pytest.raises(milldyn.StartNotCompleted, match="start stalled") as e:
        model.run(on_failure="raise", out=tmp_path / "out")
    assert isinstance(e.value, milldyn.MilldynError)
    assert e.value.result.verdict == "stalled" and e.value.verdict is e.value.result.verdict
    # The files are written before the raise, as the CLI writes them.
    assert os.path.exists(tmp_path / "out" / "summary.json")
    assert e.value.result.files
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = model.run(on_failure="ignore")
    assert r.verdict == "stalled"
    with pytest.raises(ValueError, match="on_failure"):
        model.run(on_failure="loud")


def test_an_unfinished_start_warns_and_a_completed_one_does_not(tmp_path, two_mass):
    with pytest.warns(milldyn.StartNotCompletedWarning, match="start unfinished"):
        r = milldyn.Model(BENCH, set=UNFINISHED).run()
    assert r.verdict == "unfinished" and r.verdict.kind == "unfinished" and not r.verdict.ok
    # The CLI prints the same verdict and exits 0: the run did what it was told.
    assert r.verdict.exit_code == 0
    p = cli(["run", BENCH] + sets(UNFINISHED) + ["--out", str(tmp_path / "cli")])
    assert p.returncode == 0, p.stderr
    assert "  verdict: %s\n" % r.verdict.text in p.stdout
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        done = milldyn.Model(BENCH, set=NO_PLOTS).run()
        lin = milldyn.Model(two_mass).run()
    assert done.verdict == "completed" and done.verdict.ok and done.verdict.exit_code == 0
    assert done.verdict.text.startswith("start completed")
    # An analysis that judges no start has no verdict, and is ok.
    assert lin.verdict == "" and lin.verdict.ok and not lin.verdict
    assert "none" in repr(lin.verdict)


def test_a_sweep_marks_and_warns_about_points_that_stalled():
    model = milldyn.Model(BENCH, set={"scenario.end_time": "3.5 s", "outputs.plots": "false"})
    grid = {"elements.load.constant_torque": ["0 N*m", "60 N*m"]}
    with pytest.warns(milldyn.StartNotCompletedWarning, match="1 of 2 points did not complete") as caught:
        t = milldyn.sweep(model, grid=grid, jobs=1)
    assert list(t["status"]) == ["ok", "stalled"]
    assert t["diagnostic"][1].startswith("start stalled")
    assert caught[0].message.table is t
    with pytest.raises(milldyn.StartNotCompleted) as e:
        milldyn.sweep(model, grid=grid, jobs=1, on_failure="raise")
    assert list(e.value.table["status"]) == ["ok", "stalled"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        milldyn.sweep(model, grid=grid, jobs=1, on_failure="ignore")
        # A sweep whose points all completed warns nothing.
        t = milldyn.sweep(milldyn.Model(BENCH, set=NO_PLOTS), grid={"elements.load.constant_torque": ["0 N*m", "1 N*m"]},
                          jobs=1)
    assert list(t["status"]) == ["ok", "ok"]


# ---- 3. unknown names: the CLI reader's suggestion -----------------------------

def test_unknown_element_types_keys_and_fields_suggest_the_nearest():
    with pytest.raises(KeyError, match="did you mean 'ResistanceTorque'"):
        milldyn.elements()["ResistanceTorqe"]
    with pytest.raises(KeyError, match="did you mean 'constant_torque'"):
        milldyn.elements()["ResistanceTorque"]["keys"]["constant_torqe"]
    with pytest.raises(KeyError, match="did you mean 'transient'"):
        milldyn.analyses()["transiet"]
    model = milldyn.Model(IDLE, set={"scenario.initial_state": "steady", "scenario.end_time": "0.1 s",
                                     "outputs.plots": "false"})
    with pytest.raises(KeyError, match="did you mean 'bodies'"):
        model.info()["bodys"]
    r = model.run()
    with pytest.raises(KeyError, match="did you mean 'steps'"):
        r.statistics["step"]
    with pytest.raises(KeyError, match="did you mean 'millstone.speed'"):
        r.table.units["millstone.sped"]
    # The reader says the same for a key in an override path (the CLI's message).
    with pytest.raises(milldyn.ModelError, match="did you mean 'constant_torque'"):
        milldyn.Model(IDLE, set={"elements.grinding.constant_torqe": "10 N*m"})
    p = cli(["run", IDLE, "--set", "elements.grinding.constant_torqe=10 N*m"])
    assert p.returncode == 2 and "did you mean 'constant_torque'" in p.stderr


# ---- 4. matrices with their labels ---------------------------------------------

def test_matrices_carry_their_row_and_column_labels(two_mass):
    r = milldyn.Model(two_mass).run()
    assert r.dof_names == ["a", "b"]
    M, K, C, A = (r.matrices[n] for n in ("M", "K", "C", "A"))
    assert M.rows == M.columns == ["a", "b"] and M.unit == "kg*m^2"
    # The two inertias on the diagonal, the coupling's stiffness and damping
    # in K and C: what the model file says, found by label.
    m = M.to_pandas()
    assert m.loc["a", "a"] == pytest.approx(2) and m.loc["b", "b"] == pytest.approx(3)
    assert m.loc["a", "b"] == pytest.approx(0, abs=1e-9) and m.attrs["unit"] == "kg*m^2"
    k = K.to_pandas()
    assert k.loc["a", "a"] == pytest.approx(1000) and k.loc["a", "b"] == pytest.approx(-1000)
    assert C.to_pandas().loc["b", "a"] == pytest.approx(-2)
    assert A.rows == ["a.angle", "b.angle", "a.speed", "b.speed"] and A.columns == A.rows
    # A = [[0, I], [-M^-1 K, -M^-1 C]]: d(b.speed)/dt per a.angle is +1000/3.
    assert A.to_pandas().loc["b.speed", "a.angle"] == pytest.approx(1000 / 3)
    assert A.to_pandas().loc["a.angle", "a.speed"] == pytest.approx(1)
    values, unit = K  # still unpacks as (array, unit)
    assert values is K.values and unit == "N*m/rad" and K.shape == (2, 2)
    assert "rows a, b" in repr(K)


# ---- 6. a short repr -------------------------------------------------------------

def test_repr_of_a_result_is_a_few_lines_with_the_verdict_and_table_sizes(two_mass):
    with pytest.warns(milldyn.StartNotCompletedWarning):
        r = milldyn.Model(BENCH, set=STALL).run()
    text = repr(r)
    lines = text.splitlines()
    assert 3 <= len(lines) <= 6, text
    assert all(len(line) <= 130 for line in lines), text
    assert lines[0] == "<milldyn.Result transient of %r" % r.model.name
    assert lines[1].startswith("  verdict: start stalled")
    assert "of %d results)" % len(r.summary) in text
    assert "tables: timeseries %dx%d" % (len(r.table), len(r.table.names)) in text
    lin = milldyn.Model(two_mass).run()
    assert "verdict" not in repr(lin) and "matrices: M, C, K, A" in repr(lin)


# ---- 5. a clean namespace ------------------------------------------------------

def test_no_module_but_milldyns_own_in_the_namespace():
    modules = [n for n in dir(milldyn) if not n.startswith("_") and isinstance(getattr(milldyn, n), types.ModuleType)]
    assert modules == ["errors"], modules
    for name in ("Verdict", "StartNotCompleted", "StartNotCompletedWarning"):
        assert name in milldyn.__all__ and hasattr(milldyn, name)


# ---- 7. units a designer reads -------------------------------------------------

def test_products_and_quotients_end_in_the_unit_a_designer_reads():
    torque, speed = milldyn.Value(200.0, "N*m"), milldyn.Value(150.0, "rad/s")
    power = torque * speed
    assert power.unit == "W" and float(power) == 30000
    assert power.to("kW") == pytest.approx(30) and power.to("kW").unit == "kW"
    assert (milldyn.Value(30.0, "kW").to("W")) == pytest.approx(30000)
    assert (torque / milldyn.Value(0.1, "rad")).unit == "N*m/rad"
    assert (torque / speed).unit == "N*m*s/rad"
    assert (milldyn.Value(1000.0, "N*m/rad") * milldyn.Value(0.01, "rad")).unit == "N*m"
    assert (milldyn.Value(5.0, "W") * milldyn.Value(2.0, "s")).unit == "J"
    assert (milldyn.Value(2.0, "N") * milldyn.Value(3.0, "m")).unit == "N*m"
    assert (milldyn.Value(3.0, "kN") * milldyn.Value(2.0, "m")) == pytest.approx(6000)
    assert (milldyn.Value(3.0, "kN") * milldyn.Value(2.0, "m")).unit == "N*m"
    assert (milldyn.Value(2.0, "1") * torque).unit == "N*m"
    # No unit for the dimension: the composed one, as written.
    odd = milldyn.Value(2.0, "kg") * milldyn.Value(3.0, "rad/s")
    assert odd.unit == "kg*(rad/s)" and float(odd) == 6
    with pytest.raises(milldyn.UnitError, match="dimension"):
        torque.to("W")
    assert milldyn.quantity("20 kN*m").unit == "N*m"
    assert milldyn.quantity("1500 rpm").to("rpm") == pytest.approx(1500)
    # A result's Value converts too.
    r = milldyn.Model(BENCH, set=NO_PLOTS).run()
    p = r.summary["steady_speed"]
    assert p.to("rpm") == pytest.approx(float(p) * 30 / np.pi)
