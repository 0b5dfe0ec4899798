"""The workflows Python calls as the command line runs them: check_advice() and report()."""

import json
import re

import pytest
import shockmap

from support import write_json


@pytest.fixture(scope="module")
def row_study(tmp_path_factory, source_dir):
    """The row bundle's ensemble cut to its `new` state, 3 members of 5 ms: the study file."""
    spec = json.loads((source_dir / "studies" / "bundle_row_ensemble.json").read_text())
    spec.update(name="row", members=3, window_s=0.005,
                scene=str(source_dir / "scenes" / "bundle_row.json"))
    return write_json(tmp_path_factory.mktemp("row") / "row.json", spec)


LADDER = dict(states=["new"], quantile=0.5, max_rungs=3, jobs=2)


@pytest.fixture(scope="module")
def checked(row_study, source_dir, tmp_path_factory):
    """check_advice() on the row's ensemble: (database, its result)."""
    db = tmp_path_factory.mktemp("checked") / "check.db"
    criteria = source_dir / shockmap.SCENE_CRITERIA
    return db, shockmap.check_advice(row_study, db, criteria=criteria, **LADDER)


def test_check_advice_gives_the_command_line_s_verdict_and_table(checked, row_study, source_dir,
                                                                  cli):
    db, result = checked
    assert result["factors"] == pytest.approx([1 / 3, 1, 3])
    assert len(result["cpu_s_per_member"]) == 3
    # The command line on the same database computes nothing and prints the same check.
    printed = cli("check-advice", row_study, "--db", db, "--criteria",
                  source_dir / shockmap.SCENE_CRITERIA, "--states", "new", "--quantile", "0.5",
                  "--max-rungs", "3", "--jobs", "2", "--quiet").stdout
    assert "9 members in the ladder, 0 computed now" in printed
    assert result["verdict"] in printed
    table = result["table"]
    assert list(table["state"]) == ["new"] * 3
    for family, zone in zip(table["family"], table["hottest zone"]):
        assert re.search(rf"^new +{re.escape(family)} +{re.escape(zone)} ", printed, re.M)
    members = shockmap.query(db, "SELECT count(*) AS n FROM ensemble_members")
    assert members["n"][0] == 9


def test_check_advice_writes_the_ladder_s_study_instead_when_asked(row_study, source_dir,
                                                                    tmp_path):
    written = tmp_path / "ladder.json"
    result = shockmap.check_advice(row_study, tmp_path / "none.db", write_study=written,
                                   criteria=source_dir / shockmap.SCENE_CRITERIA, **LADDER)
    assert "verdict" not in result
    assert json.loads(written.read_text())["name"] == "row_advice_check"
    assert not (tmp_path / "none.db").exists()
    assert result["dt_ratio"] > 0 and set(result["r_ftrunc"]) >= {"wrapper"}


@pytest.mark.parametrize(
    "keyword, value, message",
    [
        ("quantile", 1.0, "quantile: 1 is outside (0, 1)"),
        ("max_rungs", 13, "max_rungs: 13 is outside [3, 12]"),
        ("members", 0, "members: 0 is outside [1, 100000]"),
        ("window_s", 0.0, "window_s: 0 is outside (0, 10000]"),
        ("states", ["eol"], 'states: "eol" is not a clearance state of'),
    ],
)
def test_check_advice_refuses_what_the_command_line_refuses_before_anything_runs(
        row_study, source_dir, tmp_path, keyword, value, message):
    options = dict(LADDER, criteria=source_dir / shockmap.SCENE_CRITERIA)
    options[keyword] = value
    with pytest.raises(shockmap.InputError, match=re.escape(message)):
        shockmap.check_advice(row_study, tmp_path / "c.db", **options)
    assert not (tmp_path / "c.db").exists()


def section_ids(html):
    return re.findall(r'<section id="([^"]+)"', html)


def sections(html):
    """Each section of a report by id, but its provenance (who wrote it, when)."""
    found = dict(re.findall(r'<section id="([^"]+)">(.*?)</section>', html, re.S))
    found.pop("provenance", None)
    return found


def test_report_writes_the_command_line_s_report(checked, tmp_path, cli):
    db, result = checked
    page = shockmap.report(db, "row_advice_check", out=tmp_path / "module")
    assert page == str(tmp_path / "module" / "index.html")
    cli("report", "row_advice_check", "--db", db, "--out", tmp_path / "cli")
    from_module = (tmp_path / "module" / "index.html").read_text()
    from_cli = (tmp_path / "cli" / "index.html").read_text()
    assert section_ids(from_module) == section_ids(from_cli) != []
    assert result["verdict"].split(".")[0] in from_module
    assert sorted(p.name for p in (tmp_path / "module").iterdir()) == sorted(
        p.name for p in (tmp_path / "cli").iterdir())


def test_report_takes_thresholds_as_criteria_does(tmp_path, cli):
    spec = {"kind": "canonical", "name": "tiny", "scoring": {"window_s": 0.03},
            "grids": [{"rk": [100, 1000], "rftrunc": [10, 100],
                       "dt": {"rule": "sharp", "factor": [0.1]}}]}
    db = tmp_path / "tiny.db"
    shockmap.Study.load(write_json(tmp_path / "tiny.json", spec)).run(db=db, jobs=2)
    shockmap.report(db, out=tmp_path / "module", err_max=0.5)
    cli("report", "--db", db, "--out", tmp_path / "cli", "--err-max", "0.5")
    from_module = sections((tmp_path / "module" / "index.html").read_text())
    assert from_module == sections((tmp_path / "cli" / "index.html").read_text())
    # The threshold counts: the study's own give another verdict and criteria.
    shockmap.report(db, out=tmp_path / "own")
    own = sections((tmp_path / "own" / "index.html").read_text())
    assert own["verdict"] != from_module["verdict"] and own["criteria"] != from_module["criteria"]
    with pytest.raises(shockmap.InputError, match="errmax: not a threshold"):
        shockmap.report(db, out=tmp_path / "bad", errmax=0.5)
    assert not (tmp_path / "bad").exists()


def test_a_threshold_out_of_its_range_is_refused_before_the_report_draws(checked, tmp_path):
    db, _ = checked
    with pytest.raises(shockmap.InputError, match=re.escape("err_max = -1: must be in")):
        shockmap.report(db, "row_advice_check", out=tmp_path / "out", err_max=-1)
    assert not (tmp_path / "out").exists()


def test_report_of_a_study_the_database_lacks_is_refused_creating_nothing(checked, tmp_path):
    db, _ = checked
    with pytest.raises(shockmap.InputError, match="no_such_study"):
        shockmap.report(db, "no_such_study", out=tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_a_progress_callable_sees_each_rung_s_run_and_each_figure(row_study, source_dir,
                                                                   tmp_path):
    seen = []
    shockmap.check_advice(row_study, tmp_path / "fresh.db",
                          criteria=source_dir / shockmap.SCENE_CRITERIA,
                          progress=lambda *report: seen.append(report), **LADDER)
    assert ("points", 9.0, 9.0) in seen and {phase for phase, _, _ in seen} == {
        "references", "points"}
    spec = {"kind": "canonical", "name": "tiny", "scoring": {"window_s": 0.03},
            "grids": [{"rk": [100], "rftrunc": [10, 100], "dt": {"rule": "sharp", "factor": [0.1]}}]}
    tiny = tmp_path / "tiny.db"
    shockmap.Study.load(write_json(tmp_path / "tiny.json", spec)).run(db=tiny, jobs=2)
    figures = []
    shockmap.report(tiny, out=tmp_path / "report", progress=lambda *r: figures.append(r))
    assert [done for _, done, _ in figures] == [1.0, 2.0]
    assert all(phase.startswith("Fig. 3 of point ") and total == 2.0 for phase, _, total in figures)

    def fails(*_):
        raise RuntimeError("from the callable")

    with pytest.raises(RuntimeError, match="from the callable"):
        shockmap.report(tiny, out=tmp_path / "again", progress=fails)
