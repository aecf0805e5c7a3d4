"""Solves run without the GIL: Python threads go on while a solve runs."""
import threading
import time

import magnus
from conftest import DEMO


def test_the_main_thread_runs_during_a_solve():
    done = threading.Event()
    took = []

    def solve():
        t0 = time.perf_counter()
        magnus.run(DEMO, grid__n_theta=2048)
        took.append(time.perf_counter() - t0)
        done.set()

    worker = threading.Thread(target=solve)
    stamps = [time.perf_counter()]
    worker.start()
    while not done.is_set():
        stamps.append(time.perf_counter())
    worker.join()
    gaps = [b - a for a, b in zip(stamps, stamps[1:])]
    # Holding the GIL through the solve would stop this loop for the whole solve: one gap ≈ the solve.
    assert len(stamps) > 100
    assert max(gaps) < 0.5 * took[0], (max(gaps), took[0])
