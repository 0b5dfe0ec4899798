"""shockmap from Python: the library's runs, studies and database as NumPy arrays and pandas
DataFrames (docs/python.md).

Runs release the GIL, so Python threads run several at once. Bad input raises InputError (a
ValueError) with the command line's own message; database faults raise DatabaseError.
"""

import inspect as _inspect
import json as _json

try:
    import numpy as _np  # noqa: F401 (the compiled part returns NumPy arrays)
    import pandas as _pd

    from . import _shockmap
except ImportError as _error:
    from ._interpreter import import_failure as _import_failure

    raise ImportError(_import_failure(_error)) from _error
from ._shockmap import Comparison, DatabaseError, InputError, SceneRun as _SceneRun

__version__ = _shockmap.__version__
__all__ = [
    "Comparison", "DatabaseError", "InputError", "Scene", "SceneRun", "Study", "check_advice",
    "compare", "criteria", "point", "query", "reference", "report", "results", "simulate",
    "sizing",
]

DEFAULT_DATABASE = "shockmap.db"
_ID_MAX = 2**63 - 1  # An SQLite integer: row ids.


def _excerpt(text):
    """At most 40 characters of `text` for a message, control characters escaped."""
    shown = text[:40].encode("unicode_escape").decode("ascii")
    return shown + ("..." if len(text) > 40 else "")


def _text(name, value):
    """`value` (a str or a path) as str; InputError naming `name` when it holds a NUL byte, which
    ends a path, a name or SQL text for the library (and would cut its messages short)."""
    text = str(value)
    if "\0" in text:
        raise InputError(f'{name}: "{_excerpt(text)}" holds a NUL byte at character '
                         f"{text.index(chr(0))}; a path, a name or SQL text cannot hold one")
    return text


def _integer(name, value, low, high):
    """`value` as int; InputError naming `name` when it lies outside [low, high]."""
    number = int(value)
    if not low <= number <= high:
        bits = number.bit_length()
        shown = number if bits <= 256 else f"an integer of {bits} bits"
        raise InputError(f"{name}: {shown} is outside [{low}, {high}]")
    return number


def _real(value):
    """`value` as float, an int beyond a float's range as an infinity of its sign, so that the
    library names it as out of its range."""
    try:
        return float(value)
    except OverflowError:
        return float("inf") if value > 0 else float("-inf")


def _database(db):
    """`db` as the path of a study database; InputError for SQLite's database in memory, where a
    study would be lost as soon as the call returns."""
    path = _text("db", db)
    if path == ":memory:":
        raise InputError("db: \":memory:\" names SQLite's database in memory, which keeps nothing "
                         "once the call returns; it must name a database file (./:memory: for a "
                         "file of that name)")
    return path


# compare()'s options as declared once for the command line, Python and study files
# (compare/comparison_options.h), by keyword: defaults, ranges and help.
COMPARE_OPTIONS = {option["keyword"]: option for option in _shockmap.compare_options()}


def _compare_signature():
    """compare()'s signature, made from the declarations: the required options first, then the
    others keyword-only with their declared defaults (None where a rule sets the value)."""
    required = [_inspect.Parameter(keyword, _inspect.Parameter.POSITIONAL_OR_KEYWORD)
                for keyword, option in COMPARE_OPTIONS.items() if option.get("required")]
    optional = [_inspect.Parameter(keyword, _inspect.Parameter.KEYWORD_ONLY,
                                   default=option["default"])
                for keyword, option in COMPARE_OPTIONS.items() if not option.get("required")]
    return _inspect.Signature(required + optional)


def _option_value(keyword, value):
    """A value of a declared option as the library reads it: a word as str, a number as float;
    None (not given) as it is."""
    if value is None:
        return None
    if "choices" in COMPARE_OPTIONS[keyword]:
        return _text(keyword, value)
    return _real(value)


def compare(*args, **kwargs):
    """One run of the paper's problem scored against its reference, as `shockmap compare`;
    each option's help, unit and range are in COMPARE_OPTIONS, from which the signature is made."""
    given = compare.__signature__.bind(*args, **kwargs).arguments
    return _shockmap.compare({keyword: _option_value(keyword, value)
                              for keyword, value in given.items()})


compare.__signature__ = _compare_signature()


def _score(self, name):
    return self.scores[name]


Comparison.err = property(lambda self: _score(self, "err"), doc="Err, paper eq. 8")
Comparison.srf = property(lambda self: _score(self, "srf"), doc="SRf, paper eq. 9")
Comparison.pfr = property(lambda self: _score(self, "pfr"), doc="PFr, first shock's peak force ratio")
Comparison.summary = property(lambda self: _json.loads(self.summary_json),
                              doc="The comparison as `shockmap compare --json` prints it")
Comparison.__repr__ = lambda self: (
    f"<shockmap.Comparison status={self.status} err={self.err} srf={self.srf}>")


class Scene:
    """A scene file, checked as `shockmap simulate` checks it."""

    def __init__(self, handle):
        self._handle = handle

    @classmethod
    def load(cls, path):
        return cls(_shockmap.Scene.load(_text("path", path)))

    @classmethod
    def from_dict(cls, scene, path="<dict>"):
        """`path` names the scene in messages; data files are found beside it."""
        return cls(_shockmap.Scene.from_json_text(_json.dumps(scene), _text("path", path)))

    def to_dict(self):
        return _json.loads(self._handle.json_text())

    def set(self, key, value):
        """Sets the parameter `key` ("bundle.wire.stiffness_n_per_m", "zones[0].gap_m") to a
        value of the type the scene holds there; the scene is checked again."""
        self._handle.set(_text("key", key), _json.dumps(value))
        return self

    @property
    def name(self):
        return self._handle.name

    @property
    def path(self):
        return self._handle.path

    def __repr__(self):
        return f"<shockmap.Scene {self.name!r} from {self.path}>"


class SceneRun:
    """One simulation: its summary (as `simulate --json`), zones and histories."""

    def __init__(self, handle):
        self._handle = handle
        self.summary = _json.loads(handle.summary_json)

    def __getattr__(self, name):
        if name in ("status", "message", "steps", "dt_s", "dt_paper_s", "dt_sharp_s",
                    "coordinates", "distinct_bases", "max_energy_ratio", "wall_s", "cpu_s",
                    "build_wall_s"):
            return self.summary[name]
        raise AttributeError(name)

    @property
    def dt_used_s(self):
        return self.summary["dt_s"]

    @property
    def modes_per_beam(self):
        return self._handle.modes_per_beam

    @property
    def histories(self):
        """Arrays named as the CSV columns of `simulate --out`, with their times "t_s"."""
        return self._handle.histories

    @property
    def zones(self):
        """One row per zone: where it is, its largest force, its shocks and impact statistics
        when the scene asks for them."""
        rows = []
        for zone in self.summary.get("zone_results", []):
            row = {"zone" if k == "name" else k: v for k, v in zone.items()
                   if not isinstance(v, (dict, list))}
            row["y_m"], row["z_m"] = zone["position_m"]
            for group in ("shocks", "impact_statistics"):
                for k, v in (zone.get(group) or {}).items():
                    if not isinstance(v, (dict, list)):
                        row[f"{group}.{k}"] = v
            rows.append(row)
        return _pd.DataFrame(rows)


def simulate(scene, progress=False):
    """Runs `scene` (a Scene or a path) with the explicit modal solver. SIGINT, SIGTERM or
    SIGHUP stops it and goes to the program's handler (Ctrl-C: KeyboardInterrupt); when that
    handler returns, InterruptedError (a stopped simulation has no result)."""
    if not isinstance(scene, Scene):
        scene = Scene.load(scene)
    return SceneRun(_shockmap.simulate(scene._handle, bool(progress)))


class Study:
    """A study file, checked whole as `shockmap study run` checks it."""

    def __init__(self, handle):
        self._handle = handle

    @classmethod
    def load(cls, path):
        return cls(_shockmap.Study.load(_text("path", path)))

    name = property(lambda self: self._handle.name)
    kind = property(lambda self: self._handle.kind)
    path = property(lambda self: self._handle.path)

    def run(self, db=DEFAULT_DATABASE, jobs=None, retry_failed=False, progress=False):
        """Computes every missing point into `db` (resumable) and returns the run's summary.

        progress: False, True (the command line's progress lines on stderr), or a callable
        progress(phase, done, total). Ctrl-C stops the run as it stops `study run`: the points
        computed are stored, the others stay pending, and KeyboardInterrupt is raised."""
        if jobs is not None:
            jobs = _integer("jobs", jobs, 1, 1024)
        return self._handle.run(_database(db), jobs, bool(retry_failed), progress)

    def __repr__(self):
        return f"<shockmap.Study {self.name!r} ({self.kind}) from {self.path}>"


_UNITS = _shockmap.column_units()


def _frame(table):
    frame = _pd.DataFrame.from_records(table["rows"], columns=table["columns"])
    units = {}
    for column in frame.columns:
        unit = _UNITS.get(column, _UNITS.get(column[4:]) if column.startswith("ref_") else None)
        if unit is not None:
            units[column] = unit
    frame.attrs["units"] = units
    return frame


def query(db, sql, *parameters):
    """One read-only SQL statement, as `shockmap query`; ?1, ?2 ... bound to `parameters`
    (None, int, float or str)."""
    return _frame(_shockmap.query(_database(db), _text("sql", sql), list(parameters)))


_RESULTS_VIEW = {"canonical": "results", "scene_sweep": "scene_results",
                 "scene_ensemble": "ensemble_results"}


def results(db=DEFAULT_DATABASE, study=None):
    """The study's rows of its results view (`results`, `scene_results` or `ensemble_results`),
    ordered by point; frame.attrs["units"] gives each declared column's unit."""
    name, kind = _shockmap.study_and_kind(_database(db), _text("study", study or ""))
    view = _RESULTS_VIEW[kind]
    order = "point_id" if kind != "scene_ensemble" else "1"
    return query(db, f"SELECT * FROM {view} WHERE study = ?1 ORDER BY {order}", name)


def _thresholds(keywords):
    """Thresholds given as keywords (err_max=0.1, srf_min=0.9) by score name (err, srf)."""
    given = {}
    for key, value in keywords.items():
        for suffix in ("_max", "_min"):
            if key.endswith(suffix):
                given[key[: -len(suffix)]] = float(value)
                break
        else:
            raise InputError(f"{key}: not a threshold; give NAME_max or NAME_min (err_max, srf_min)")
    return given


def criteria(db=DEFAULT_DATABASE, study=None, **thresholds):
    """The validity criteria of a study of the paper's problem, one row per R_k, as `criteria
    derive` derives them; thresholds (err_max=0.1, srf_min=0.9, ...) over the study's own."""
    given = _thresholds(thresholds)
    data = _json.loads(_shockmap.criteria_json(_database(db), _text("study", study or ""), given))
    frame = _pd.DataFrame(data["boundary"])
    frame.attrs["criteria"] = data
    return frame


def sizing(db=DEFAULT_DATABASE, study=None, wear=False, quantile=0.95, confidence=0.95):
    """The sizing table of an ensemble study, as `sizing --format csv` (`--wear` with wear)."""
    return _frame(_shockmap.sizing(_database(db), _text("study", study or ""), bool(wear),
                                   float(quantile), float(confidence)))


def reference(db, reference_id, scene=False):
    """A stored reference's signals as arrays ("t_s" first), by its id in reference_runs, or in
    scene_references with scene=True."""
    return _shockmap.reference(_database(db), _integer("reference_id", reference_id, 1, _ID_MAX),
                               bool(scene))


def point(db, study, point_id):
    """A stored point of the paper's problem computed again against its stored reference."""
    return _shockmap.point(_database(db), _text("study", study),
                           _integer("point_id", point_id, 1, _ID_MAX))


def _progress(progress):
    """A workflow's progress: a callable progress(phase, done, total) as given, else a bool."""
    return progress if callable(progress) else bool(progress)


def report(db=DEFAULT_DATABASE, study=None, *, out, progress=False, **thresholds):
    """The HTML report of a stored study into the folder `out`, as `shockmap report`; returns
    the path of its index.html. thresholds (err_max=0.1, srf_min=0.9, ...) over the study's own;
    progress: True prints what is drawn, a callable gets ("Fig. 3 of point N", done, total).
    A report refused half-way leaves no folder it created."""
    return _shockmap.report(_database(db), _text("study", study or ""), _thresholds(thresholds),
                            _text("out", out), _progress(progress))


def check_advice(study, db=DEFAULT_DATABASE, *, criteria=None, members=None, window_s=None,
                 states=None, jobs=None, quantile=None, tolerance=None, max_rungs=None,
                 record=None, write_study=None, progress=False):
    """The advice for an ensemble study's scene checked on its members, as `shockmap
    check-advice STUDY`: the ensemble run into `db` at the advised truncations and dt, a third
    of them and 3, 9, ... times until each zone family's sizing quantile stops moving.

    Options left None take the command line's defaults (criteria: SCENE_CRITERIA from the
    working folder; members and window_s: the study file's; every clearance state); each given
    one is checked as its flag is. Returns a dict: the advice (dt_ratio, r_ftrunc per beam,
    warnings) and, unless write_study names a file for the ladder's study instead, the check:
    verdict (text), table (DataFrame, one row per state and zone family), factors,
    cpu_s_per_member, converged, undecided. record: an outcomes file a decided check is added
    to. progress: True prints the command line's lines, a callable gets the study engine's
    (phase, done, total) of each rung's run. Ctrl-C stops it as it stops `check-advice`: the
    members computed are stored."""
    if states is not None:
        states = [_text("states", state) for state in ([states] if isinstance(states, str)
                                                        else states)]
    result = _shockmap.check_advice(
        _text("study", study), _database(db), None if criteria is None else _text("criteria",
                                                                                 criteria),
        members, window_s, states or [], jobs, quantile, tolerance, max_rungs,
        "" if record is None else _text("record", record),
        "" if write_study is None else _text("write_study", write_study), _progress(progress))
    if "table" in result:
        result["table"] = _frame(result["table"])
    return result


SCENE_CRITERIA = _shockmap.SCENE_CRITERIA
