"""The exceptions milldyn raises; each carries the text the CLI prints."""


class MilldynError(Exception):
    """Base of milldyn's exceptions. ``text`` is what ``milldyn`` prints."""

    def __init__(self, text):
        super().__init__(text)
        self.text = text


class ModelError(MilldynError, ValueError):
    """Bad input (CLI exit code 2): a model file, an override, a plugin.

    ``text`` is the CLI's one line ``file:line:col: error: key: reason``;
    ``file``, ``line``, ``column``, ``key`` and ``reason`` its parts, and
    ``included_from`` the include chain of a value from a part file.
    """

    def __init__(self, text, file="", line=0, column=0, key="", reason="", included_from=""):
        super().__init__(text)
        self.file, self.line, self.column = file, line, column
        self.key, self.reason, self.included_from = key, reason, included_from


class ModelFileNotFound(ModelError, FileNotFoundError):
    """The model file (or a part it includes) does not exist: a ModelError
    (CLI exit code 2) that ``except FileNotFoundError`` catches too;
    ``filename`` is the missing file."""

    def __init__(self, text, file="", line=0, column=0, key="", reason="", included_from="", filename=""):
        ModelError.__init__(self, text, file, line, column, key, reason, included_from)
        import errno
        self.errno, self.strerror, self.filename = errno.ENOENT, "No such file or directory", filename or file

    def __str__(self):
        return self.text


class AnalysisFailed(MilldynError, RuntimeError):
    """The analysis failed (CLI exit code 1); ``reason`` names the element or
    quantity and the simulated time."""

    def __init__(self, text, reason=""):
        super().__init__(text)
        self.reason = reason


class OutputFailed(MilldynError, OSError):
    """A file could not be written (CLI exit code 1)."""

    def __init__(self, text, reason=""):
        MilldynError.__init__(self, text)
        self.reason = reason

    def __str__(self):
        return self.text


class Cancelled(MilldynError):
    """A run stopped because its CancelToken was set."""


class UnitError(MilldynError, ValueError):
    """A quantity or unit that does not parse (``column``: 0-based offset)."""

    def __init__(self, text, column=0):
        super().__init__(text)
        self.column = column


class StartNotCompleted(MilldynError, RuntimeError):
    """A run that did not do what was asked, raised by ``run(...,
    on_failure="raise")``: its verdict is ``stalled`` (the CLI exits 3) or
    ``unfinished`` (a start, a run-out or a starting sequence not finished
    by end_time: no start time or steady values). ``result`` is the run's
    Result (tables, summary, files written), ``verdict`` its Verdict; from
    ``sweep(..., on_failure="raise")``, ``table`` is the sweep's Table and
    ``result`` None."""

    def __init__(self, text, result=None, table=None):
        super().__init__(text)
        self.result = result
        self.table = table
        self.verdict = result.verdict if result is not None else None


class StartNotCompletedWarning(UserWarning):
    """Warned by ``run()`` (``on_failure="warn"``, the default) for a run whose
    verdict is ``stalled`` or ``unfinished``, and by ``sweep()`` for a sweep
    with such points; the message is the verdict's text. ``result`` is the
    run's Result (None for a sweep's warning, whose ``table`` is the sweep's
    Table)."""

    def __init__(self, text, result=None, table=None):
        super().__init__(text)
        self.result = result
        self.table = table
