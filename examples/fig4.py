#!/usr/bin/env python3
"""The paper's Fig. 4 from Python: Err and SRf against R_ftrunc, one curve per R_k.

Runs a small grid of the paper's problem (R_k 10 to 1e5, R_ftrunc 10 to 1000, dt = 0.1 of the
sharp bound, scored over the first shock) as a study in a temporary database, reads it back
with shockmap.results and draws both scores with matplotlib.

    python3 examples/fig4.py [OUT.png]        # default fig4.png
"""

import json
import math
import pathlib
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import shockmap  # noqa: E402

STUDY = {
    "kind": "canonical",
    "name": "fig4_example",
    "description": "examples/fig4.py: Err and SRf against R_ftrunc for five R_k",
    "scoring": {"window_s": 0.03, "thresholds": {"err_max": 0.1, "srf_min": 0.8}},
    "grids": [
        {
            "rk": {"logspace": [1, 5, 5]},
            "rftrunc": {"logspace": [1, 3, 9]},
            "dt": {"rule": "sharp", "factor": [0.1]},
        }
    ],
}


def run_grid():
    """The grid's results view as a DataFrame."""
    with tempfile.TemporaryDirectory() as folder:
        study_file = pathlib.Path(folder) / "fig4_example.json"
        study_file.write_text(json.dumps(STUDY))
        db = pathlib.Path(folder) / "fig4_example.db"
        shockmap.Study.load(study_file).run(db=db)
        return shockmap.results(db, STUDY["name"])


def draw(results, out):
    thresholds = STUDY["scoring"]["thresholds"]
    figure, (err_axes, srf_axes) = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    for rk, points in results.groupby("r_k"):
        points = points.sort_values("r_ftrunc")
        scored = points[points["status"] == "ok"]  # Diverged or unconverged: no score.
        label = f"$R_k = 10^{{{math.log10(rk):.0f}}}$"
        (line,) = err_axes.plot(scored["r_ftrunc"], scored["err"], "o-", label=label)
        srf_axes.plot(scored["r_ftrunc"], scored["srf"], "o-", color=line.get_color(), label=label)
        if points["r_ftrunc"].min() <= math.sqrt(rk) <= points["r_ftrunc"].max():
            for axes in (err_axes, srf_axes):
                axes.axvline(math.sqrt(rk), color=line.get_color(), linestyle=":", linewidth=1)
    err_axes.axhline(thresholds["err_max"], color="black", linestyle="--", linewidth=1)
    srf_axes.axhline(thresholds["srf_min"], color="black", linestyle="--", linewidth=1)
    err_axes.set(xscale="log", yscale="log", ylabel="Err (eq. 8)", title="(a) spectral error")
    srf_axes.set(xscale="log", ylabel="SRf (eq. 9)", title="(b) first-shock impulse ratio")
    for axes in (err_axes, srf_axes):
        axes.set_xlabel(r"$R_{ftrunc} = f_{trunc} / f_1$")
        axes.grid(True, which="both", alpha=0.3)
    err_axes.legend(title="dotted: $R_{ftrunc} = \\sqrt{R_k}$", fontsize="small", loc="lower left")
    figure.suptitle("Explicit modal scheme, dt = 0.1 of the sharp bound, window 0.03 s")
    figure.savefig(out, dpi=120)


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "fig4.png")
    out.parent.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    results = run_grid()
    draw(results, out)
    counts = results["status"].value_counts().to_dict()
    print(f"{len(results)} points {counts} in {time.perf_counter() - start:.1f} s: {out}")


if __name__ == "__main__":
    main()
