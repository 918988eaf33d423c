"""The Python module against the CLI: the same numbers bit for bit, the same
error lines, parallel runs from threads, cancellation and Ctrl-C.

Run by ctest (test `python`) with Debian's python3 and PYTHONPATH at the
build tree's python/; MILLDYN_BINARY is the CLI built beside the module.
"""

import csv
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import threading

import numpy as np
import pytest

import milldyn

SRC = os.environ.get("MILLDYN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BIN = os.environ.get("MILLDYN_BINARY", os.path.join(SRC, "build", "milldyn"))
PLUGIN = os.environ.get("MILLDYN_EXAMPLE_PLUGIN", "")
IDLE = os.path.join(SRC, "models", "burr_mill_5p5kW_idle.yaml")
# A run long enough to be stopped: the motor never switched off.
LONG = {"elements.motor.switch_off_time": "1000 s", "scenario.end_time": "200 s", "outputs.plots": "false"}


def cli(*args, cwd=None):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, cwd=cwd)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def cli_sets(overrides):
    out = []
    for path, value in overrides.items():
        out += ["--set", "%s=%s" % (path, value)]
    return out


def test_run_is_bit_identical_to_the_cli(tmp_path, monkeypatch):
    overrides = {"elements.grinding.constant_torque": "20 N*m", "scenario.end_time": "5.5 s",
                 "outputs.plots": "false"}
    r = cli("run", IDLE, "--out", tmp_path / "cli", "--quiet", *cli_sets(overrides))
    assert r.returncode == 0, r.stderr
    header, rows = read_csv(tmp_path / "cli" / "timeseries.csv")

    cwd = tmp_path / "cwd"
    cwd.mkdir()
    monkeypatch.chdir(cwd)
    result = milldyn.Model(IDLE, set=overrides).run()
    assert os.listdir(cwd) == []  # nothing written unless asked

    assert result.analysis == "transient"
    assert result.table.headers() == header
    assert len(result.table) == len(rows) > 1000
    for i, name in enumerate(result.table.names):
        column = np.array([row[i] for row in rows])
        assert np.array_equal(result.table[name], column), name  # exact, not close

    with open(tmp_path / "cli" / "summary.json") as f:
        summary = json.load(f)
    assert set(result.summary) == set(summary["results"])
    for name, value in result.summary.items():
        assert float(value) == summary["results"][name]["value"], name
        assert value.unit == summary["results"][name]["unit"], name
    assert result.notes == summary["notes"]
    assert result.statistics["steps"] == summary["statistics"]["steps"]
    ours = json.loads(result.summary_json())
    del ours["run"], summary["run"]
    assert ours == summary

    # run(out=...) writes the CLI's files, byte for byte.
    written = milldyn.Model(IDLE, set=overrides).run(out=tmp_path / "py").files
    assert str(tmp_path / "py" / "timeseries.csv") in written
    with open(tmp_path / "cli" / "timeseries.csv", "rb") as a, open(tmp_path / "py" / "timeseries.csv", "rb") as b:
        assert a.read() == b.read()


def test_numbers_are_si_and_text_has_units():
    # 20 N*m as an SI number, as text, and as text in another unit.
    a = milldyn.Model(IDLE, set={"elements.grinding.constant_torque": 20.0, "scenario.end_time": 4.5}).run()
    b = milldyn.Model(IDLE, set={"elements.grinding.constant_torque": "20 N*m", "scenario.end_time": "4500 ms"}).run()
    assert np.array_equal(a.table["millstone.speed"], b.table["millstone.speed"])
    assert a.table.units["millstone.speed"] == "rad/s"
    assert a.summary["resistance_torque"] == 20.0 and a.summary["resistance_torque"].unit == "N*m"
    assert milldyn.to_si("1500 rpm", "rad/s") == pytest.approx(1500 * 2 * math.pi / 60, rel=1e-15)
    q = milldyn.quantity("20 kN*m")
    assert float(q) == 20000.0 and q.unit == "N*m"  # the SI units of the names written (issue 29 item 5)
    with pytest.raises(milldyn.UnitError, match="did you mean 'rpm'"):
        milldyn.to_si("1500 rmp", "rad/s")


def test_to_pandas_names_without_units():
    result = milldyn.Model(IDLE, set={"scenario.end_time": "4.2 s"}).run()
    df = result.to_pandas()
    assert list(df.columns) == result.table.names
    assert all("[" not in c for c in df.columns)
    assert df.attrs["units"]["time"] == "s"
    assert np.array_equal(df["motor_shaft.speed"].to_numpy(), result.table["motor_shaft.speed"])


def test_bad_input_raises_model_error_with_the_cli_text(tmp_path):
    bad = tmp_path / "bad.yaml"
    with open(IDLE) as f:
        bad.write_text(f.read().replace("rated_speed: 1446 rpm", "rated_speed: 1446 rmp"))
    r = cli("run", bad, "--out", tmp_path / "o")
    assert r.returncode == 2
    with pytest.raises(milldyn.ModelError) as e:
        milldyn.Model(bad)
    assert e.value.text == r.stderr.strip() == str(e.value)
    assert e.value.file == str(bad)
    line = 1 + [i for i, text in enumerate(bad.read_text().splitlines()) if "1446 rmp" in text][0]
    assert e.value.line == line and e.value.key.endswith("rated_speed")
    assert e.value.column > 0 and "rmp" in e.value.reason
    assert e.value.text.startswith("%s:%d:%d: error: " % (bad, e.value.line, e.value.column))

    # A bad override: the same line as --set prints.
    r = cli("info", IDLE, "--set", "elements.grinding.constant_torque=20 N*x")
    with pytest.raises(milldyn.ModelError) as e:
        milldyn.Model(IDLE, set={"elements.grinding.constant_torque": "20 N*x"})
    assert r.returncode == 2 and e.value.text == r.stderr.strip()
    # ... also when the override comes with run().
    model = milldyn.Model(IDLE)
    with pytest.raises(milldyn.ModelError):
        model.run(set={"elements.nothing.stiffness": 3})
    with pytest.raises(milldyn.ModelError, match="scenario"):
        milldyn.Model(IDLE, scenario="no_such_scenario")
    with pytest.raises(milldyn.ModelError):
        milldyn.Model(tmp_path / "missing.yaml")
    with pytest.raises(TypeError):
        milldyn.Model(IDLE, set={"scenario.end_time": object()})
    with pytest.raises(TypeError):
        milldyn.Model(IDLE, set={"scenario.end_time": [1, 2]})


def test_info_is_what_the_cli_shows():
    info = milldyn.Model(IDLE).info()
    r = cli("info", IDLE)
    assert r.returncode == 0
    assert "bodies: %d, mobilities (DOF): %d, constraints: %d, forces: %d" % (
        info["bodies"], info["mobilities"], info["constraints"], info["forces"]) in r.stdout
    for name, type_ in info["elements"]:
        assert "element %s: %s" % (name, type_) in r.stdout
    assert "time integration: " + info["time_integration"] in r.stdout
    assert "outputs: " + " ".join("%s[%s]" % o for o in info["outputs"]) in r.stdout
    assert [b["name"] for b in info["body_list"]] == ["motor_shaft", "millstone"]
    assert info["warnings"] == [] and info["notes"] == []
    # What each element registered, as the CLI lists it: the motor's torque probe on its shaft.
    motor_type, motor_items = info["contributions"]["motor"]
    assert motor_type == "InductionMotor"
    assert ("probe", "motor.torque", "motor_shaft", "[N*m], drive torque") in motor_items
    assert "      probe motor.torque [N*m], drive torque, on motor_shaft\n" in r.stdout
    # A reader note, as the CLI prints it: switching the analysis drops the keys it does not take.
    switched = milldyn.Model(IDLE, set={"scenario.analysis": "linearize"}).info()
    assert switched["notes"] and "note: " + switched["notes"][0] in cli("info", IDLE, "--set", "scenario.analysis=linearize").stdout


def _run_into(results, key, overrides, token=None):
    try:
        results[key] = milldyn.Model(IDLE, set=overrides).run(cancel=token)
    except BaseException as e:  # reported by the test
        results[key] = e


def test_threads_run_models_in_parallel():
    sets = [{"elements.grinding.constant_torque": "%d N*m" % m, "scenario.end_time": "5 s"} for m in (12, 20)]
    alone = [milldyn.Model(IDLE, set=s).run() for s in sets]
    results = {}
    token = milldyn.CancelToken()
    threads = [threading.Thread(target=_run_into, args=(results, i, s, token if i == 0 else None))
               for i, s in enumerate(sets)]
    for t in threads:
        t.start()
    # The main thread runs Python while a run is under way: the run does not
    # hold the GIL (a run holding it would let this loop see only 0 or the end).
    seen_midway = False
    while threads[0].is_alive():
        reached, end = token.progress
        if 0 < reached < end:
            seen_midway = True
    for t in threads:
        t.join()
    assert seen_midway
    for i in range(2):
        assert isinstance(results[i], milldyn.Result), results[i]
        assert np.array_equal(results[i].table["millstone.speed"], alone[i].table["millstone.speed"])
        assert results[i].summary == alone[i].summary


def test_cancel_token_stops_a_run_from_another_thread():
    token = milldyn.CancelToken()
    results = {}
    t = threading.Thread(target=_run_into, args=(results, 0, LONG, token))
    t.start()
    while t.is_alive() and token.progress[0] < 0.5:
        pass
    token.cancel()
    t.join()
    assert isinstance(results[0], milldyn.Cancelled), results[0]
    reached, end = token.progress
    assert 0.5 <= reached < end == 200
    # The module is fine afterwards.
    assert milldyn.Model(IDLE, set={"scenario.end_time": "4.1 s"}).run().summary["steady_speed"] > 150


def test_keyboard_interrupt_stops_a_run_cleanly():
    token = milldyn.CancelToken()  # only to see how far the run got

    done = threading.Event()

    def interrupt():
        while token.progress[0] < 0.5 and not done.is_set():
            pass
        if not done.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=interrupt)
    sender.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            milldyn.Model(IDLE, set=LONG).run(cancel=token)
    finally:
        done.set()
        sender.join()
    reached, end = token.progress
    assert 0.5 <= reached < end == 200
    assert milldyn.Model(IDLE, set={"scenario.end_time": "4.1 s"}).run().summary["steady_speed"] > 150


def test_sweep_gives_the_cli_table(tmp_path, monkeypatch):
    base = {"scenario.end_time": "4.5 s", "outputs.plots": "false"}
    r = cli("sweep", IDLE, "--grid", "elements.grinding.constant_torque=10 N*m:30 N*m:3", "--jobs", "2",
            "--out", tmp_path / "cli", "--quiet", *cli_sets(base))
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "cli" / "sweep.csv", newline="") as f:
        rows = list(csv.reader(f))
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path / "tmp"))
    os.mkdir(tmp_path / "tmp")
    table = milldyn.sweep(milldyn.Model(IDLE, set=base),
                          grid={"elements.grinding.constant_torque": ("10 N*m", "30 N*m", 3)}, jobs=2)
    assert os.listdir(tmp_path / "tmp") == []  # the working directory is gone
    assert table.headers() == rows[0]
    # 30 N*m is more than the Kloss motor gives at standstill (0.65·36.3 = 23.6 N*m): that start stalls.
    assert len(table) == 3 and list(table["status"]) == ["ok", "ok", "stalled"]
    for i, name in enumerate(table.names):
        for k, row in enumerate(rows[1:]):
            if name in ("status", "diagnostic"):
                assert table[name][k] == row[i]
            elif row[i] == "":  # a result the point has not (a stalled start prints no steady values)
                assert math.isnan(table[name][k]), name
            else:
                assert table[name][k] == float(row[i]), name
    assert table.units["elements.grinding.constant_torque"] == "N*m"
    assert table.summary["total"] == 3

    lhs = milldyn.sweep(IDLE, lhs=3, ranges={"scenario.end_time": (4.2, 4.6)}, seed=7, jobs=2)
    assert len(lhs) == 3 and all(4.2 <= v <= 4.6 for v in lhs["scenario.end_time"])
    assert lhs.units["scenario.end_time"] == "SI"
    # Bare numbers are SI at every point (they failed at every point once,
    # read like a command line's unit-less value).
    assert list(lhs["status"]) == ["ok"] * 3, lhs["diagnostic"]
    with pytest.raises(ValueError, match="--lhs"):
        milldyn.sweep(IDLE, lhs=3)
    with pytest.raises(milldyn.ModelError):
        milldyn.sweep(IDLE, grid={"scenario.end_time": "1:2:0"})


def test_validate_gives_the_cli_rows():
    r = cli("validate", "--filter", "burr_mill_coastdown", "--json")
    assert r.returncode == 0, r.stderr
    expected = json.loads(r.stdout)
    rows = milldyn.validate("burr_mill_coastdown")
    assert len(rows) == len(expected) > 0
    for ours, theirs in zip(rows, expected):
        assert ours["case"] == theirs["case"]
        assert ours["status"] == theirs["status"]
        assert ours["oracle"] == theirs["oracle"]
        assert ours["multibody"] == theirs.get("multibody")


def test_elements_lists_every_registered_type_with_keys_units_defaults_ranges():
    types = milldyn.elements()
    for t in ("InductionMotor", "TorsionalCoupling", "ResistanceTorque", "GearMesh", "SegmentCharge",
              "BeltDrive", "JournalFriction", "JointReaction", "DiscDrag", "FlexibleRotor", "CarrierDrive"):
        assert t in types, t
    stiffness = types["TorsionalCoupling"]["keys"]["stiffness"]
    assert stiffness["unit"] == "N*m/rad" and stiffness["kind"] == "quantity"
    assert stiffness["min"] is not None
    law = types["ResistanceTorque"]["keys"]["law"]
    assert law["kind"] == "choice" and "speed_linear" in law["choices"]
    optional = [k for t in types.values() for k in t["keys"].values() if not k["required"]]
    assert optional and all(k["default"] is not None for k in optional if k["kind"] == "quantity")
    assert "transient" in milldyn.analyses() and "coastdown_identify" in milldyn.analyses()


@pytest.mark.skipif(not PLUGIN, reason="MILLDYN_EXAMPLE_PLUGIN not set")
def test_plugin_element_runs():
    model = milldyn.Model(os.path.join(SRC, "tests", "testdata", "plugin_constant_torque.yaml"), plugins=[PLUGIN])
    assert "ConstantTorque" in milldyn.elements()
    # ω(1 s) = M·t/J = 3·1/2 = 1.5 rad/s (the closed form of PluginTest).
    # Constant torque on an inertia never settles: the verdict is unfinished and the speed is the end value.
    assert model.run().summary["speed_at_end"] == pytest.approx(1.5, abs=1e-12)


@pytest.mark.skipif(not os.environ.get("MILLDYN_BUILD_DIR"), reason="MILLDYN_BUILD_DIR not set")
def test_installs_into_a_prefix(tmp_path):
    import sys
    r = subprocess.run([os.environ.get("MILLDYN_CMAKE", "cmake"), "--install", os.environ["MILLDYN_BUILD_DIR"],
                        "--prefix", str(tmp_path / "prefix")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    site = tmp_path / "prefix" / "lib" / "python3" / "dist-packages"
    code = ("import milldyn; print(milldyn.__file__); "
            "print(milldyn.Model(%r, set={'scenario.end_time': '4.1 s'}).run().summary['steady_speed'].unit)" % IDLE)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path,
                       env=dict(os.environ, PYTHONPATH=str(site)))
    assert r.returncode == 0, r.stderr
    assert r.stdout.split("\n")[:2] == [str(site / "milldyn" / "__init__.py"), "rad/s"]


def test_a_failed_analysis_raises_with_the_cli_text(tmp_path):
    # Semi-explicit Euler at 100 ms steps on the belt mode (about 180 rad/s):
    # far outside its stability limit (omega*h < 2), the motion overflows.
    unstable = {"integrator.name": "SemiExplicitEuler", "integrator.max_step": "100 ms",
                "elements.motor.switch_off_time": "100 s", "scenario.end_time": "100 s", "outputs.plots": "false"}
    r = cli("run", IDLE, "--out", tmp_path / "o", *cli_sets(unstable))
    assert r.returncode == 1
    with pytest.raises(milldyn.AnalysisFailed) as e:
        milldyn.Model(IDLE, set=unstable).run(out=tmp_path / "py")
    assert e.value.text == r.stderr.strip()
    assert "not finite" in e.value.reason and "t = " in e.value.reason and "motor_shaft" in e.value.reason
    assert not (tmp_path / "py").exists()


def test_sigint_stops_a_sweep_with_keyboard_interrupt(tmp_path):
    # Issue 16: Ctrl-C during milldyn.sweep() was ignored until every point
    # had run. In a child Python: SIGINT while the first of three 200 s
    # points runs must raise KeyboardInterrupt there and then, leave no
    # table and no temporaries, and keep only finished point files.
    out = tmp_path / "sweep"
    code = (
        "import sys, milldyn\n"
        "print('started', flush=True)\n"
        "try:\n"
        "    milldyn.sweep(milldyn.Model(%r, set=%r), grid={'elements.grinding.constant_torque': ('10 N*m', '12 N*m', 3)},\n"
        "                  jobs=1, out=%r)\n"
        "except KeyboardInterrupt:\n"
        "    print('KeyboardInterrupt', flush=True)\n"
        "    sys.exit(3)\n"
        "print('finished', flush=True)\n" % (IDLE, LONG, str(out)))
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(milldyn.__file__)))
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=env)
    assert child.stdout.readline().strip() == "started"
    # Interrupt once the first point is integrating (its directory claimed).
    for _ in range(600):
        if (out / "sweep-plan.json").exists():
            break
        threading.Event().wait(0.05)
    threading.Event().wait(0.5)
    child.send_signal(signal.SIGINT)
    try:
        stdout, stderr = child.communicate(timeout=120)  # uninterrupted: three 200 s runs
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        pytest.fail("the sweep did not stop on SIGINT")
    assert child.returncode == 3, stdout + stderr
    assert "KeyboardInterrupt" in stdout
    names = os.listdir(out)
    assert "sweep.csv" not in names
    assert not [n for n in names if ".tmp." in n or "staging" in n], names
    points = os.listdir(out / "points")
    assert not [n for n in points if ".tmp." in n], points
    assert len(points) < 3
