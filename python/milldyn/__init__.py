"""milldyn from Python: the same models, runs, sweeps and validation as the
``milldyn`` command line, through the same C++ code (docs/python.md).

    import milldyn
    model = milldyn.Model("models/burr_mill_5p5kW_idle.yaml",
                          set={"elements.grinding.constant_torque": "20 N*m"})
    result = model.run()                 # a stalled start warns StartNotCompletedWarning
    result.verdict, result.verdict.text  # "ran", the sentence `milldyn run` prints
    result.summary["runout_time"]        # 1.12... s  (a float with .unit)
    result.table["millstone.speed"]      # numpy array; result.table.units[...]
    df = result.to_pandas()              # columns without [unit]; df.attrs["units"]

Values may be given as text with units ("20 N*m", "1500 rpm") or as numbers
in SI; every result says its unit. Runs release the GIL (threads run models
in parallel); Ctrl-C stops a run on the main thread at its next sample, and
a CancelToken stops one from any thread.
"""

# The standard modules under private names: `milldyn.` completes to
# milldyn's own names only (issue 29 item 5).
import collections as _collections
import csv as _csv
import os as _os
import shutil as _shutil
import sys as _sys
import tempfile as _tempfile
import threading as _threading
import warnings as _warnings

# Plugin libraries (plugins=[...]) resolve the registry's symbols from the
# module, as they do from the milldyn executable: load it RTLD_GLOBAL.
_flags = _sys.getdlopenflags()
_sys.setdlopenflags(_flags | _os.RTLD_GLOBAL)
try:
    from . import _milldyn as _core
finally:
    _sys.setdlopenflags(_flags)

from .errors import (AnalysisFailed, Cancelled, MilldynError, ModelError, ModelFileNotFound,  # noqa: E402
                     OutputFailed, StartNotCompleted, StartNotCompletedWarning, UnitError)

import numpy as _np  # noqa: E402

__version__ = _core.__version__
CancelToken = _core.CancelToken

__all__ = ["Model", "Result", "Table", "Value", "Matrix", "Verdict", "CancelToken", "sweep", "front", "validate", "elements",
           "analyses", "load_plugin", "to_si", "quantity", "ModelError", "ModelFileNotFound", "AnalysisFailed",
           "OutputFailed", "Cancelled", "UnitError", "MilldynError", "StartNotCompleted", "StartNotCompletedWarning"]


def _unit_factor(unit):
    """A unit as a factor of a product: parenthesised when it holds an
    operator (``N*m`` -> ``(N*m)``)."""
    return unit if all(c not in unit for c in "*/^ ") else "(%s)" % unit


# The unit a designer reads for each dimension a product or quotient of
# Values may have (docs/python.md, "Units"): coherent SI units, so a value
# keeps its number. A torque times an angular speed is a power (W) and a
# torque times an angle a work (J): Units.h keeps the radian in the
# dimension, these names drop it, as a mechanical power does. The one
# dimension shared by two common units, kg*m^2/s^2 (a torque N*m, an energy
# J), is named after its factors: N*m when one holds a force or a torque
# (N), J when one holds a power or an energy (W, J), else left composed.
_PREFERRED_UNITS = ("kg*m^2", "rad/s", "rad/s^2", "W", "N", "N*m/rad", "N*m*s/rad", "N*s/m", "N/m", "Pa", "m/s",
                    "m/s^2", "rad", "m", "s", "kg", "A", "1/s", "m^2", "m^3", "kg/m^3")
_PREFERRED_ALIASES = {"N*m*rad/s": "W", "N*m*rad": "J"}
_preferred_by_dimension = None


def _dimension(unit):
    """(SI value of 1 ``unit``, its dimension's canonical text); "1" is
    dimensionless. UnitError if it does not parse."""
    if unit in ("", "1"):
        return 1.0, "1"
    return _core.parse_quantity("1 " + unit)


def _preferred_unit(dimension, factors):
    global _preferred_by_dimension
    if _preferred_by_dimension is None:
        table = {_dimension(u)[1]: u for u in _PREFERRED_UNITS}
        table.update({_dimension(u)[1]: name for u, name in _PREFERRED_ALIASES.items()})
        _preferred_by_dimension = table
    if dimension == "1":
        return "1"
    if dimension == _dimension("N*m")[1]:
        if any("N" in f for f in factors):
            return "N*m"
        if any("W" in f or "J" in f for f in factors):
            return "J"
        return None
    return _preferred_by_dimension.get(dimension)


def _composed(value, unit, factors):
    """A product's or quotient's Value: in the preferred unit of its
    dimension (its number scaled to it), else in the composed unit."""
    try:
        scale, dimension = _dimension(unit)
    except MilldynError:
        return Value(value, unit)
    preferred = _preferred_unit(dimension, factors)
    if preferred is None:
        return Value(value, unit)
    return Value(value * scale, preferred)


class Value(float):
    """A number with its unit (and a line saying what it is): ``float(v)`` is
    the value in ``v.unit``.

    Arithmetic keeps the unit or refuses: ``v + w`` and ``v - w`` need the
    same unit (a plain number counts as being in ``v.unit``) and keep it;
    ``v * 2``, ``v / 2``, ``-v``, ``abs(v)`` keep it; ``v * w`` and ``v / w``
    compose the units (``N*m`` * ``rad/s`` -> ``(N*m)*(rad/s)``; a Value over
    one of the same unit is ``1``); anything else (``v ** 2`` of a unit,
    ``v + w`` of two units) raises UnitError. ``float(v)`` drops the unit.
    """

    def __new__(cls, value, unit, doc=""):
        self = super().__new__(cls, value)
        self.unit = unit
        self.doc = doc
        return self

    def __repr__(self):
        return "%r %s" % (float(self), self.unit)

    def __reduce__(self):
        return (Value, (float(self), self.unit, self.doc))

    def _same_unit(self, other, op):
        if isinstance(other, Value) and other.unit != self.unit:
            raise UnitError("%s of %r and %r: the units differ (convert one with milldyn.to_si)" % (op, self, other))
        return float(other)

    def __add__(self, other):
        if not isinstance(other, (int, float, _np.integer, _np.floating)):
            return NotImplemented
        return Value(float(self) + self._same_unit(other, "sum"), self.unit)

    __radd__ = __add__

    def __sub__(self, other):
        if not isinstance(other, (int, float, _np.integer, _np.floating)):
            return NotImplemented
        return Value(float(self) - self._same_unit(other, "difference"), self.unit)

    def __rsub__(self, other):
        if not isinstance(other, (int, float, _np.integer, _np.floating)):
            return NotImplemented
        return Value(self._same_unit(other, "difference") - float(self), self.unit)

    def to(self, unit):
        """This value in ``unit`` (a Value): ``summary["power"].to("kW")``;
        UnitError for a unit of another dimension."""
        unit = _utf8(unit, "unit", UnitError)
        scale, dimension = _dimension(self.unit)
        target_scale, target = _dimension(unit)
        if dimension != target:
            raise UnitError("%r cannot be given in %s: its dimension is %s, that of %s is %s"
                            % (self, unit, dimension, unit, target))
        return Value(float(self) * scale / target_scale, unit, self.doc)

    def __mul__(self, other):
        if isinstance(other, Value):
            if self.unit in ("", "1") or other.unit in ("", "1"):
                unit = other.unit if self.unit in ("", "1") else self.unit
                return Value(float(self) * float(other), unit or "1")
            return _composed(float(self) * float(other), "%s*%s" % (_unit_factor(self.unit), _unit_factor(other.unit)),
                             (self.unit, other.unit))
        if not isinstance(other, (int, float, _np.integer, _np.floating)) or isinstance(other, bool):
            return NotImplemented
        return Value(float(self) * float(other), self.unit)

    __rmul__ = __mul__

    def __truediv__(self, other):
        if isinstance(other, Value):
            if other.unit == self.unit:
                return Value(float(self) / float(other), "1")
            if other.unit in ("", "1"):
                return Value(float(self) / float(other), self.unit)
            top = "1" if self.unit in ("", "1") else _unit_factor(self.unit)
            return _composed(float(self) / float(other), "%s/%s" % (top, _unit_factor(other.unit)),
                             (self.unit, other.unit))
        if not isinstance(other, (int, float, _np.integer, _np.floating)) or isinstance(other, bool):
            return NotImplemented
        return Value(float(self) / float(other), self.unit)

    def __rtruediv__(self, other):
        if not isinstance(other, (int, float, _np.integer, _np.floating)) or isinstance(other, bool):
            return NotImplemented
        return Value(float(other) / float(self), "1/%s" % _unit_factor(self.unit))

    def __pow__(self, other, modulo=None):
        if self.unit in ("", "1"):
            return Value(float(self) ** other, self.unit)
        raise UnitError("%r ** %r: a power of a value with a unit is not kept as a unit; use float(v) ** n" % (self, other))

    def __neg__(self):
        return Value(-float(self), self.unit)

    def __pos__(self):
        return self

    def __abs__(self):
        return Value(abs(float(self)), self.unit)

    def __floordiv__(self, other):
        raise UnitError("%r // %r: floor division keeps no unit; use float(v) // x" % (self, other))

    __rfloordiv__ = __mod__ = __rmod__ = __divmod__ = __rdivmod__ = __rpow__ = __floordiv__


class Matrix(_collections.namedtuple("Matrix", "values unit")):
    """One matrix of a linear model (``Result.matrices[name]``): ``values``
    a square numpy array and ``unit`` the unit of its entries ("kg*m^2" for
    M, "N*m*s/rad" for C, "N*m/rad" for K; A is labelled "1/s" though its
    blocks are 1, 1/s^2 and 1/s: docs/python.md). ``rows`` and ``columns``
    label its rows and columns: the degrees of freedom (``Result.dof_names``)
    for M, C, K; ``DOF.angle`` then ``DOF.speed`` for A (and the other
    first-order matrices of that size); None where the result names no
    labels (A_with_motor_states: the motors' flux states follow). Unpacks as
    ``values, unit``; ``to_pandas()`` is a labelled DataFrame."""

    rows = None
    columns = None

    def __new__(cls, values, unit, rows=None, columns=None):
        self = super().__new__(cls, values, unit)
        self.rows = None if rows is None else list(rows)
        self.columns = None if columns is None else list(columns)
        return self

    @property
    def shape(self):
        return self.values.shape

    def __repr__(self):
        shape = "%dx%d" % (self.values.shape[0], self.values.shape[1] if self.values.ndim > 1 else 1)
        labels = ""
        if self.rows is not None:
            labels = ", rows %s%s" % (", ".join(self.rows[:4]), ", ..." if len(self.rows) > 4 else "")
        return "<milldyn.Matrix %s [%s]%s>" % (shape, self.unit, labels)

    def to_pandas(self):
        """A pandas DataFrame with the row and column labels (needs pandas);
        the unit in ``df.attrs["unit"]``."""
        import pandas
        df = pandas.DataFrame(self.values, index=self.rows, columns=self.columns)
        df.attrs["unit"] = self.unit
        return df


def _matrix_labels(values, dof_names):
    """Row and column labels of a linear model's matrix: the DOF names for
    an n x n matrix, DOF.angle then DOF.speed for a 2n x 2n one (positions,
    then speeds, as A = [[0, I], [-M^-1 K, -M^-1 C]]), else None."""
    n = len(dof_names)
    if n and values.shape == (n, n):
        return list(dof_names)
    if n and values.shape == (2 * n, 2 * n):
        return ["%s.angle" % d for d in dof_names] + ["%s.speed" % d for d in dof_names]
    return None


class Verdict(str):
    """A run's verdict as the CLI prints it: the string itself is its name
    ("completed", "stalled", "unfinished", "steady_held", "ran"; "" where
    the analysis judges no start, e.g. a linearize run), ``text`` the CLI's
    sentence with the numbers (``verdict: ...`` of ``milldyn run``),
    ``kind`` "done" | "unfinished" | "stalled", ``ok`` whether the run did
    what was asked (kind "done"), ``exit_code`` the CLI's (3 for a stall).
    Kind and exit code come from driver/Api (verdictKind, runExitCode), the
    rule the CLI and the sweeps use."""

    def __new__(cls, name, text="", kind="done", exit_code=0):
        self = super().__new__(cls, name)
        self.text, self.kind, self.exit_code = text, kind, exit_code
        return self

    @property
    def ok(self):
        return self.kind == "done"

    def __repr__(self):
        if not self:
            return "<milldyn.Verdict none (the analysis judges no start)>"
        return "<milldyn.Verdict %s: %s>" % (str(self), self.text)

    def __reduce__(self):
        return (Verdict, (str(self), self.text, self.kind, self.exit_code))


class _Named(dict):
    """A dict whose missing keys raise KeyError with the nearest name."""

    what = "name"

    def __missing__(self, key):
        raise KeyError(_unknown(key, list(self), self.what))


def _named(mapping, what):
    """``mapping`` as a dict whose unknown keys raise KeyError naming
    ``what`` and the nearest key."""
    out = _Named(mapping)
    out.what = what
    return out


def _encodable(text):
    try:
        text.encode("utf-8")
        return True
    except UnicodeEncodeError:
        return False


def _nearest(word, names):
    if not _encodable(word):
        return ""
    return _core.nearest_name(word, [n for n in names if _encodable(n)])


def _unknown(key, names, what):
    """The CLI reader's "did you mean" (its nearestName, through the core)
    for a name that is not among ``names``; the first known ones when none
    is close."""
    near = _nearest(str(key), [str(n) for n in names])
    text = "unknown %s %r" % (what, key)
    if near:
        text += " (did you mean %r?)" % near
    elif names:
        text += " (%d known: %s%s)" % (len(names), ", ".join(repr(n) for n in list(names)[:6]),
                                       ", ..." if len(names) > 6 else "")
    return text


class _Results(_Named):
    what = "result"


class _Tables(_Named):
    what = "table"


class _Matrices(_Named):
    what = "matrix"


def _utf8(text, what, error=None):
    """``text`` as a str that UTF-8 can encode: a lone surrogate (from a file
    name read with surrogateescape, or a bad escape) raises ModelError (or
    ``error``) naming where, instead of pybind11's TypeError."""
    text = str(text)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as e:
        message = "%s: %r is not valid text (a lone surrogate %r at offset %d; UTF-8 cannot hold it)" % (
            what, text, text[e.start:e.end], e.start)
        if error is UnitError:
            raise UnitError(message, e.start) from None
        raise ModelError("<python>:1:%d: error: %s" % (e.start + 1, message), "<python>", 1, e.start + 1, what,
                         "not valid text (a lone surrogate)") from None
    return text


def _path(path):
    """A file path for the core: bytes as the file system has them (a name
    that is not UTF-8 still opens)."""
    return _os.fsencode(_os.fspath(path))


def _text(value):
    """An override's value text: strings as written (with their units),
    numbers (SI) with every digit, so they reach the model exactly."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return _utf8(value, "override value")
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
        out.append(("use_scenario", _utf8(scenario, "scenario"), False))
    if preset is not None:
        out.append(("preset", _utf8(preset, "preset"), False))
    for path, value in (set or {}).items():
        out.append((_utf8(path, "override path"), _text(value), _is_si_number(value)))
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
        self.units = _named(zip(self.names, units), "column of table %s" % name)
        self.columns = _named(zip(self.names, columns), "column of table %s" % name)

    def __getitem__(self, name):
        try:
            return self.columns[name]
        except KeyError:
            raise KeyError(_unknown(name, self.names, "column of table %s" % self.name)) from None

    def __contains__(self, name):
        return name in self.columns

    def __iter__(self):
        return iter(self.names)

    def __len__(self):
        return len(self.columns[self.names[0]]) if self.names else 0

    def __repr__(self):
        shown = ", ".join("%s[%s]" % (n, self.units[n]) for n in self.names[:6])
        more = ", ... (%d columns)" % len(self.names) if len(self.names) > 6 else ""
        return "<milldyn.Table %s: %d rows, %s%s>" % (self.name, len(self), shown, more)

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


_REPR_RESULTS = 4


def _wrap(parts, lead="", width=100):
    """Comma-joined ``parts`` on lines of about ``width`` characters, each
    indented by two spaces (the first after ``lead``)."""
    lines, line = [], "  " + lead
    for k, part in enumerate(parts):
        if k and len(line) + len(part) + 2 > width:
            lines.append(line + ",")
            line = "    "
        elif k:
            line += ", "
        line += part
    return lines + [line]


class Result:
    """What one run produced.

    - ``table``: the analysis's main table (a Table: timeseries, ...);
    - ``tables``: every table by name (the main one and the further ones);
    - ``summary``: the named results, name -> Value (a float with ``.unit``);
    - ``derived``: values elements derive from their parameters;
    - ``verdict``: the run's verdict (a Verdict: "completed", "stalled",
      "unfinished", ...; ``.text`` the CLI's sentence, ``.ok``, ``.exit_code``);
    - ``notes``: what happened, in words;
    - ``statistics``: integrator, accuracy, steps, realizations, wall time;
    - ``dof_names``, ``matrices``: a linear model's degrees of freedom and
      its matrices, name -> Matrix(values, unit, rows, columns) (M, C, K, A:
      docs/python.md);
    - ``files``: what was written (``run(out=...)`` or ``write()``).

    An unknown name in ``summary``, ``derived``, ``tables``, ``matrices``,
    ``statistics`` or a Table raises KeyError with the nearest name.
    """

    def __init__(self, model, handle):
        self.model = model
        self._handle = handle
        self.analysis = handle.analysis
        self.table = _table(handle.table())
        self.tables = _Tables({self.table.name: self.table})
        for t in handle.extra_tables():
            self.tables[t["name"]] = _table(t)
        self.summary = _Results((n, Value(v, u, doc)) for n, v, u, doc in handle.results())
        self.derived = _Results((n, Value(v, u, doc)) for n, v, u, doc in handle.derived())
        self.verdict = Verdict(*handle.verdict())
        self.notes = list(handle.notes())
        self.statistics = _named(handle.statistics(), "statistic")
        self.dof_names, matrices = handle.linear_model()
        self.matrices = _Matrices()
        for n, (values, unit) in matrices.items():
            labels = _matrix_labels(values, self.dof_names)
            self.matrices[n] = Matrix(values, unit, labels, labels)
        self.files = []
        self.warning = ""

    def __repr__(self):
        # A few lines: the verdict, the first results (the analysis's
        # headline ones), the tables' sizes; print(result.summary) and
        # result.verdict.text give everything.
        lines = ["<milldyn.Result %s of %r" % (self.analysis, self.model.name)]
        if self.verdict:
            text = self.verdict.text if len(self.verdict.text) <= 110 else self.verdict.text[:107] + "..."
            lines.append("  verdict: %s" % text)
        items = list(self.summary.items())
        shown = [("%s = %.6g %s" % (n, v, v.unit)).rstrip() if v.unit not in ("", "1") else "%s = %.6g" % (n, v)
                 for n, v in items[:_REPR_RESULTS]]
        if items:
            shown[-1] += " (%d of %d results)" % (len(shown), len(items))
        lines += _wrap(shown) if items else ["  no results"]
        tables = ["%s %dx%d" % (n, len(t), len(t.names)) for n, t in list(self.tables.items())[:4]]
        if len(self.tables) > 4:
            tables.append("%d more" % (len(self.tables) - 4))
        lines += _wrap(tables, "tables: ")
        extra = []
        if self.matrices:
            extra.append("matrices: " + ", ".join(self.matrices))
        if self.notes:
            extra.append("%d note%s" % (len(self.notes), "" if len(self.notes) == 1 else "s"))
        if extra:
            lines.append("  " + "; ".join(extra))
        return "\n".join(lines) + ">"

    def to_pandas(self):
        """The main table as a pandas DataFrame (units in ``df.attrs``)."""
        return self.table.to_pandas()

    def summary_json(self):
        """The text of the CLI's summary.json for this run."""
        return self._handle.summary_json()

    def write(self, out):
        """Writes the files ``milldyn run --out DIR`` writes; returns their paths."""
        files, warning = self._handle.write(_path(out))
        self.files, self.warning = list(files), warning
        return self.files


_loaded_plugins = set()


def load_plugin(path):
    """Loads a plugin library's element types (``--plugin LIB.so``); a library
    already loaded by this process is not loaded twice."""
    path = _os.path.realpath(_os.fspath(path))
    if path not in _loaded_plugins:
        _core.load_plugin(_os.fsencode(path))
        _loaded_plugins.add(path)


def _read_model(path, overrides):
    """The core's reader; a missing file raises ModelFileNotFound (a
    ModelError and a FileNotFoundError)."""
    try:
        return _core.read_model(_path(path), overrides)
    except ModelError as e:
        if e.reason.endswith("no such file"):
            missing = path if e.key == "<file>" else e.reason.split("'")[1] if "'" in e.reason else e.file
            raise ModelFileNotFound(e.text, e.file, e.line, e.column, e.key, e.reason, e.included_from,
                                    missing) from None
        raise
    except UnicodeDecodeError:
        # The core's message holds a file name's bytes that are not UTF-8.
        shown = _os.fsdecode(_path(path)).encode("utf-8", "backslashreplace").decode("utf-8")
        if not _os.path.exists(path):
            raise ModelFileNotFound("%s:1:1: error: <file>: cannot open the model file: no such file" % shown, shown,
                                    1, 1, "<file>", "cannot open the model file: no such file", "", path) from None
        raise ModelError("%s:1:1: error: <file>: the model's diagnostic names a file whose name is not UTF-8" % shown,
                         shown, 1, 1, "<file>", "a file name that is not UTF-8") from None


class Model:
    """A model file, read and checked with its overrides.

    ``Model(path, set={"elements.belt.stiffness": "2e5 N*m/rad"},
    scenario="idle", preset="fast", plugins=["lib.so"])``; bad input raises
    ModelError with the CLI's line ``file:line:col: error: key: reason``, a
    missing file ModelFileNotFound (also a FileNotFoundError).
    """

    def __init__(self, path, set=None, scenario=None, preset=None, plugins=()):
        for p in plugins:
            load_plugin(p)
        self.path = _os.fspath(path)
        self.overrides = _overrides(set, scenario, preset)
        self._spec = _read_model(self.path, self.overrides)

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
        """What ``milldyn info`` shows, as a dict (an unknown field raises
        KeyError with the nearest name)."""
        return _named(_core.describe(self._spec), "info field")

    def run(self, out=None, set=None, scenario=None, preset=None, integrator=None, accuracy=None,
            end_time=None, cancel=None, on_failure="warn", check_resolution=False):
        """Runs the model's analysis and returns a Result. Nothing is written
        unless ``out`` names a directory (then the CLI's files go there).
        ``set``, ``scenario``, ``preset``, ``integrator``, ``accuracy`` and
        ``end_time`` add to the model's overrides for this run only.
        ``cancel``: a CancelToken another thread may set.

        ``on_failure`` says what a run that did not do what was asked does
        (its verdict ``stalled``, where the CLI exits 3, or ``unfinished``):
        "warn" (default) warns StartNotCompletedWarning with the verdict's
        text and returns the Result; "raise" raises StartNotCompleted
        carrying the Result (its files written first when ``out`` is
        given, as the CLI writes them); "ignore" only sets
        ``result.verdict``.

        ``check_resolution=True`` runs the model again at a tenth of its
        accuracy, as ``milldyn run --check-resolution`` does, and adds a
        warning note for every torque peak, peak-to-peak value, ripple and
        speed fluctuation that moves by more than 1 %
        (docs/speed-accuracy.md "Your own model")."""
        _check_on_failure(on_failure)
        extra = _overrides(set, scenario, preset, integrator=integrator, accuracy=accuracy, end_time=end_time)
        spec = _read_model(self.path, self.overrides + extra) if extra else self._spec
        on_main = _threading.current_thread() is _threading.main_thread()
        result = Result(self, _core.run(spec, cancel, on_main, bool(check_resolution)))
        if out is not None:
            result.write(out)
        _judge(result, on_failure)
        return result


def _check_on_failure(on_failure):
    if on_failure not in ("warn", "raise", "ignore"):
        raise ValueError("on_failure must be \"warn\", \"raise\" or \"ignore\", got %r" % (on_failure,))


def _judge(result, on_failure):
    """Says so when a run did not do what was asked (Result.verdict)."""
    verdict = result.verdict
    if verdict.ok or on_failure == "ignore":
        return
    text = "%s: %s" % (result.model.name, verdict.text)
    if on_failure == "raise":
        raise StartNotCompleted(text, result)
    # stacklevel 3: the warning names the caller of Model.run.
    _warnings.warn(StartNotCompletedWarning(text, result), stacklevel=3)


def _axis_text(value, what):
    if isinstance(value, bool):
        raise ModelError("<python>:1:1: error: %s: %r is not a number or text with a unit" % (what, value),
                         "<python>", 1, 1, what, "not a number")
    if isinstance(value, str):
        return _utf8(value, what)
    if isinstance(value, (int, float, _np.integer, _np.floating)):
        return repr(float(value))
    raise ModelError("<python>:1:1: error: %s: %r is not a number or text with a unit" % (what, value),
                     "<python>", 1, 1, what, "not a number")


def _count(n, what):
    """A grid's number of values: a whole number (3 or 3.0), never 2.5."""
    if isinstance(n, bool) or not isinstance(n, (int, float, _np.integer, _np.floating)) or \
            (isinstance(n, (float, _np.floating)) and not float(n).is_integer()):
        raise ModelError("<python>:1:1: error: %s: the number of values must be a whole number, got %r" % (what, n),
                         "<python>", 1, 1, what, "the number of values must be a whole number")
    return int(n)


def _spec_text(path, spec, ranges):
    """One path's part of a --grid (or --range) text."""
    what = "ranges[%r]" % path if ranges else "grid[%r]" % path
    if isinstance(spec, str):
        return "%s=%s" % (path, _utf8(spec, what))
    if isinstance(spec, list):  # a value list
        if ranges:
            raise ModelError("<python>:1:1: error: %s: a range is (a, b), not a list" % what, "<python>", 1, 1, what,
                             "a range is (a, b)")
        if len(spec) == 0:
            raise ModelError("<python>:1:1: error: %s: an empty list of values" % what, "<python>", 1, 1, what,
                             "an empty list of values")
        if len(spec) == 1:  # "v," is no list: one value is a grid of one
            return "%s=%s:%s:1" % (path, _axis_text(spec[0], what), _axis_text(spec[0], what))
        return "%s=%s" % (path, ",".join(_axis_text(v, what) for v in spec))
    spec = tuple(spec)
    if ranges:
        if len(spec) != 2:
            raise ModelError("<python>:1:1: error: %s: expected (a, b)" % what, "<python>", 1, 1, what, "expected (a, b)")
        return "%s=%s:%s" % (path, _axis_text(spec[0], what), _axis_text(spec[1], what))
    if len(spec) == 4 and spec[3] in ("log", "lin"):
        return "%s=%s:%s:%d:%s" % (path, _axis_text(spec[0], what), _axis_text(spec[1], what), _count(spec[2], what),
                                   spec[3])
    if len(spec) != 3:
        raise ModelError("<python>:1:1: error: %s: expected (a, b, n), (a, b, n, \"log\"), a list of values or "
                         "\"a:b:n\"" % what, "<python>", 1, 1, what, "expected (a, b, n)")
    return "%s=%s:%s:%d" % (path, _axis_text(spec[0], what), _axis_text(spec[1], what), _count(spec[2], what))


def _axis_option(key, spec, ranges):
    """A --grid/--range text; a tuple of paths ties them to one axis: one
    spec for all, or a list with one spec per path."""
    if isinstance(key, tuple):
        paths = [_utf8(k, "grid path") for k in key]
        per_path = isinstance(spec, list) and len(spec) == len(paths) and \
            all(isinstance(x, (tuple, list)) or (isinstance(x, str) and (":" in x or "," in x)) for x in spec)
        specs = spec if per_path else [spec] * len(paths)
        return ";".join(_spec_text(p, x, ranges) for p, x in zip(paths, specs))
    return _spec_text(_utf8(key, "grid path"), spec, ranges)


def front(model, integrators=None, accuracies=None, reference=None, budget=None, repeat=1, write_presets=False):
    """The error-cost front of a model, as ``milldyn front`` measures it
    (docs/speed-accuracy.md "Your own model"): the model (a Model, whose
    overrides apply, or a path) at every integrator of ``integrators``
    (default RungeKuttaMerson, RungeKutta3, CPodes) and accuracy of
    ``accuracies`` (default 1e-3 ... 1e-8) against ``reference`` (a pair
    (integrator, accuracy), default ("RungeKuttaMerson", 1e-10)).

    Returns a dict: ``points`` (one dict per run: integrator, accuracy,
    status, cpu_s, the errors peak_error, ripple_error, speed_error,
    time_error, energy, worst, and front: on the front), ``reference``,
    ``presets`` ({"fast", "balanced", "accurate"}: the index in ``points``
    of the cheapest point within the target, or None), ``targets``,
    ``torque_floor`` [N*m], ``steady_window`` [s], ``notes`` and ``csv``
    (front.csv's text). ``write_presets=True`` writes MODEL.presets.yaml
    beside the model (its path in ``presets_file``)."""
    if not isinstance(model, Model):
        model = Model(model)
    ref = reference or ("", 0.0)
    if not isinstance(ref, (tuple, list)) or len(ref) != 2:
        raise TypeError("reference must be a pair (integrator, accuracy)")
    result = _core.front(_path(model.path), model.overrides, [str(i) for i in (integrators or [])],
                         [float(a) for a in (accuracies or [])], str(ref[0]), float(ref[1]),
                         float(budget or 0.0), int(repeat), bool(write_presets))
    return _named(result, "front key")


def sweep(model, grid=None, lhs=None, ranges=None, seed=1, jobs=None, out=None, progress=None, cancel=None,
          integrator=None, accuracy=None, end_time=None, on_failure="warn"):
    """Runs a model over a grid or a Latin hypercube, like ``milldyn sweep``.

    - ``grid={"path": spec}``, every combination of the paths' values; spec:
      ``(a, b, n)`` n values from a to b, ``(a, b, n, "log")`` spaced evenly
      in log, a list ``[v1, v2, ...]`` of values, or the CLI's text
      ``"a:b:n"``; values are numbers (SI) or text with the same unit
      ("10 N*m"); n a whole number;
    - a tuple of paths as the key ties them to one axis (they move
      together): ``grid={("elements.fw1.inertia", "elements.fw2.inertia"):
      (1, 5, 5)}`` gives both the same values; a list with one spec per path
      gives each its own (``[("1000 rpm", "1500 rpm", 6), ("990 rpm",
      "1485 rpm", 6)]``);
    - ``lhs=N, ranges={"path": (a, b)}``: N points of a Latin hypercube
      (``seed``); a tuple of paths ties ranges as in ``grid``.

    ``integrator``, ``accuracy``, ``end_time`` apply to every point (as the
    CLI's options). ``jobs`` threads (default: all cores).
    ``progress(done, total, failed)`` is called on the calling thread as
    points finish; it may return False to stop the sweep, as
    ``cancel.cancel()`` on a CancelToken does from any thread: running
    points stop at their next sample, finished ones are kept in ``out``
    (they resume), and Cancelled is raised. A sweep whose every point
    failed (bad input or a failed analysis; the CLI exits 1) raises
    AnalysisFailed naming the first point's diagnostic.

    Points whose start stalled or did not finish have that verdict as
    their ``status`` (``stalled``, ``unfinished``) and its text as their
    ``diagnostic``; ``on_failure`` says what a sweep with such points does:
    "warn" (default) warns StartNotCompletedWarning (how many, the first
    one's text; ``table`` the sweep's Table), "raise" raises
    StartNotCompleted (its ``table`` the Table), "ignore" nothing.

    Returns a Table: ``index``, the swept values (in the unit they were
    given in, ``SI`` otherwise), ``status`` (ok | bad_input | failed | a
    start's verdict), every result with its unit (NaN where a point has
    none: see ``status`` and ``diagnostic``). Only with ``out`` does the
    sweep's directory (``sweep.csv``, ``points/``) stay on disk.
    """
    _check_on_failure(on_failure)
    if not isinstance(model, Model):
        model = Model(model)
    grids = [_axis_option(k, v, False) for k, v in (grid or {}).items()]
    rng = [_axis_option(k, v, True) for k, v in (ranges or {}).items()]
    overrides = model.overrides + _overrides(integrator=integrator, accuracy=accuracy, end_time=end_time)
    directory = _os.fspath(out) if out is not None else _tempfile.mkdtemp(prefix="milldyn-sweep-")
    if progress is not None and not callable(progress):
        raise TypeError("progress must be callable as progress(done, total, failed)")
    try:
        summary = _core.sweep(_path(model.path), overrides, grids, rng, int(lhs or 0), int(seed),
                              int(jobs or _os.cpu_count() or 1), _path(directory), progress, cancel)
        table = _read_sweep_csv(_os.path.join(directory, "sweep.csv"))
    finally:
        if out is None:
            _shutil.rmtree(directory, ignore_errors=True)
    table.summary = _named(summary, "sweep summary key")
    if out is None:
        table.summary["files"] = []
    if summary["total"] > 0 and summary["errors"] == summary["total"]:
        first = table["diagnostic"][0] if len(table) else ""
        raise AnalysisFailed("milldyn: sweep failed: every one of its %d points failed (first: %s)"
                             % (summary["total"], first), first)
    _judge_sweep(model, table, on_failure)
    return table


# A point's status that is a start's verdict (driver/Sweep.cpp writes the
# verdict of driver/Api's verdictKind other than "done" as the status).
_VERDICT_STATUSES = ("stalled", "unfinished")


def _judge_sweep(model, table, on_failure):
    if on_failure == "ignore" or "status" not in table:
        return
    status = list(table["status"])
    bad = [i for i, s in enumerate(status) if s in _VERDICT_STATUSES]
    if not bad:
        return
    counts = ", ".join("%d %s" % (status.count(s), s) for s in _VERDICT_STATUSES if s in status)
    text = "sweep of %s: %d of %d points did not complete (%s; see the status and diagnostic columns); " \
           "first, point %d: %s" % (model.name, len(bad), len(status), counts, bad[0], table["diagnostic"][bad[0]])
    if on_failure == "raise":
        raise StartNotCompleted(text, table=table)
    _warnings.warn(StartNotCompletedWarning(text, table=table), stacklevel=3)


def _read_sweep_csv(path):
    # RFC 4180 (the csv module): a quoted path or name may hold commas,
    # quotes and line breaks.
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(_csv.reader(f))
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
    return _named(((e["type"], _element_entry(e)) for e in _core.elements()), "element type")


def analyses():
    """The analysis kinds a scenario may ask for, with their keys (as elements())."""
    return _named(((e["type"], _element_entry(e)) for e in _core.analyses()), "analysis kind")


def _element_entry(e):
    e["keys"] = _named(e["keys"], "key of %s" % e["type"])
    return e


def to_si(text, unit):
    """``to_si("1500 rpm", "rad/s")`` -> 157.07...: text with a unit to the SI
    unit a key wants (a bare number is SI already). Raises UnitError for text
    that does not parse, a unit of another dimension, or a ``unit`` that is
    not a coherent SI unit ("rpm", "xyz")."""
    return _core.to_si(_utf8(text, "text", UnitError), _utf8(unit, "unit", UnitError))


# The coherent SI unit of each unit name the parser knows (Units.h).
_SI_NAMES = {"kg": "kg", "g": "kg", "t": "kg", "m": "m", "mm": "m", "cm": "m", "um": "m", "km": "m",
             "L": "m^3", "s": "s", "ms": "s", "min": "s", "h": "s", "rad": "rad", "deg": "rad", "rev": "rad",
             "rpm": "rad/s", "Hz": "1/s", "N": "N", "kN": "N", "MN": "N", "Pa": "Pa", "kPa": "Pa", "MPa": "Pa",
             "GPa": "Pa", "W": "W", "kW": "W", "MW": "W", "J": "J", "kJ": "J", "%": "1", "A": "A"}


def _si_unit_of(text):
    """The unit of ``text`` with every unit name replaced by its coherent
    SI name ("20 kN*m" -> "N*m", "3 mm/min" -> "m/s"); None if unsure."""
    import re
    m = re.match(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*(.*?)\s*$", text)
    if not m or not m.group(3):
        return None
    unit = m.group(3)
    if unit in _SI_NAMES:  # one name: its SI unit as is ("rpm" -> "rad/s")
        return _SI_NAMES[unit]
    ok = True

    def name(match):
        nonlocal ok
        si = _SI_NAMES.get(match.group(0))
        if si is None:
            ok = False
            return match.group(0)
        return si if all(c not in si for c in "/^*") else "(%s)" % si

    out = re.sub(r"[A-Za-z%]+", name, unit)
    return out if ok else None


def quantity(text):
    """``quantity("20 kN*m")`` -> Value(20000.0, "N*m"): text with a unit to
    its SI value, in the SI units of the names it was written with ("rpm" ->
    "rad/s", "kN*m" -> "N*m", "%" -> "1"); UnitError if it does not parse."""
    text = _utf8(text, "text", UnitError)
    value, dimension = _core.parse_quantity(text)
    unit = _si_unit_of(text)
    if unit is not None:
        try:
            return Value(_core.to_si(text, unit), unit)
        except MilldynError:
            pass
    # Names the table above does not know: the unit a designer reads for
    # the dimension (N*m for kg*m^2/s^2 written with N, ...), else the
    # dimension's canonical text.
    return Value(value, _preferred_unit(dimension, (text,)) or dimension)
