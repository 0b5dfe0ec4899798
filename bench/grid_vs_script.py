#!/usr/bin/python3
"""The Fig. 4 grid timed side by side (docs/performance.md, "The grid against a script"):
`shockmap study run` of each study file with each build, and the Numba script
bench/fig4_grid_numba.py, each a whole process under /usr/bin/time -v into a fresh database,
the runs interleaved, medians of RUNS.

    bench/grid_vs_script.py RUNS LABEL=BUILD/app/shockmap [...] -- STUDY.json [...]

A build that refuses a study file (an older one without its keys) is left out of that row.
Prints one row per (build, study) and one for the script: wall, user + system CPU, and, for the
script, the wall and CPU time its own code reports (without the interpreter's start, the imports
and loading Numba's compiled cache). The script's first run, untimed, fills its cache
(NUMBA_CACHE_DIR, a temporary folder unless set).
"""

import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "fig4_grid_numba.py")


def timed(command, env=None):
    """(wall s, user + system s, stdout) of one whole process, or None when it failed."""
    result = subprocess.run(["/usr/bin/time", "-v"] + command, capture_output=True, text=True,
                            env=env)
    if result.returncode != 0:
        return None
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (?:(\d+):)?(\d+):([\d.]+)",
                     result.stderr)
    user = float(re.search(r"User time \(seconds\): ([\d.]+)", result.stderr).group(1))
    system = float(re.search(r"System time \(seconds\): ([\d.]+)", result.stderr).group(1))
    seconds = float(wall.group(3)) + 60.0 * float(wall.group(2)) + 3600.0 * float(wall.group(1) or 0)
    return seconds, user + system, result.stdout


def main():
    runs = int(sys.argv[1])
    split = sys.argv.index("--")
    builds = [a.split("=", 1) for a in sys.argv[2:split]]
    studies = sys.argv[split + 1:]
    env = dict(os.environ)
    cache = tempfile.TemporaryDirectory()
    env.setdefault("NUMBA_CACHE_DIR", cache.name)
    rows = {}
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run(["/usr/bin/python3", SCRIPT], env=env, check=True, capture_output=True)
        for run in range(runs):
            for label, binary in builds:
                for study in studies:
                    db = os.path.join(folder, f"{label}_{run}_{os.path.basename(study)}.db")
                    t = timed([binary, "study", "run", study, "--db", db, "--jobs", "1"])
                    if t:
                        rows.setdefault((label, os.path.basename(study)), []).append(t[:2])
            db = os.path.join(folder, f"script_{run}.db")
            t = timed(["/usr/bin/python3", SCRIPT, db], env=env)
            own = re.search(r"grid: ([\d.]+) s wall, ([\d.]+) s CPU", t[2])
            rows.setdefault(("numba script", "its own code"), []).append(
                (float(own.group(1)), float(own.group(2))))
            rows.setdefault(("numba script", "whole process"), []).append(t[:2])
    print(f"| build | study | wall (median of {runs}) | CPU | runs (wall) |")
    print("|---|---|---|---|---|")
    for (label, study), times in rows.items():
        wall = statistics.median(t[0] for t in times)
        cpu = statistics.median(t[1] for t in times)
        print(f"| {label} | {study} | {wall:.3f} s | {cpu:.3f} s | "
              + ", ".join(f"{t[0]:.3f}" for t in times) + " |")


if __name__ == "__main__":
    main()
