"""milldyn from Python: the same models, runs, sweeps and validation as the
``milldyn`` command line, through the same C++ code (docs/python.md).

    import milldyn
    model = milldyn.Model("models/burr_mill_5p5kW_idle.yaml",
                          set={"elements.grinding.constant_torque": "20 N*m"})
    result = model.run()
    result.summary["runout_time"]        # 1.12... s  (a float with .unit)
    result.table["millstone.speed"]      # numpy array; result.table.units[...]
    df = result.to_pandas()              # columns without [unit]; df.attrs["units"]

Values may be given as text with units ("20 N*m", "1500 rpm") or as numbers
in SI; every result says its unit. Runs release the GIL (threads run models
in parallel); Ctrl-C stops a run on the main thread at its next sample, and
a CancelToken stops one from any thread.
"""

import csv
import os
import shutil
import sys
import tempfile
import threading

# Plugin libraries (plugins=[...]) resolve the registry's symbols from the
# module, as they do from the milldyn executable: load it RTLD_GLOBAL.
_flags = sys.getdlopenflags()
sys.setdlopenflags(_flags | os.RTLD_GLOBAL)
try:
    from . import _milldyn as _core
finally:
    sys.setdlopenflags(_flags)

from .errors import AnalysisFailed, Cancelled, MilldynError, ModelError, OutputFailed, UnitError  # noqa: E402

import numpy as _np  # noqa: E402

__version__ = _core.__version__
CancelToken = _core.CancelToken

__all__ = ["Model", "Result", "Table", "Value", "CancelToken", "sweep", "validate", "elements", "analyses",
           "load_plugin", "to_si", "quantity", "ModelError", "AnalysisFailed", "OutputFailed", "Cancelled",
           "UnitError", "MilldynError"]


class Value(float):
    """A number with its unit (and a line saying what it is): ``float(v)`` is
    the value in ``v.unit``."""

    def __new__(cls, value, unit, doc=""):
        self = super().__new__(cls, value)
        self.unit = unit
        self.doc = doc
        return self

    def __repr__(self):
        return "%r %s" % (float(self), self.unit)

    def __reduce__(self):
        return (Value, (float(self), self.unit, self.doc))


def _text(value):
    """An override's value text: strings as written (with their units),
    numbers (SI) with every digit, so they reach the model exactly."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    if isinstance(value, (int, _np.integer)):
        return str(int(value))
    if isinstance(value, (float, _np.floating)):
        return repr(float(value))
    raise TypeError("an override's value must be one number (SI) or text with a unit, got %r" % (value,))


def _is_si_number(value):
    return not isinstance(value, (bool, str)) and isinstance(value, (int, float, _np.integer, _np.floating))


def _overrides(set=None, scenario=None, preset=None, **options):
    """(path, text, si) triples: si says the text is a bare SI number (a
    Python number), which the reader takes without a unit; text with units
    is read as the CLI reads --set."""
    out = []
    if scenario is not None:
        out.append(("use_scenario", str(scenario), False))
    if preset is not None:
        out.append(("preset", str(preset), False))
    for path, value in (set or {}).items():
        out.append((str(path), _text(value), _is_si_number(value)))
    for key, path in (("integrator", "integrator.name"), ("accuracy", "integrator.accuracy"),
                      ("end_time", "scenario.end_time")):
        if options.get(key) is not None:
            out.append((path, _text(options[key]), _is_si_number(options[key])))
    return out


class Table:
    """Columns by name (numpy arrays) with their units.

    ``table["time"]`` is a column, ``table.units["time"]`` its unit,
    ``table.names`` the columns in order; ``to_pandas()`` a DataFrame with
    the same column names and the units in ``df.attrs["units"]``.
    """

    def __init__(self, name, names, units, columns):
        self.name = name
        self.names = list(names)
        self.units = dict(zip(self.names, units))
        self.columns = dict(zip(self.names, columns))

    def __getitem__(self, name):
        return self.columns[name]

    def __contains__(self, name):
        return name in self.columns

    def __iter__(self):
        return iter(self.names)

    def __len__(self):
        return len(self.columns[self.names[0]]) if self.names else 0

    def __repr__(self):
        return "<milldyn.Table %s: %d rows, %s>" % (
            self.name, len(self), ", ".join("%s[%s]" % (n, self.units[n]) for n in self.names))

    def headers(self):
        """The CLI's CSV header: ``name[unit]`` for each column (text
        columns, whose unit is "", by name alone)."""
        return ["%s[%s]" % (n, self.units[n]) if self.units[n] else n for n in self.names]

    def to_pandas(self):
        """A pandas DataFrame (needs pandas): columns without the unit
        suffix, units in ``df.attrs["units"]``."""
        try:
            import pandas
        except ImportError as e:  # pragma: no cover - pandas is installed by scripts/install-deps.sh
            raise ImportError("to_pandas() needs pandas (Debian: python3-pandas)") from e
        df = pandas.DataFrame({n: self.columns[n] for n in self.names}, columns=self.names)
        df.attrs["units"] = dict(self.units)
        df.attrs["table"] = self.name
        return df


def _table(d):
    return Table(d["name"], d["names"], d["units"], d["columns"])


class Result:
    """What one run produced.

    - ``table``: the analysis's main table (a Table: timeseries, ...);
    - ``tables``: every table by name (the main one and the further ones);
    - ``summary``: the named results, name -> Value (a float with ``.unit``);
    - ``derived``: values elements derive from their parameters;
    - ``notes``: what happened, in words (the verdicts);
    - ``statistics``: integrator, accuracy, steps, realizations, wall time;
    - ``dof_names``, ``matrices``: a linear model's (name -> (array, unit));
    - ``files``: what was written (``run(out=...)`` or ``write()``).
    """

    def __init__(self, model, handle):
        self.model = model
        self._handle = handle
        self.analysis = handle.analysis
        self.table = _table(handle.table())
        self.tables = {self.table.name: self.table}
        for t in handle.extra_tables():
            self.tables[t["name"]] = _table(t)
        self.summary = {n: Value(v, u, doc) for n, v, u, doc in handle.results()}
        self.derived = {n: Value(v, u, doc) for n, v, u, doc in handle.derived()}
        self.notes = list(handle.notes())
        self.statistics = dict(handle.statistics())
        self.dof_names, self.matrices = handle.linear_model()
        self.files = []
        self.warning = ""

    def __repr__(self):
        return "<milldyn.Result %s of %s: %s>" % (
            self.analysis, self.model.name, ", ".join("%s=%r" % kv for kv in self.summary.items()))

    def to_pandas(self):
        """The main table as a pandas DataFrame (units in ``df.attrs``)."""
        return self.table.to_pandas()

    def summary_json(self):
        """The text of the CLI's summary.json for this run."""
        return self._handle.summary_json()

    def write(self, out):
        """Writes the files ``milldyn run --out DIR`` writes; returns their paths."""
        files, warning = self._handle.write(os.fspath(out))
        self.files, self.warning = list(files), warning
        return self.files


_loaded_plugins = set()


def load_plugin(path):
    """Loads a plugin library's element types (``--plugin LIB.so``); a library
    already loaded by this process is not loaded twice."""
    path = os.path.realpath(os.fspath(path))
    if path not in _loaded_plugins:
        _core.load_plugin(path)
        _loaded_plugins.add(path)


class Model:
    """A model file, read and checked with its overrides.

    ``Model(path, set={"elements.belt.stiffness": "2e5 N*m/rad"},
    scenario="idle", preset="fast", plugins=["lib.so"])``; bad input raises
    ModelError with the CLI's line ``file:line:col: error: key: reason``.
    """

    def __init__(self, path, set=None, scenario=None, preset=None, plugins=()):
        for p in plugins:
            load_plugin(p)
        self.path = os.fspath(path)
        self.overrides = _overrides(set, scenario, preset)
        self._spec = _core.read_model(self.path, self.overrides)

    @property
    def name(self):
        return self._spec.name

    @property
    def analysis(self):
        return self._spec.analysis

    @property
    def description(self):
        return self._spec.description

    def __repr__(self):
        return "<milldyn.Model %s (%s): %s>" % (self.name, self.path, self.analysis)

    def info(self):
        """What ``milldyn info`` shows, as a dict."""
        return _core.describe(self._spec)

    def run(self, out=None, set=None, scenario=None, preset=None, integrator=None, accuracy=None,
            end_time=None, cancel=None):
        """Runs the model's analysis and returns a Result. Nothing is written
        unless ``out`` names a directory (then the CLI's files go there).
        ``set``, ``scenario``, ``preset``, ``integrator``, ``accuracy`` and
        ``end_time`` add to the model's overrides for this run only.
        ``cancel``: a CancelToken another thread may set."""
        extra = _overrides(set, scenario, preset, integrator=integrator, accuracy=accuracy, end_time=end_time)
        spec = _core.read_model(self.path, self.overrides + extra) if extra else self._spec
        on_main = threading.current_thread() is threading.main_thread()
        result = Result(self, _core.run(spec, cancel, on_main))
        if out is not None:
            result.write(out)
        return result


def _axis_text(value):
    return value if isinstance(value, str) else repr(float(value))


def sweep(model, grid=None, lhs=None, ranges=None, seed=1, jobs=None, out=None):
    """Runs a model over a grid or a Latin hypercube, like ``milldyn sweep``.

    - ``grid={"path": (a, b, n)}`` (or ``"a:b:n"``): n values from a to b for
      each path, every combination; a and b numbers (SI) or text with the same
      unit ("10 N*m");
    - ``lhs=N, ranges={"path": (a, b)}``: N points of a Latin hypercube
      (``seed``).

    ``jobs`` threads (default: all cores). Returns a Table: ``index``, the
    swept values (in the unit they were given in, ``SI`` otherwise), ``status``
    (ok | bad_input | failed), every result with its unit (NaN where a point
    has none: see ``status`` and ``diagnostic``). Only with ``out`` does the
    sweep's directory (``sweep.csv``, ``points/``) stay on disk.
    """
    if not isinstance(model, Model):
        model = Model(model)
    grids, rng = [], []
    for path, spec in (grid or {}).items():
        if isinstance(spec, str):
            grids.append("%s=%s" % (path, spec))
        else:
            a, b, n = spec
            grids.append("%s=%s:%s:%d" % (path, _axis_text(a), _axis_text(b), int(n)))
    for path, spec in (ranges or {}).items():
        if isinstance(spec, str):
            rng.append("%s=%s" % (path, spec))
        else:
            a, b = spec
            rng.append("%s=%s:%s" % (path, _axis_text(a), _axis_text(b)))
    directory = os.fspath(out) if out is not None else tempfile.mkdtemp(prefix="milldyn-sweep-")
    try:
        summary = _core.sweep(model.path, model.overrides, grids, rng, int(lhs or 0), int(seed),
                              int(jobs or os.cpu_count() or 1), directory)
        table = _read_sweep_csv(os.path.join(directory, "sweep.csv"))
    finally:
        if out is None:
            shutil.rmtree(directory, ignore_errors=True)
    table.summary = summary
    if out is None:
        table.summary["files"] = []
    return table


def _read_sweep_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    names, units = [], []
    for h in header:
        if h.endswith("]") and "[" in h:
            i = h.rindex("[")
            names.append(h[:i])
            units.append(h[i + 1:-1])
        else:
            names.append(h)
            units.append("")
    columns = []
    for c, name in enumerate(names):
        cells = [r[c] for r in body]
        if name in ("status", "diagnostic"):
            columns.append(_np.array(cells, dtype=object))
        elif name == "index":
            columns.append(_np.array([int(x) for x in cells], dtype=_np.int64))
        else:
            columns.append(_np.array([float(x) if x != "" else _np.nan for x in cells], dtype=float))
    return Table("sweep", names, units, columns)


def validate(filter=""):
    """Every oracle comparison whose case name contains ``filter`` (as
    ``milldyn validate``): a list of dicts with case, quantity, unit,
    multibody, oracle, paper, rel_error (None where the oracle is 0, with
    abs_error), tolerance, status, note."""
    return _core.validate(filter)


def elements():
    """Every registered element type (built in and from plugins): a dict
    type -> {doc, output_only, keys: {key: {kind, unit, required, default,
    choices, min, max, min_exclusive, max_exclusive, doc}}}; defaults and
    bounds in SI (the key's ``unit``)."""
    return {e["type"]: e for e in _core.elements()}


def analyses():
    """The analysis kinds a scenario may ask for, with their keys (as elements())."""
    return {e["type"]: e for e in _core.analyses()}


def to_si(text, unit):
    """``to_si("1500 rpm", "rad/s")`` -> 157.07...: text with a unit to the SI
    unit a key wants (a bare number is SI already); UnitError otherwise."""
    return _core.to_si(str(text), unit)


def quantity(text):
    """``quantity("20 N*m")`` -> Value(20.0, "kg*m^2/s^2"): text with a unit
    to its SI value and the SI unit of its dimension."""
    value, unit = _core.parse_quantity(str(text))
    return Value(value, unit)
