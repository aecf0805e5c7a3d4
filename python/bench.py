#!/usr/bin/python3
"""Timing of the Python module against the command line, run by hand:

    PYTHONPATH=build/python /usr/bin/python3 python/bench.py [CASE] [--magnus build/magnus] [--repeat 20]

1. magnus.run(CASE), wall-clock seconds of the whole call (case parsing, solve, post-processing, the Result),
   against the compute time `magnus run CASE --json` reports (timing.total_s: the solve and post-processing,
   without writing its file), each a new process. magnus.run is timed warm (repeated in one process) and
   as the first call of a fresh interpreter. The best of --repeat runs of each; the ratio should be ≤ 1.2.
2. magnus.sweep(CASE, spin_ratio=1000 values from 0 to 4), wall-clock seconds (best of --repeat); ≤ 0.1 s.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
# This folder holds the package's sources without the compiled part: import the built (or installed) one.
sys.path = [d for d in sys.path if pathlib.Path(d or ".").resolve() != HERE]
import magnus  # noqa: E402


def best(f, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("case", nargs="?", default=str(HERE.parent / "cases" / "spin_ratio_1.toml"))
    p.add_argument("--magnus", default=os.environ.get("MAGNUS_EXE", str(HERE.parent / "build" / "magnus")))
    p.add_argument("--repeat", type=int, default=20)
    a = p.parse_args()

    magnus.run(a.case)  # warm up (libraries, FFTW plans)
    py_s = best(lambda: magnus.run(a.case), a.repeat)
    cli_s = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.h5")
        for _ in range(a.repeat):
            j = json.loads(subprocess.run([a.magnus, "run", a.case, "-o", out, "--json"], check=True,
                                          capture_output=True, text=True).stdout)
            cli_s.append(j["timing"]["total_s"]["value"])
    # Cold, as the command line always is: a fresh interpreter per call, timing the call alone.
    cold = ("import magnus, sys, time; t = time.perf_counter(); r = magnus.run(sys.argv[1]); "
            "print(time.perf_counter() - t, r.timing['total_s'])")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    runs = [subprocess.run([sys.executable, "-c", cold, a.case], check=True, capture_output=True, text=True,
                           env=env).stdout.split() for _ in range(a.repeat)]
    py_cold_s = min(float(wall) for wall, _ in runs)
    py_cold_total_s = min(float(total) for _, total in runs)
    r = magnus.run(a.case)
    print(f"case {a.case}: n_r × n_theta = {r.parameters['n_r']} × {r.parameters['n_theta']}, "
          f"{r.parameters['method']}, best of {a.repeat}")
    print(f"magnus.run (wall, whole call)      {py_s * 1e3:9.3f} ms")
    print(f"magnus run (its timing.total_s)    {min(cli_s) * 1e3:9.3f} ms")
    print(f"magnus.run, first call of a process{py_cold_s * 1e3:9.3f} ms   (its timing.total_s "
          f"{py_cold_total_s * 1e3:.3f} ms)")
    print(f"ratio, warm                        {py_s / min(cli_s):9.3f}   (target ≤ 1.2)")
    print(f"ratio, first call                  {py_cold_s / min(cli_s):9.3f}   (target ≤ 1.2)")

    alphas = np.linspace(0.0, 4.0, 1000)
    sweep_s = best(lambda: magnus.sweep(a.case, spin_ratio=alphas), a.repeat)
    print(f"magnus.sweep, 1000 spin ratios     {sweep_s * 1e3:9.3f} ms   (target ≤ 100 ms)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
