"""shockmap.compare and shockmap.point against what the command line stores and prints."""

import gc
import json
import sqlite3

import numpy as np
import pytest

import shockmap
from support import NUL_REFUSAL, read_only, write_json

WINDOW_S = 0.03
DT_FACTOR = 0.1
# Three points of the paper's problem with a small R_k (each runs in milliseconds): below,
# near and above the boundary R_ftrunc ~ sqrt(R_k) (README, "Criteria").
POINTS = [(100.0, 30.0), (1000.0, 100.0), (3000.0, 300.0)]


@pytest.fixture(scope="module")
def stored_study(tmp_path_factory, cli):
    """A three-point canonical study run by the command line; its database and name."""
    folder = tmp_path_factory.mktemp("compare")
    study = write_json(
        folder / "three_points.json",
        {
            "kind": "canonical",
            "name": "three_points",
            "scoring": {"window_s": WINDOW_S},
            "points": [
                {"rk": rk, "rftrunc": rf, "dt": {"rule": "sharp", "factor": DT_FACTOR}}
                for rk, rf in POINTS
            ],
        },
    )
    db = folder / "three_points.db"
    cli("study", "run", study, "--db", db, "--quiet")
    return db, "three_points"


def stored_rows(db):
    """The stored points with their scores, by R_k, as dicts."""
    with read_only(db) as connection:
        connection.row_factory = sqlite3.Row
        rows = connection.execute(
            "SELECT point_id, r_k, r_ftrunc, window_s, dt_factor, status, err, srf, pfr, steps, "
            "dt_used_s, n_modes, n_elements, dt_paper_s, dt_sharp_s, reference_id "
            "FROM points JOIN scores USING (point_id) ORDER BY r_k"
        ).fetchall()
    return [dict(row) for row in rows]


def bits(value):
    """The IEEE 754 bits of a double, so that a mismatch prints both values in full."""
    return None if value is None else np.float64(value).tobytes().hex()


def test_compare_equals_the_stored_result_bit_for_bit(stored_study):
    db, _ = stored_study
    rows = stored_rows(db)
    assert [(row["r_k"], row["r_ftrunc"]) for row in rows] == POINTS
    for row in rows:
        assert row["status"] == "ok"
        c = shockmap.compare(
            row["r_k"],
            row["r_ftrunc"],
            dt_factor=row["dt_factor"],
            dt_rule="sharp",
            window_s=row["window_s"],
        )
        assert c.status == "ok", c.message
        for score in ("err", "srf", "pfr"):
            assert bits(getattr(c, score)) == bits(row[score]), (score, row)
            assert bits(c.scores[score]) == bits(row[score]), (score, row)
        assert (c.steps, c.n_modes) == (row["steps"], row["n_modes"])
        assert c.n_elements == row["n_elements"]
        for bound in ("dt_used_s", "dt_paper_s", "dt_sharp_s"):
            assert bits(getattr(c, bound)) == bits(row[bound]), (bound, row)


def test_point_computed_again_equals_the_stored_scores(stored_study):
    db, study = stored_study
    for row in stored_rows(db):
        c = shockmap.point(db, study, row["point_id"])
        for score in ("err", "srf", "pfr"):
            assert bits(getattr(c, score)) == bits(row[score]), (score, row)
        assert c.steps == row["steps"]


def test_reference_by_id_is_the_stored_blob(stored_study):
    db, _ = stored_study
    reference_id = stored_rows(db)[-1]["reference_id"]
    with read_only(db) as connection:
        dt, tip, force = connection.execute(
            "SELECT output_dt_s, tip_m, force_n FROM reference_runs WHERE reference_id = ?",
            (reference_id,),
        ).fetchone()
    signals = shockmap.reference(db, reference_id)
    tip = np.frombuffer(tip, dtype="<f8")
    force = np.frombuffer(force, dtype="<f8")
    assert tip.size > 1000
    np.testing.assert_array_equal(signals["tip_displacement_m"], tip)
    np.testing.assert_array_equal(signals["contact_force_n"], force)
    np.testing.assert_allclose(signals["t_s"], np.arange(tip.size) * dt, rtol=0, atol=1e-15)
    assert signals["t_s"][-1] == pytest.approx(WINDOW_S, abs=1e-12)


def test_defaults_are_the_command_lines(cli):
    printed = json.loads(cli("compare", "--rk", 3000, "--rftrunc", 300, "--json").stdout)
    c = shockmap.compare(rk=3000, rftrunc=300)
    assert c.err == printed["err"] and c.srf == printed["srf"] and c.pfr == printed["pfr"]
    assert c.steps == printed["steps"] and c.dt_used_s == printed["dt_s"]
    assert c.reference_r_fref == printed["r_fref"]
    assert c.reference_difference == printed["ref_convergence"]
    first = c.shocks_numerical[0]
    assert first["impulse_n_s"] == printed["first_shock_num"]["impulse_n_s"]
    assert first["rebounds"] == printed["first_shock_num"]["rebounds"]
    assert c.shocks_reference[0]["peak_force_n"] == printed["first_shock_ref"]["peak_force_n"]


def test_summary_and_shocks_have_the_members_compare_json_prints(cli):
    printed = json.loads(cli("compare", "--rk", 3000, "--rftrunc", 300, "--json").stdout)
    c = shockmap.compare(rk=3000, rftrunc=300)
    assert c.summary.keys() == printed.keys()
    timings = {"wall_ref_s", "wall_num_s", "cpu_num_s"}
    assert {k: v for k, v in c.summary.items() if k not in timings} == {
        k: v for k, v in printed.items() if k not in timings}
    # A shock as a dict has every member of the JSON's shocks, its duration included.
    assert c.shocks_numerical[0] == printed["first_shock_num"]
    assert c.shocks_reference[0] == printed["first_shock_ref"]


def test_histories_are_arrays_on_the_run_s_time_grid():
    c = shockmap.compare(rk=3000, rftrunc=300, window_s=WINDOW_S)
    t = c.numerical["t_s"]
    assert isinstance(t, np.ndarray) and t.dtype == np.float64
    assert t.size == c.steps + 1
    assert t[-1] == pytest.approx(WINDOW_S, rel=1e-12)
    np.testing.assert_allclose(np.diff(t), c.dt_used_s, rtol=1e-9)
    for name in ("tip_displacement_m", "contact_force_n"):
        assert c.numerical[name].shape == t.shape
        assert c.reference[name].shape == c.reference["t_s"].shape
    # Released from +1 mm at rest; the spring pushes only (unilateral, gap 0).
    assert c.numerical["tip_displacement_m"][0] == pytest.approx(1e-3, rel=1e-12)
    assert c.numerical["contact_force_n"].min() >= 0.0
    # The first shock's peak is the largest force inside it.
    first = c.shocks_numerical[0]
    inside = (t >= first["start_s"]) & (t <= first["end_s"])
    assert c.numerical["contact_force_n"][inside].max() == pytest.approx(first["peak_force_n"])


def test_arrays_survive_their_result_being_deleted():
    c = shockmap.compare(rk=3000, rftrunc=300, window_s=WINDOW_S)
    tip = c.numerical["tip_displacement_m"]
    force = c.reference["contact_force_n"]
    tip_copy, force_copy = tip.copy(), force.copy()
    del c
    gc.collect()
    # Reuse the freed memory: a dangling view would now read these runs' values.
    others = [shockmap.compare(rk=100, rftrunc=30, window_s=WINDOW_S) for _ in range(3)]
    clutter = [np.full(tip.size, -7.0) for _ in range(8)]
    np.testing.assert_array_equal(tip, tip_copy)
    np.testing.assert_array_equal(force, force_copy)
    assert others and clutter


def test_diverged_run_is_a_status_not_an_error():
    c = shockmap.compare(rk=3000, rftrunc=10, dt_rule="paper", dt_factor=1.0)
    assert c.status == "diverged"
    assert c.err is None and c.srf is None


@pytest.mark.parametrize(
    "arguments, named",
    [
        ({"rk": -1.0, "rftrunc": 300}, r"r_?k"),
        ({"rk": 3000, "rftrunc": 0.5}, r"r_?ftrunc"),
        ({"rk": 3000, "rftrunc": 300, "window_s": float("nan")}, r"window"),
        ({"rk": 3000, "rftrunc": 300, "scheme": "runge-kutta"}, r"scheme"),
        ({"rk": 3000, "rftrunc": 300, "dt_rule": "fast"}, r"dt_rule"),
    ],
)
def test_bad_value_raises_input_error_naming_it(arguments, named):
    with pytest.raises(shockmap.InputError, match=named):
        shockmap.compare(**arguments)
    assert issubclass(shockmap.InputError, ValueError)


@pytest.mark.parametrize("keyword", ["dt_rule", "scheme"])
def test_a_nul_byte_in_a_text_argument_is_refused_whole(keyword):
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.compare(1000, 100, **{keyword: "sharp\0paper"})
    assert str(raised.value) == NUL_REFUSAL.format(keyword, "sharp\\x00paper", 5)


def test_a_huge_element_count_is_refused_naming_its_range():
    with pytest.raises(shockmap.InputError) as raised:
        shockmap.compare(1000, 100, elements=10**30)
    assert str(raised.value) == (
        "elements: value 1e+30 is out of range: must be a whole number from 0 to 1500")
    with pytest.raises(shockmap.InputError, match=r"^elements: value inf is out of range"):
        shockmap.compare(1000, 100, elements=10**400)  # beyond a float
