"""Issue 29 item 8 from Python: milldyn.front (the error-cost front of any
model, presets written beside it) and Model.run(check_resolution=True), the
same code as `milldyn front` and `milldyn run --check-resolution`
(driver/Front.h; the C++ tests are tests/driver/FrontTest.cpp).

The model: tests/driver/FrontTest.cpp's stiff-shaft start (a 15 kW Kloss
motor, 0.12 + 0.3 kg*m^2, shaft 2e5 N*m/rad, 20 N*m load, 3 s): at
RungeKuttaMerson 1e-3 its shaft peak is 630 N*m against 179.7 N*m at 1e-6
and 1e-10. Run by ctest (test `python`).
"""

import os

import milldyn

SRC = os.environ.get("MILLDYN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
STIFF = open(os.path.join(SRC, "tests", "testdata", "front", "stiff_shaft_start.yaml")).read()


def test_front_writes_presets_that_a_run_uses_and_the_resolution_check_warns(tmp_path):
    path = tmp_path / "stiff.yaml"
    path.write_text(STIFF)
    f = milldyn.front(str(path), integrators=["RungeKuttaMerson"], accuracies=[1e-3, 1e-6, 1e-9],
                      write_presets=True)
    assert [p["accuracy"] for p in f["points"]] == [1e-3, 1e-6, 1e-9]
    assert all(p["status"] == "ok" for p in f["points"])
    for p in f["points"]:
        assert p["worst"] == max(p["peak_error"], p["ripple_error"], p["speed_error"], p["time_error"], p["energy"])
    # 1e-3 misses the ringing shaft's peak by far (630 against 179.7 N*m).
    assert f["points"][0]["peak_error"] > 1
    balanced = f["presets"]["balanced"]
    assert balanced is not None and f["points"][balanced]["worst"] <= f["targets"]["balanced"] == 1e-3
    assert os.path.exists(f["presets_file"])
    model = milldyn.Model(str(path))
    chosen = model.run(preset="balanced", on_failure="raise")
    assert chosen.verdict.ok
    assert any(n.startswith("preset balanced: RungeKuttaMerson") for n in chosen.notes), chosen.notes
    # The model's own accuracy (1e-3) does not resolve the shaft's peak.
    loose = model.run(check_resolution=True)
    assert any(n.startswith("warning: peak.shaft.torque") and "not resolved" in n for n in loose.notes), loose.notes
    tight = model.run(accuracy=1e-8, check_resolution=True)
    assert any(n.startswith("resolution:") and "each within 1 %" in n for n in tight.notes), tight.notes
    assert not any("not resolved" in n for n in tight.notes)
