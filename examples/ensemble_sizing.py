#!/usr/bin/env python3
"""The sizing histogram of an ensemble from Python.

Runs a cut-down copy of studies/bundle_hex_ensemble.json (the 7-pin hexagonal bundle, 60
members in each of its two clearance states, enough for Wilks' first-order 95 %/95 % limit)
into a temporary database, takes the sizing statistics with shockmap.sizing, reads every
member's largest force in the hottest zone and in the hottest wire (between two pins) with
shockmap.query, and draws their histograms with the P95, its interval, Wilks' limit and the
nominal run.

    python3 examples/ensemble_sizing.py [OUT.png]        # default ensemble_sizing.png
"""

import json
import pathlib
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import shockmap  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parent.parent
MEMBERS = 60

MEMBER_FORCES = """
SELECT z.max_force_n FROM ensemble_member_zones z
JOIN ensemble_members m USING (point_id) JOIN studies s USING (study_id)
WHERE s.name = ? AND m.state = ? AND z.zone = ? AND m.status = 'ok'
"""
ZONE_NAMES = """
SELECT DISTINCT r.zones_json FROM ensemble_members m
JOIN ensemble_references r USING (reference_id) JOIN studies s USING (study_id)
WHERE s.name = ? AND m.state = ?
"""


def study_spec():
    spec = json.loads((REPOSITORY / "studies" / "bundle_hex_ensemble.json").read_text())
    spec["name"] = "bundle_hex_sizing_example"
    spec["description"] = "examples/ensemble_sizing.py: bundle_hex_ensemble with 60 members"
    spec["members"] = MEMBERS
    spec["scene"] = str(REPOSITORY / "scenes" / "bundle_hex_7.json")
    spec.pop("impact_statistics", None)  # The histograms need the largest forces only.
    return spec


def member_forces(db, study, state, zone_name):
    """Every ok member's largest force in the zone (N); zones are stored by index."""
    (zones_json,) = shockmap.query(db, ZONE_NAMES, study, state)["zones_json"]
    index = [zone["name"] for zone in json.loads(zones_json)].index(zone_name)
    return shockmap.query(db, MEMBER_FORCES, study, state, index)["max_force_n"]


def highest_p95(rows):
    return rows.loc[rows["p95_n"].idxmax()]


def bound(value):
    return f"{value:+.0f}" if value in (float("inf"), float("-inf")) else f"{value:.0f}"


def draw_panel(axes, forces, row, title):
    """The members' forces, the P95 with its interval (cut to the data where unbounded),
    Wilks' limit where the member count allows one, and the nominal run."""
    lower, upper = row["p95_lower_n"], row["p95_upper_n"]
    axes.hist(forces, bins=15, color="tab:blue", alpha=0.75)
    axes.axvline(row["p95_n"], color="tab:red", linewidth=2, label=f"P95 = {row['p95_n']:.0f} N")
    axes.axvspan(max(lower, forces.min()), min(upper, forces.max()), color="tab:red", alpha=0.12,
                 label=f"its 95 % interval [{bound(lower)}, {bound(upper)}]")
    if row["wilks_order"] > 0:
        axes.axvline(row["wilks_limit_n"], color="black", linestyle="--",
                     label=f"Wilks 95/95, order {row['wilks_order']}: {row['wilks_limit_n']:.0f} N")
    axes.axvline(row["nominal_n"], color="tab:green", linestyle=":",
                 label=f"nominal run: {row['nominal_n']:.0f} N")
    axes.set(title=title, xlabel="largest contact force of a member (N)", ylabel="members")
    axes.legend(fontsize="small")


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "ensemble_sizing.png")
    out.parent.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    spec = study_spec()
    with tempfile.TemporaryDirectory() as folder:
        study_file = pathlib.Path(folder) / "ensemble.json"
        study_file.write_text(json.dumps(spec))
        db = pathlib.Path(folder) / "ensemble.db"
        shockmap.Study.load(study_file).run(db=db, progress=True)
        sizing = shockmap.sizing(db, spec["name"])
        states = list(dict.fromkeys(sizing["state"]))
        figure, axes = plt.subplots(len(states), 2, figsize=(12, 4.2 * len(states)),
                                    constrained_layout=True, squeeze=False)
        for row_axes, state in zip(axes, states):
            rows = sizing[sizing["state"] == state]
            wires = rows[rows["zone"].str.contains("-pin_", regex=False)]  # Between two pins.
            hottest = rows[rows["hottest"] == 1].iloc[0]  # sizing's own choice
            for panel, (row, what) in zip(row_axes, [(hottest, "hottest zone"),
                                                     (highest_p95(wires), "hottest wire")]):
                forces = member_forces(db, spec["name"], state, row["zone"])
                title = f"{state}: {what} {row['zone']}, {len(forces)} members"
                draw_panel(panel, forces, row, title)
                print(f"{state:12s} {what:13s} {row['zone']:22s} P95 {row['p95_n']:.1f} N "
                      f"[{row['p95_lower_n']:.1f}, {row['p95_upper_n']:.1f}] "
                      f"from {len(forces)} members")
    figure.suptitle("7-pin hexagonal bundle, 10 g handling shock: members' largest forces")
    figure.savefig(out, dpi=110)
    print(f"{MEMBERS} members x {len(states)} states in {time.perf_counter() - start:.1f} s: {out}")


if __name__ == "__main__":
    main()
