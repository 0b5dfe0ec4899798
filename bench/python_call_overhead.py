#!/usr/bin/python3
"""What the Python module adds to a call: shockmap.compare(rk=3000, rftrunc=300) against the C++
call it wraps (solver_bench's CompareCall, RunComparison with the same defaults), measured side
by side in alternating rounds of one run.

    PYTHONPATH=build/python bench/python_call_overhead.py build/bench/solver_bench [ROUNDS]

Prints each round's medians and the ratio of the medians over all rounds (Python / C++).
"""

import json
import statistics
import subprocess
import sys
import time

import shockmap

CALLS_PER_ROUND = 15


def python_round():
    times = []
    for _ in range(CALLS_PER_ROUND):
        start = time.perf_counter()
        result = shockmap.compare(rk=3000, rftrunc=300)
        times.append(time.perf_counter() - start)
        assert result.status == "ok"
    return statistics.median(times)


def cpp_round(solver_bench):
    done = subprocess.run(
        [solver_bench, "--benchmark_filter=^CompareCall$", "--benchmark_format=json",
         f"--benchmark_repetitions={CALLS_PER_ROUND}", "--benchmark_min_time=0"],
        capture_output=True, text=True, check=True)
    runs = [b for b in json.loads(done.stdout)["benchmarks"] if b.get("run_type") == "iteration"]
    # real_time is in the benchmark's unit, milliseconds.
    return statistics.median(b["real_time"] for b in runs) / 1e3


def main():
    solver_bench = sys.argv[1]
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    shockmap.compare(rk=3000, rftrunc=300)  # The first call builds the cached modal basis.
    python_s, cpp_s = [], []
    for r in range(rounds):
        cpp_s.append(cpp_round(solver_bench))
        python_s.append(python_round())
        print(f"round {r + 1}: C++ {1e3 * cpp_s[-1]:.2f} ms, Python {1e3 * python_s[-1]:.2f} ms")
    ratio = statistics.median(python_s) / statistics.median(cpp_s)
    print(f"median over {rounds} rounds: C++ {1e3 * statistics.median(cpp_s):.2f} ms, "
          f"Python {1e3 * statistics.median(python_s):.2f} ms, Python / C++ = {ratio:.3f}")


if __name__ == "__main__":
    main()
