"""shockmap.Study, results, query, criteria and sizing against `shockmap study run`, `query`,
`criteria derive` and `sizing` on the same files."""

import csv
import io
import json
import math
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time

import pytest

import shockmap
from support import NUL_REFUSAL, cli_error_message, read_only, write_json

CANONICAL = {
    "kind": "canonical",
    "name": "small_grid",
    "scoring": {"window_s": 0.03},
    "grids": [
        {
            "rk": [10, 100, 1000, 3000],
            "rftrunc": [10, 30, 100, 300],
            "dt": {"rule": "sharp", "factor": [0.1]},
        }
    ],
}
N_POINTS = 16
RK = [10.0, 100.0, 1000.0, 3000.0]


def ensemble(source_dir, name, members, window_s):
    """The hexagonal 7-pin ensemble of studies/bundle_hex_ensemble.json, cut down."""
    spec = json.loads((source_dir / "studies" / "bundle_hex_ensemble.json").read_text())
    spec.update(
        name=name,
        members=members,
        window_s=window_s,
        scene=str(source_dir / "scenes" / "bundle_hex_7.json"),
    )
    return spec


@pytest.fixture(scope="module")
def canonical(tmp_path_factory):
    """The small canonical grid run through the module: (study file, database, summary)."""
    folder = tmp_path_factory.mktemp("study")
    path = write_json(folder / "small_grid.json", CANONICAL)
    db = folder / "small_grid.db"
    summary = shockmap.Study.load(path).run(db=db, jobs=2)
    return path, db, summary


@pytest.fixture(scope="module")
def small_ensemble(tmp_path_factory, source_dir):
    """Three members in each of two clearance states, 0.05 s each: (database, study name)."""
    folder = tmp_path_factory.mktemp("ensemble")
    path = write_json(folder / "tiny_ensemble.json", ensemble(source_dir, "tiny_ensemble", 3, 0.05))
    db = folder / "tiny_ensemble.db"
    shockmap.Study.load(path).run(db=db, jobs=2)
    return db, "tiny_ensemble"


def missing(value):
    return value is None or value == "" or (isinstance(value, float) and math.isnan(value))


def same_cell(printed, value):
    """A cell as the command line prints it (CSV) against the DataFrame's value."""
    if missing(printed) or missing(value):
        return missing(printed) and missing(value)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(printed) == float(value)  # Printed digits read back as the same double.
    return printed == str(value)


def assert_frame_matches_csv(frame, printed, sort_by=None):
    """The DataFrame holds the rows the command line printed as CSV, exactly."""
    rows = list(csv.reader(io.StringIO(printed)))
    header, rows = rows[0], rows[1:]
    assert list(frame.columns) == header
    records = frame.astype(object).where(frame.notna(), None).values.tolist()
    if sort_by is not None:
        key = header.index(sort_by)
        rows.sort(key=lambda row: float(row[key]))
        records.sort(key=lambda row: float(row[key]))
    assert len(records) == len(rows)
    for printed_row, row in zip(rows, records):
        for column, printed_cell, cell in zip(header, printed_row, row):
            assert same_cell(printed_cell, cell), (column, printed_cell, cell, printed_row)


def test_load_gives_name_and_kind(canonical, tmp_path, source_dir):
    path, _, _ = canonical
    study = shockmap.Study.load(path)
    assert (study.name, study.kind) == ("small_grid", "canonical")
    sweep = shockmap.Study.load(source_dir / "studies" / "bundle_row_truncation.json")
    assert (sweep.name, sweep.kind) == ("bundle_row_truncation", "scene_sweep")
    spec = ensemble(source_dir, "e", 3, 0.05)
    ensemble_study = shockmap.Study.load(write_json(tmp_path / "e.json", spec))
    assert ensemble_study.kind == "scene_ensemble"


def test_run_stores_every_point_and_a_second_run_computes_none(canonical):
    path, db, summary = canonical
    assert summary["points_computed"] == N_POINTS
    with read_only(db) as connection:
        before = connection.execute(
            "SELECT point_id, status, updated_utc FROM points ORDER BY point_id"
        ).fetchall()
    assert len(before) == N_POINTS and {row[1] for row in before} == {"ok"}
    again = shockmap.Study.load(path).run(db=db)
    assert again["points_computed"] == 0
    with read_only(db) as connection:
        after = connection.execute(
            "SELECT point_id, status, updated_utc FROM points ORDER BY point_id"
        ).fetchall()
        runs = connection.execute("SELECT end_reason FROM runs ORDER BY run_id").fetchall()
    assert after == before
    assert runs == [("completed",), ("completed",)]


def test_the_module_and_the_command_line_store_the_same_scores(canonical, tmp_path, cli):
    path, db, _ = canonical
    cli_db = tmp_path / "cli.db"
    cli("study", "run", path, "--db", cli_db, "--quiet")
    sql = "SELECT r_k, r_ftrunc, status, err, srf, pfr, steps FROM results ORDER BY r_k, r_ftrunc"
    with read_only(db) as module_run, read_only(cli_db) as cli_run:
        assert module_run.execute(sql).fetchall() == cli_run.execute(sql).fetchall()


def test_results_are_the_rows_query_prints(canonical, cli):
    _, db, _ = canonical
    frame = shockmap.results(db, "small_grid")
    printed = cli(
        "query", "--db", db, "SELECT * FROM results WHERE study = 'small_grid'", "--format", "csv"
    ).stdout
    assert len(frame) == N_POINTS
    assert_frame_matches_csv(frame, printed, sort_by="point_id")
    assert frame["err"].dtype == float and frame["steps"].dtype.kind == "i"


def test_results_carry_units_in_the_column_metadata(canonical):
    _, db, _ = canonical
    units = shockmap.results(db).attrs["units"]
    assert units["dt_used_s"] == "s" and units["window_s"] == "s"
    assert units["first_shock_peak_n"] == "N"
    assert units["first_shock_impulse_n_s"] == "N s"
    assert set(units) <= set(shockmap.results(db).columns)


def test_query_with_parameters_is_the_command_line_s_query(canonical, cli):
    _, db, _ = canonical
    frame = shockmap.query(db, "SELECT r_k, r_ftrunc, err, srf FROM results WHERE r_k > ?", 500)
    printed = cli(
        "query", "--db", db, "SELECT r_k, r_ftrunc, err, srf FROM results WHERE r_k > 500",
        "--format", "csv",
    ).stdout
    assert len(frame) == 8
    assert_frame_matches_csv(frame, printed)


def test_query_binds_parameters_with_their_types(canonical):
    _, db, _ = canonical
    frame = shockmap.query(db, "SELECT ?1 AS x, typeof(?1) AS tx, typeof(?2) AS ti, ?3 IS NULL AS n",
                           1.5, 2, None)
    assert frame["x"][0] == 1.5
    assert list(frame.loc[0, ["tx", "ti", "n"]]) == ["real", "integer", 1]
    unscored = shockmap.query(db, "SELECT count(*) AS n FROM results WHERE dt_asked_s IS ?", None)
    assert unscored["n"][0] == N_POINTS
    with pytest.raises(shockmap.InputError, match=r"parameters\[0\]: a list cannot be bound"):
        shockmap.query(db, "SELECT ?", [1])


def test_query_refuses_to_write(canonical):
    _, db, _ = canonical
    with pytest.raises(shockmap.DatabaseError):
        shockmap.query(db, "DELETE FROM points")
    assert len(shockmap.query(db, "SELECT point_id FROM points")) == N_POINTS


def test_missing_database_raises_and_creates_nothing(tmp_path):
    absent = tmp_path / "absent.db"
    with pytest.raises(shockmap.DatabaseError, match="absent.db"):
        shockmap.results(absent)
    assert not absent.exists()


def test_the_database_in_memory_is_refused_by_every_call_taking_db(tmp_path):
    path = write_json(tmp_path / "s.json", CANONICAL)
    calls = [
        lambda: shockmap.Study.load(path).run(db=":memory:"),
        lambda: shockmap.results(":memory:"),
        lambda: shockmap.query(":memory:", "SELECT 1"),
        lambda: shockmap.criteria(":memory:"),
        lambda: shockmap.sizing(":memory:"),
        lambda: shockmap.reference(":memory:", 1),
        lambda: shockmap.point(":memory:", "s", 1),
    ]
    for call in calls:
        with pytest.raises(shockmap.InputError, match='db: ":memory:" names SQLite\'s database in '
                           "memory, which keeps nothing once the call returns"):
            call()


def test_criteria_has_one_row_per_rk_as_criteria_derive(canonical, tmp_path, cli):
    _, db, _ = canonical
    frame = shockmap.criteria(db, "small_grid")
    out = tmp_path / "criteria.json"
    cli("criteria", "derive", "small_grid", "--db", db, "--out", out)
    derived = json.loads(out.read_text())
    assert list(frame["r_k"]) == RK == [row["r_k"] for row in derived["boundary"]]
    assert list(frame["r_ftrunc_min"]) == [row["r_ftrunc_min"] for row in derived["boundary"]]
    # Below the knee a coarse truncation passes; at R_k = 3000 it needs more than sqrt(R_k).
    boundary = dict(zip(frame["r_k"], frame["r_ftrunc_min"]))
    assert boundary[10.0] == 10.0 and boundary[3000.0] > math.sqrt(3000.0)


def test_progress_callback_sees_every_point(tmp_path):
    path = write_json(tmp_path / "small_grid.json", CANONICAL)
    seen = []
    shockmap.Study.load(path).run(
        db=tmp_path / "progress.db", jobs=1, progress=lambda *report: seen.append(report)
    )
    assert seen, "the callback was never called"
    for phase, done, total in seen:
        assert isinstance(phase, str) and 0 <= done <= total
    points = [(done, total) for phase, done, total in seen if total == N_POINTS]
    assert points and points[-1] == (N_POINTS, N_POINTS)


@pytest.mark.parametrize(
    "fault, value",
    [
        ("short_logspace", {"logspace": [0, 5]}),
        ("negative_rk", [-1.0]),
        ("text_rk", "many"),
    ],
)
def test_bad_study_file_raises_the_command_line_s_message(tmp_path, cli, fault, value):
    spec = json.loads(json.dumps(CANONICAL))
    spec["grids"][0]["rk"] = value
    path = write_json(tmp_path / f"{fault}.json", spec)
    db = tmp_path / f"{fault}.db"
    expected = cli_error_message(cli("study", "run", path, "--db", db, expect=2).stderr)
    assert str(path) in expected and "grids[0].rk" in expected
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.Study.load(path).run(db=db)
    assert str(raised.value) == expected
    assert not db.exists()


def test_scene_sweep_results_are_scene_results(tmp_path, source_dir, cli):
    spec = {
        "kind": "scene_sweep",
        "name": "tip_truncation",
        "scene": str(source_dir / "scenes" / "cantilever_spring.json"),
        "sweep": {"solver.r_ftrunc": [10, 30]},
        "reference": {"solver.r_ftrunc": 100},
        "scoring": {
            "displacement": "tip",
            "zone": "tip_spring",
            "window_s": 0.03,
            "rest_duration_s": 0.0052,
        },
    }
    path = write_json(tmp_path / "sweep.json", spec)
    db = tmp_path / "sweep.db"
    shockmap.Study.load(path).run(db=db)
    frame = shockmap.results(db, "tip_truncation")
    printed = cli("query", "--db", db, "SELECT * FROM scene_results", "--format", "csv").stdout
    assert len(frame) == 2 and set(frame["status"]) == {"ok"}
    assert_frame_matches_csv(frame, printed, sort_by="point_id")


def test_sizing_is_the_command_line_s_table(small_ensemble, cli):
    db, name = small_ensemble
    frame = shockmap.sizing(db, name)
    printed = cli("sizing", name, "--db", db, "--format", "csv").stdout
    assert_frame_matches_csv(frame, printed)
    assert set(frame["state"]) == {"new", "end_of_life"}
    members = shockmap.query(db, "SELECT count(*) AS n FROM ensemble_members WHERE status = 'ok'")
    assert members["n"][0] == 6


INTERRUPTED_RUN = textwrap.dedent(
    """
    import sys
    import shockmap
    study = shockmap.Study.load(sys.argv[1])
    try:
        study.run(db=sys.argv[2], jobs=1)
    except KeyboardInterrupt:
        print("KeyboardInterrupt", flush=True)
        sys.exit(0)
    print("finished", flush=True)
    """
)


def test_ctrl_c_stops_the_run_as_sigint_does(tmp_path, source_dir):
    path = write_json(tmp_path / "long.json", ensemble(source_dir, "long_ensemble", 60, 0.3))
    db = tmp_path / "long.db"
    child = subprocess.Popen(
        [sys.executable, "-c", INTERRUPTED_RUN, str(path), str(db)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and child.poll() is None:
            time.sleep(0.05)
            if db.exists() and stored_members(db) >= 1:
                break
        assert child.poll() is None, f"the run ended uninterrupted: {child.stdout.read()}"
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
    assert child.returncode == 0 and out.strip() == "KeyboardInterrupt", (out, err)
    with read_only(db) as connection:
        runs = connection.execute("SELECT end_reason FROM runs").fetchall()
        statuses = dict(
            connection.execute("SELECT status, count(*) FROM ensemble_members GROUP BY status")
        )
    assert runs == [("interrupted",)]
    assert statuses.get("ok", 0) >= 1 and statuses.get("pending", 0) >= 1
    assert "running" not in statuses
    assert sum(statuses.values()) == 120


def stored_members(db):
    try:
        with read_only(db) as connection:
            return connection.execute(
                "SELECT count(*) FROM ensemble_members WHERE status = 'ok'"
            ).fetchone()[0]
    except sqlite3.Error:  # The run has not created its tables yet.
        return 0


def test_criteria_of_an_ensemble_are_refused_as_the_command_line_refuses_them(small_ensemble, cli):
    db, name = small_ensemble
    printed = cli("criteria", "derive", name, "--db", db, expect=2)
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.criteria(db, name)
    assert str(raised.value) == cli_error_message(printed.stderr)
    assert "shockmap sizing" in str(raised.value)


INT64 = "[-9223372036854775808, 9223372036854775807]"


def test_a_huge_integer_query_parameter_is_refused_naming_it(canonical):
    _, db, _ = canonical
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.query(db, "SELECT ?", 1, 10**30)
    assert str(raised.value) == (
        f"parameters[1]: {10**30} is outside {INT64}, the integers SQLite stores; bind it as a "
        "float or a str"
    )
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.query(db, "SELECT ?", -(10**400))
    assert str(raised.value).startswith("parameters[0]: an integer of 1329 bits is outside ")


@pytest.mark.parametrize(
    "call, named",
    [
        (
            lambda db, path: shockmap.Study.load(path).run(db=db, jobs=10**30),
            "jobs: {} is outside [1, 1024]",
        ),
        (
            lambda db, path: shockmap.reference(db, 10**30),
            "reference_id: {} is outside [1, 9223372036854775807]",
        ),
        (
            lambda db, path: shockmap.point(db, "small_grid", 10**30),
            "point_id: {} is outside [1, 9223372036854775807]",
        ),
    ],
)
def test_a_huge_integer_keyword_is_refused_naming_its_range(canonical, call, named):
    path, db, _ = canonical
    with pytest.raises(shockmap.InputError) as raised:
        call(db, path)
    assert str(raised.value) == named.format(10**30)


def test_a_nul_byte_in_a_path_name_or_sql_is_refused_whole(canonical, tmp_path):
    _, db, _ = canonical
    cut = str(tmp_path / "study\0.json")
    calls = [
        (lambda: shockmap.Study.load(cut), "path", cut),
        (lambda: shockmap.query(f"{db}\0", "SELECT 1"), "db", f"{db}\0"),
        (lambda: shockmap.query(db, "SELECT 1\0; SELECT 2"), "sql", "SELECT 1\0; SELECT 2"),
        (lambda: shockmap.results(db, "small\0grid"), "study", "small\0grid"),
        (lambda: shockmap.criteria(db, "small\0grid"), "study", "small\0grid"),
    ]
    for call, name, value in calls:
        with pytest.raises(shockmap.InputError) as raised:
            call()
        shown = value[:40].encode("unicode_escape").decode() + ("..." if len(value) > 40 else "")
        assert str(raised.value) == NUL_REFUSAL.format(name, shown, value.index("\0"))


def test_corrupt_stored_study_json_is_a_database_error(canonical, tmp_path):
    _, db, _ = canonical
    copy = tmp_path / "corrupt.db"
    with sqlite3.connect(db) as source, sqlite3.connect(copy) as target:
        source.backup(target)
    with sqlite3.connect(copy) as connection:
        connection.execute("UPDATE studies SET spec_json = '{\"kind\": \"canonical\", '")
    for call in (
        lambda: shockmap.results(copy, "small_grid"),
        lambda: shockmap.criteria(copy, "small_grid"),
        lambda: shockmap.point(copy, "small_grid", 1),
    ):
        with pytest.raises(shockmap.DatabaseError) as raised:
            call()
        assert str(raised.value).startswith(
            f"{copy}: database corrupt: study small_grid: spec_json: parse error at line 1"
        ), str(raised.value)
