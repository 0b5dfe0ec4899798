"""compare()'s options, declared once (compare/comparison_options.h): the command line, Python
and a study file take the same default and refuse the same value outside the declared range."""

import inspect
import json
import math

import pytest

import shockmap
from support import cli_error_message, read_only, write_json

# A point of the paper's problem that runs in milliseconds.
RK, RFTRUNC = 100, 10
OPTIONS = shockmap.COMPARE_OPTIONS
NUMBERS = [k for k, o in OPTIONS.items() if "choices" not in o]
CHOICES = [k for k, o in OPTIONS.items() if "choices" in o]


def _outside(option):
    """Values just outside the range: its lower bound when strict (else one below), and twice its
    upper bound (one above for a whole number) when it has one."""
    low, high = option["low"], option["high"]
    values = [low if option["low_strict"] else low - 1]
    if math.isfinite(high):
        values.append(high + 1 if option["whole"] else 2 * high)
    return [int(v) if option["whole"] else v for v in values]


def _shown(value):
    """`value` as the command line is given it, and as its refusal names it again."""
    if isinstance(value, str):
        return value
    return str(int(value)) if float(value).is_integer() and abs(value) < 1e15 else repr(value)


def _point(study_key, value):
    point = {"rk": RK, "rftrunc": RFTRUNC}
    head, _, tail = study_key.partition(".")
    point[head] = {tail: value} if tail else value
    return point


def _study(folder, points):
    return write_json(folder / "options.json",
                      {"kind": "canonical", "name": "options", "points": points})


def _arguments(keyword, value):
    arguments = {"rk": RK, "rftrunc": RFTRUNC}
    arguments[keyword] = value
    return arguments


def _flags(arguments):
    return [text for k, v in arguments.items() for text in (OPTIONS[k]["flag"], _shown(v))]


@pytest.fixture(scope="module")
def stored_point(tmp_path_factory, cli):
    """The point (RK, RFTRUNC), nothing else given, as a study file stores it: its parameter
    and score rows."""
    folder = tmp_path_factory.mktemp("options")
    db = folder / "options.db"
    cli("study", "run", _study(folder, [{"rk": RK, "rftrunc": RFTRUNC}]), "--db", db, "--quiet")
    with read_only(db) as connection:
        connection.row_factory = lambda cursor, row: {
            c[0]: v for c, v in zip(cursor.description, row)}
        return connection.execute(
            "SELECT * FROM points JOIN scores USING (point_id)").fetchone()


def test_python_keywords_default_to_the_declaration():
    parameters = inspect.signature(shockmap.compare).parameters
    for keyword, option in OPTIONS.items():
        assert parameters[keyword].default == (
            option["default"] if option["default"] is not None else
            inspect.Parameter.empty if keyword in ("rk", "rftrunc") else None), keyword


def test_python_and_the_command_line_take_the_same_reference_truncation(cli):
    """Without rfref, both apply the studies' rule max(3000, 10 sqrt(R_k)): 1e4 at R_k = 1e6."""
    arguments = {"rk": 1e6, "rftrunc": RFTRUNC, "window_s": 0.005}
    command_line = json.loads(cli("compare", *_flags(arguments), "--json").stdout)
    python = shockmap.compare(**arguments).summary
    assert command_line["r_fref"] == python["r_fref"] == 1e4


def test_the_three_front_ends_run_the_declared_defaults(cli, stored_point):
    command_line = json.loads(cli("compare", *_flags({"rk": RK, "rftrunc": RFTRUNC}),
                                  "--json").stdout)
    python = shockmap.compare(RK, RFTRUNC).summary
    stored = stored_point
    assert OPTIONS["dt_rule"]["default"] == "sharp"
    for run in (command_line, python):
        assert run["window_s"] == OPTIONS["window_s"]["default"]
        assert run["scheme"] == OPTIONS["scheme"]["default"]
        assert run["dt_requested_s"] == OPTIONS["dt_factor"]["default"] * run["dt_sharp_s"]
        assert run["n_elements"] == stored["n_elements"]
    assert stored["window_s"] == OPTIONS["window_s"]["default"]
    assert stored["scheme"] == OPTIONS["scheme"]["default"]
    assert stored["dt_rule"] == OPTIONS["dt_rule"]["default"]
    assert stored["dt_factor"] == OPTIONS["dt_factor"]["default"]
    assert stored["dt_asked_s"] is None
    assert stored["n_elements_asked"] == OPTIONS["elements"]["default"]
    assert stored["dt_requested_s"] == command_line["dt_requested_s"]


@pytest.mark.parametrize("keyword", NUMBERS)
def test_the_three_front_ends_refuse_a_value_outside_the_declared_range(keyword, cli, tmp_path):
    option = OPTIONS[keyword]
    refusal = "is out of range: must be " + option["allowed"]
    for value in _outside(option):
        done = cli("compare", *_flags(_arguments(keyword, value)), expect=2)
        assert f"{option['flag']}: value {_shown(value)} {refusal}" in done.stderr, done.stderr
        with pytest.raises(shockmap.InputError) as raised:
            shockmap.compare(**_arguments(keyword, value))
        message = str(raised.value)
        assert message.startswith(f"{keyword}: value ") and refusal in message, message
        if not option["study_key"]:
            continue  # A study sets it by its reference policy.
        study = _study(tmp_path, [_point(option["study_key"], value)])
        done = cli("study", "run", study, "--db", tmp_path / "s.db", expect=2)
        message = cli_error_message(done.stderr)
        assert message.startswith(f"{study}: points[0].{option['study_key']}: value "), message
        assert refusal in message, message


@pytest.mark.parametrize("keyword", CHOICES)
def test_the_three_front_ends_refuse_a_word_not_declared(keyword, cli, tmp_path):
    option = OPTIONS[keyword]
    done = cli("compare", *_flags(_arguments(keyword, "fast")), expect=2)
    assert option["flag"] in done.stderr and "fast" in done.stderr
    assert all(choice in done.stderr for choice in option["choices"])
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.compare(**_arguments(keyword, "fast"))
    assert str(raised.value) == f'{keyword}: "fast" is not allowed: must be {option["allowed"]}'
    study = _study(tmp_path, [_point(option["study_key"], "fast")])
    done = cli("study", "run", study, "--db", tmp_path / "s.db", expect=2)
    assert cli_error_message(done.stderr) == (
        f'{study}: points[0].{option["study_key"]}: "fast" is not allowed: must be '
        f'{option["allowed"]}')
