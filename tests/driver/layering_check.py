#!/usr/bin/env python3
"""The library layers of CMakeLists.txt and what generic code may name (issue 31 items 4, 6).

  milldyn_driver_lib        model files, scenes, analyses, outputs
  milldyn_validation_cases  validation/cases, validation/report (over the driver)
  milldyn_api               driver/Api, Sweep, Front (over both)
  milldyn_cli               driver/Cli (over the Api); the Python module is over the Api too

Fails when
  1. a file of the driver library includes a header of a layer above it;
  2. python/bindings.cpp or driver/Cli.cpp reaches past driver/Api into the
     element registry or the validation cases;
  3. generic code (driver/, plugins/scene/) names an element type in a string
     literal, outside the list below of the places not yet moved onto a
     capability (each says why it is still there). The list may only shrink:
     an entry that no longer matches fails too, so it is removed when fixed.

Usage: layering_check.py SOURCE_DIR
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1])
# The built-in types, by their register functions (plugins/scene/BuiltinElements.cpp).
ELEMENT_TYPES = sorted(set(re.findall(r"void register(\w+)\(ElementRegistry& registry\);",
                                      (ROOT / "plugins/scene/BuiltinElements.cpp").read_text())) - {"BuiltinElements"})
# Not yet a capability (issue 31 item 4, open): file -> the types it names.
KNOWN = {
    # The near-centrifuging warning and the frozen charge's verdict read
    # SegmentCharge's outputs by name (a result-check hook per element type
    # would serve; it needs AnalysisResult below the plugins).
    "driver/analyses/Analysis.cpp": {"SegmentCharge"},
    "driver/analyses/Transient.cpp": {"SegmentCharge"},
    # Energy categories by element type (a category field on EnergyFlow
    # would serve).
    "plugins/scene/EnergyMeter.cpp": {"InductionMotor", "DqInductionMotor", "JournalFriction", "ShaftBearings", "Brake",
                                      "Clutch", "TorsionalCoupling", "BeltDrive", "GearPair", "GearMesh",
                                      "FlexibleRotor"},
}

failures = []


def includes(path):
    return re.findall(r'^\s*#include\s+"([^"]+)"', path.read_text(), re.M)


cmake = (ROOT / "CMakeLists.txt").read_text()
block = re.search(r"add_library\(milldyn_driver_lib STATIC(.*?)\)", cmake, re.S).group(1)
driver_sources = block.split()
if len(driver_sources) < 20:
    failures.append(f"CMakeLists.txt: milldyn_driver_lib lists only {len(driver_sources)} sources (parse error?)")
above = re.compile(r"^(validation/cases/|validation/report/|driver/(Api|Sweep|SweepMpi|Front|Cli)\.h$)")
for src in driver_sources:
    for path in [ROOT / src, (ROOT / src).with_suffix(".h")]:
        if not path.exists():
            continue
        for inc in includes(path):
            if above.match(inc):
                failures.append(f"{path.relative_to(ROOT)}: includes {inc}, a layer above milldyn_driver_lib")

for front in ["python/bindings.cpp", "driver/Cli.cpp"]:
    for inc in includes(ROOT / front):
        if inc.startswith("validation/") or inc == "plugins/scene/ElementRegistry.h":
            failures.append(f"{front}: includes {inc}: the registry and the validation cases are reached through driver/Api")
    text = (ROOT / front).read_text()
    for word in ["ElementRegistry::", "runValidationCases("]:
        if word in text:
            failures.append(f"{front}: uses {word} directly, not through driver/Api")

if len(ELEMENT_TYPES) < 20:
    failures.append(f"found only {len(ELEMENT_TYPES)} element types in plugins/scene/BuiltinElements.cpp")
generic = sorted(list(ROOT.glob("driver/**/*.cpp")) + list(ROOT.glob("driver/**/*.h")) +
                 [p for p in ROOT.glob("plugins/scene/*") if p.name != "BuiltinElements.cpp"])
for path in generic:
    rel = str(path.relative_to(ROOT))
    text = path.read_text()
    code = re.sub(r"//[^\n]*", "", text)
    named = {t for t in ELEMENT_TYPES if f'"{t}"' in code}
    allowed = KNOWN.get(rel, set())
    for t in sorted(named - allowed):
        failures.append(f"{rel}: names the element type \"{t}\" (generic code asks a capability, not a type)")
    for t in sorted(allowed - named):
        failures.append(f"{rel}: no longer names \"{t}\": remove it from KNOWN in tests/driver/layering_check.py")
for rel in KNOWN:
    if not (ROOT / rel).exists():
        failures.append(f"{rel}: listed in KNOWN but gone")

for f in failures:
    print(f)
print(f"layering: {len(driver_sources)} driver sources, {len(ELEMENT_TYPES)} element types, "
      f"{sum(len(v) for v in KNOWN.values())} known type names in {len(KNOWN)} generic files; "
      f"{len(failures)} problems")
sys.exit(1 if failures else 0)
