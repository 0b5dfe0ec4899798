#!/usr/bin/python3
"""Two methods that agree: the explicit modal scheme at finer truncations and time steps set
against the semi-analytical reference of the same problem (docs/fidelity.md, "Two methods").

    bench/two_methods.py build/app/shockmap RK RFTRUNC,RFTRUNC,... DT_FACTOR,DT_FACTOR,...

For each truncation and each dt / dt_sharp it runs `shockmap compare --window 0.03 --out` and
prints the largest tip difference over the window as a fraction of the reference's amplitude
(the reference interpolated at the numerical run's times by 4-point Lagrange: interpolating
every other reference sample from the rest, its error is about 5e-10 of the amplitude at
R_k = 1e2 and 2e-8 at 1e6, below every difference printed), the first-shock impulse's relative
difference, Err, the modes kept and the numerical run's CPU time; then the order observed in
R_ftrunc between successive truncations at the finest time step.
"""

import json
import math
import subprocess
import sys
import tempfile

import numpy as np

WINDOW_S = 0.03


def lagrange4(t, u, at):
    """u(t) sampled on an increasing grid, interpolated at the times `at` through 4 samples."""
    i = np.clip(np.searchsorted(t, at) - 2, 0, len(t) - 4)
    value = np.zeros_like(at)
    for j in range(4):
        weight = np.ones_like(at)
        for m in range(4):
            if m != j:
                weight *= (at - t[i + m]) / (t[i + j] - t[i + m])
        value += weight * u[i + j]
    return value


def run(binary, rk, rftrunc, dt_factor, folder):
    out = f"{folder}/{rftrunc:g}_{dt_factor:g}"
    command = [binary, "compare", "--rk", str(rk), "--rftrunc", str(rftrunc), "--dt-factor",
               str(dt_factor), "--window", str(WINDOW_S), "--out", out, "--json"]
    result = json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout)
    numerical = np.loadtxt(f"{out}/numerical.csv", delimiter=",", skiprows=1, usecols=(0, 1))
    reference = np.loadtxt(f"{out}/reference.csv", delimiter=",", skiprows=1, usecols=(0, 1))
    at = lagrange4(reference[:, 0], reference[:, 1], numerical[:, 0])
    tip = np.max(np.abs(numerical[:, 1] - at)) / np.max(np.abs(reference[:, 1]))
    i_num = result["first_shock_num"]["impulse_n_s"]
    i_ref = result["first_shock_ref"]["impulse_n_s"]
    return tip, abs(i_num - i_ref) / i_ref, result


def main():
    binary, rk = sys.argv[1], float(sys.argv[2])
    truncations = [float(x) for x in sys.argv[3].split(",")]
    dt_factors = [float(x) for x in sys.argv[4].split(",")]
    finest = []
    with tempfile.TemporaryDirectory() as folder:
        for rftrunc in truncations:
            cells = []
            for dt_factor in dt_factors:
                tip, impulse, r = run(binary, rk, rftrunc, dt_factor, folder)
                cells.append(f"{tip:.2e} / {impulse:.1e} (Err {r['err']:.1e}, "
                             f"{r['cpu_num_s']:.2f} s)")
            finest.append((rftrunc, tip, impulse))
            print(f"R_k {rk:g}  R_ftrunc {rftrunc:g} ({r['n_modes']} modes; reference "
                  f"{r['r_fref']:g} f1, estimate {r['ref_convergence']:.1e}): " +
                  " | ".join(cells), flush=True)
    for (r0, tip0, i0), (r1, tip1, i1) in zip(finest, finest[1:]):
        ratio = math.log(r1 / r0)
        print(f"order in R_ftrunc from {r0:g} to {r1:g}: tip {math.log(tip0 / tip1) / ratio:.2f}, "
              f"impulse {math.log(i0 / i1) / ratio:.2f}")


if __name__ == "__main__":
    main()
