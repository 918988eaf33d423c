"""Issue 26 items 4 and 10 and issue 29 items 4 and 5 in the Python module:
tables whose names hold commas, errors a user can catch by their documented
classes, sweeps as people ask them (value lists, log spacing, tied paths,
progress and cancel), and a module that behaves as its users expect.

Run by ctest (test `python`), as test_milldyn.py.
"""

import csv
import os
import subprocess
import threading

import numpy as np
import pytest

import milldyn

SRC = os.environ.get("MILLDYN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("MILLDYN_BINARY", os.path.join(SRC, "build", "milldyn"))
IDLE = os.path.join(SRC, "models", "burr_mill_5p5kW_idle.yaml")
# Short points from steady running.
SHORT = {"scenario.initial_state": "steady", "scenario.end_time": "0.3 s", "outputs.plots": "false"}

SHAFT = """format_version: 1
name: one shaft
bodies:
  - {name: shaft, inertia: 10 kg*m^2, joint: {type: pin, parent: ground}}
elements:
  - {type: InductionMotor, name: motor, body: shaft, rated_torque: 1000 N*m, rated_speed: 990 rpm, synchronous_speed: 1000 rpm}
  - {type: ResistanceTorque, name: "lo,ad", body: shaft, constant_torque: 500 N*m}
scenario: {analysis: transient, initial_state: steady, end_time: 0.05 s}
outputs: {sample_interval: 10 ms, plots: false}
"""


# ---- issue 26 item 4: a name with a comma --------------------------------

def test_a_sweep_over_an_element_named_with_a_comma_reads_its_table(tmp_path):
    model = tmp_path / "shaft.yaml"
    model.write_text(SHAFT)
    table = milldyn.sweep(str(model), grid={"elements.lo,ad.constant_torque": ("400 N*m", "500 N*m", 2)}, jobs=1,
                          out=tmp_path / "s")
    assert table.names[1] == "elements.lo,ad.constant_torque"
    assert list(table["elements.lo,ad.constant_torque"]) == [400, 500]
    assert list(table["status"]) == ["ok", "ok"]
    with open(tmp_path / "s" / "sweep.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert all(len(r) == len(rows[0]) for r in rows)
    result = milldyn.Model(str(model)).run(out=tmp_path / "r")
    with open(tmp_path / "r" / "timeseries.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == result.table.headers()
    assert all(len(r) == len(rows[0]) for r in rows)


def test_a_path_swept_twice_or_set_and_swept_is_refused():
    with pytest.raises(milldyn.ModelError, match="is set and swept"):
        milldyn.sweep(milldyn.Model(IDLE, set=dict(SHORT, **{"elements.grinding.constant_torque": "5 N*m"})),
                      grid={"elements.grinding.constant_torque": ("10 N*m", "20 N*m", 2)})
    with pytest.raises(milldyn.ModelError, match="swept twice"):
        milldyn.sweep(milldyn.Model(IDLE, set=SHORT),
                      grid={("elements.grinding.constant_torque", "elements.grinding.constant_torque"): (1, 2, 2)})


# ---- issue 26 item 10 -------------------------------------------------------

def test_to_si_raises_unit_error_as_documented():
    assert milldyn.to_si("1500 rpm", "rad/s") == pytest.approx(157.07963267948966)
    for text, unit in (("12 N*m", "rpm"), ("12 N*m", "xyz"), ("12 N*m", "rad/s"), ("twelve", "N*m")):
        with pytest.raises(milldyn.UnitError):
            milldyn.to_si(text, unit)


def test_a_lone_surrogate_gives_a_clean_error():
    with pytest.raises(milldyn.UnitError, match="lone surrogate"):
        milldyn.to_si("12 \udc80", "N*m")
    with pytest.raises(milldyn.UnitError, match="lone surrogate"):
        milldyn.quantity("12 N*\udc80")
    with pytest.raises(milldyn.ModelError, match="lone surrogate"):
        milldyn.Model(IDLE, set={"elements.grinding.constant_torque": "12 N*m\udc80"})
    with pytest.raises(milldyn.ModelError, match="lone surrogate"):
        milldyn.Model(IDLE, set={"elements.\udc80.constant_torque": "12 N*m"})
    with pytest.raises(milldyn.ModelError, match="lone surrogate"):
        milldyn.sweep(IDLE, grid={"elements.grinding.constant_torque": ("1 N*m", "2 N*m\udcff", 2)})
    # A file name that is not UTF-8 (surrogateescape) is a file name: it opens.
    with pytest.raises(FileNotFoundError):
        milldyn.Model(os.fsdecode(b"/nonexistent/\xff.yaml"))


def test_a_grid_count_must_be_a_whole_number():
    for n in (2.5, "3", None, True):
        with pytest.raises(milldyn.ModelError, match="whole number"):
            milldyn.sweep(IDLE, grid={"elements.grinding.constant_torque": ("10 N*m", "20 N*m", n)})


def test_a_sweep_whose_every_point_failed_raises_as_the_cli_exits_1(tmp_path):
    with pytest.raises(milldyn.AnalysisFailed, match="every one of its 2 points failed"):
        milldyn.sweep(milldyn.Model(IDLE, set=SHORT), grid={"integrator.accuracy": (1, 2, 2)}, jobs=1)
    r = subprocess.run([BIN, "sweep", IDLE, "--grid", "integrator.accuracy=1:2:2", "--jobs", "1", "--out",
                        str(tmp_path / "cli")], capture_output=True, text=True)
    assert r.returncode == 1


# ---- issue 29 item 4: sweeps as people ask them ------------------------------

def test_value_lists_log_grids_and_tied_paths():
    model = milldyn.Model(IDLE, set=SHORT)
    t = milldyn.sweep(model, grid={"elements.grinding.constant_torque": ["10 N*m", "14 N*m", "12 N*m"]}, jobs=1)
    assert list(t["elements.grinding.constant_torque"]) == [10, 14, 12]
    t = milldyn.sweep(model, grid={"elements.grinding.constant_torque": (1, 100, 3, "log")}, jobs=1)
    assert list(t["elements.grinding.constant_torque"]) == [1, 10, 100]
    # Two paths on one axis, each its own values: 3 points, not 9.
    t = milldyn.sweep(model, grid={("elements.grinding.constant_torque", "elements.motor.rated_torque"):
                                   [("10 N*m", "12 N*m", 3), ["36 N*m", "37 N*m", "38 N*m"]]}, jobs=1)
    assert len(t) == 3
    assert list(t["elements.motor.rated_torque"]) == [36, 37, 38]
    assert list(t["elements.grinding.constant_torque"]) == [10, 11, 12]
    # One spec for both tied paths.
    t = milldyn.sweep(model, grid={("elements.grinding.constant_torque", "elements.grinding.viscous_coefficient"):
                                   (0, 0.01, 2)}, jobs=1)
    assert len(t) == 2 and list(t["elements.grinding.viscous_coefficient"]) == [0, 0.01]
    # The run options apply to every point.
    t = milldyn.sweep(model, grid={"elements.grinding.constant_torque": [10, 12]}, accuracy=1e-5, end_time=0.2,
                      jobs=1)
    assert list(t["status"]) == ["ok", "ok"]


def test_progress_callback_and_cancel(tmp_path):
    model = milldyn.Model(IDLE, set=SHORT)
    seen = []
    t = milldyn.sweep(model, grid={"elements.grinding.constant_torque": ("10 N*m", "13 N*m", 4)}, jobs=1,
                      progress=lambda done, total, failed: seen.append((done, total, failed)))
    assert len(t) == 4
    assert seen and seen[-1] == (4, 4, 0)
    assert [d for d, _, _ in seen] == sorted(d for d, _, _ in seen)
    # progress returning False stops the sweep: Cancelled, finished points kept.
    # Points of about 0.5 s each (progress is polled every 50 ms, so a point
    # shorter than that could all finish before the first call).
    slow = milldyn.Model(IDLE, set={"elements.motor.switch_off_time": "1000 s", "scenario.end_time": "150 s",
                                    "outputs.plots": "false"})
    with pytest.raises(milldyn.Cancelled):
        milldyn.sweep(slow, grid={"elements.grinding.constant_torque": ("10 N*m", "13 N*m", 4)}, jobs=1,
                      out=tmp_path / "stopped", progress=lambda done, total, failed: done < 1)
    kept = os.listdir(tmp_path / "stopped" / "points")
    assert 1 <= len(kept) < 4
    assert not os.path.exists(tmp_path / "stopped" / "sweep.csv")
    # ... and resume: the kept points are reused.
    t = milldyn.sweep(slow, grid={"elements.grinding.constant_torque": ("10 N*m", "13 N*m", 4)}, jobs=1,
                      out=tmp_path / "stopped")
    assert t.summary["resumed"] == len(kept)
    # A CancelToken set from another thread.
    token = milldyn.CancelToken()
    long = milldyn.Model(IDLE, set={"elements.motor.switch_off_time": "1000 s", "scenario.end_time": "200 s",
                                    "outputs.plots": "false"})
    threading.Timer(0.5, token.cancel).start()
    with pytest.raises(milldyn.Cancelled):
        milldyn.sweep(long, grid={"elements.grinding.constant_torque": ("10 N*m", "12 N*m", 2)}, jobs=1, cancel=token)


# ---- issue 29 item 5: Python as its users expect ------------------------------

def test_a_missing_file_is_a_file_not_found_error(tmp_path):
    with pytest.raises(FileNotFoundError) as e:
        milldyn.Model(tmp_path / "nope.yaml")
    assert isinstance(e.value, milldyn.ModelError)
    assert e.value.filename == str(tmp_path / "nope.yaml")
    assert "nope.yaml" in str(e.value)
    model = tmp_path / "m.yaml"
    model.write_text("format_version: 1\nname: m\ninclude: parts/missing.yaml\n")
    with pytest.raises(FileNotFoundError):
        milldyn.Model(model)


def test_unknown_names_suggest_the_nearest():
    r = milldyn.Model(IDLE, set=SHORT).run()
    name = next(iter(r.summary))
    with pytest.raises(KeyError, match="did you mean %r" % name):
        r.summary[name[:-1]]
    column = r.table.names[1]
    with pytest.raises(KeyError, match="did you mean"):
        r.table[column + "x"]
    with pytest.raises(KeyError, match="unknown table"):
        r.tables["timeseries2"]


def test_the_namespace_holds_milldyns_names_only():
    public = {n for n in dir(milldyn) if not n.startswith("_")}
    for module in ("os", "sys", "csv", "shutil", "tempfile", "threading", "collections", "difflib"):
        assert module not in public, module
    assert set(milldyn.__all__) <= public


def test_repr_of_a_result_is_short_and_matrices_are_documented():
    r = milldyn.Model(IDLE, set=SHORT).run()
    assert len(repr(r)) < 400, repr(r)
    assert "results)" in repr(r) or len(r.summary) <= 4
    lin = milldyn.Model(os.path.join(SRC, "models", "roll_crusher.yaml"), scenario="modes",
                        set={"outputs.plots": "false"}).run()
    assert lin.matrices, "a linearize run has matrices"
    for name, m in lin.matrices.items():
        assert isinstance(m, milldyn.Matrix)
        values, unit = m  # still unpacks as (array, unit)
        assert values is m.values and unit == m.unit
        assert values.shape[0] == values.shape[1]
        assert "Matrix" in repr(m) and unit in repr(m)
    with pytest.raises(KeyError, match="unknown matrix"):
        lin.matrices["Q"]


def test_value_keeps_its_unit_under_arithmetic_or_refuses():
    t = milldyn.Value(20.0, "N*m")
    assert (t + 5).unit == "N*m" and float(t + 5) == 25
    assert (t - milldyn.Value(5, "N*m")).unit == "N*m"
    assert (2 * t).unit == "N*m" and (t / 4).unit == "N*m"
    assert (-t).unit == "N*m" and abs(-t).unit == "N*m"
    assert (t / milldyn.Value(10, "N*m")).unit == "1"
    # A torque times an angular speed reads as a power (issue 29 item 5, round two).
    assert (t * milldyn.Value(3, "rad/s")).unit == "W"
    with pytest.raises(milldyn.UnitError):
        t + milldyn.Value(1, "rad/s")
    with pytest.raises(milldyn.UnitError):
        t ** 2
    assert float(t) ** 2 == 400
    assert sum([t, t]).unit == "N*m"


def test_quantity_prints_the_units_it_was_written_in_as_si():
    q = milldyn.quantity("20 kN*m")
    assert float(q) == 20000 and q.unit == "N*m"
    assert repr(q) == "20000.0 N*m"
    assert milldyn.quantity("1500 rpm").unit == "rad/s"
    assert milldyn.quantity("5 %").unit == "1" and float(milldyn.quantity("5 %")) == 0.05
    assert milldyn.quantity("3 mm/min").unit == "m/s"
    assert milldyn.quantity("537 N*m/rad").unit == "N*m/rad"
    assert milldyn.quantity("2.5").unit == "1"
    with pytest.raises(milldyn.UnitError):
        milldyn.quantity("20 kN*mx")
