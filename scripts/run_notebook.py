#!/usr/bin/python3
"""Execute a lesson notebook end to end, as a test: `run_notebook.py NOTEBOOK [--save EXECUTED]`.

The stored notebook must carry no outputs (the repository keeps lessons clean). It is run in a scratch
directory with Debian's python3 kernel (nbclient, ipykernel); the magnus module, the command line and the
source tree come from PYTHONPATH, MAGNUS_EXE and MAGNUS_SOURCE_DIR. The executed copy is written only with
--save. Prints each cell's wall time; on a failure prints one line naming the cell and the error, exit 1.
"""
import argparse
import os
import sys
import tempfile
import time

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError


def stored_outputs(nb):
    """The indices of the code cells that carry outputs or an execution count."""
    return [i for i, c in enumerate(nb.cells)
            if c.cell_type == "code" and (c.get("outputs") or c.get("execution_count") is not None)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("notebook")
    ap.add_argument("--save", help="write the executed notebook here")
    ap.add_argument("--timeout", type=int, default=600, help="seconds per cell (default 600)")
    args = ap.parse_args()
    try:
        nb = nbformat.read(args.notebook, as_version=4)
    except (OSError, ValueError) as e:
        sys.exit(f"run_notebook: {args.notebook}: cannot read it as a notebook ({e})")
    dirty = stored_outputs(nb)
    if dirty:
        sys.exit(f"run_notebook: {args.notebook}: code cells {dirty} carry outputs; store the lesson without "
                 "them (jupyter nbconvert --clear-output --inplace)")
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel debugger's start-up notes
    start, times, started = time.monotonic(), [], []
    with tempfile.TemporaryDirectory(prefix="magnus-notebook-") as scratch:
        client = NotebookClient(nb, timeout=args.timeout, kernel_name="python3",
                                resources={"metadata": {"path": scratch}})
        client.on_cell_start = lambda cell, cell_index, **_: started.append(cell_index)
        client.on_cell_executed = lambda cell, cell_index, **_: times.append((cell_index, time.monotonic()))
        try:
            client.execute()
        except CellExecutionError as e:
            cell = started[-1] if started else "?"
            last = [line for line in str(e).strip().splitlines() if line.strip()][-1]
            sys.exit(f"run_notebook: {args.notebook}: cell {cell} failed: {last}")
    previous = start
    for index, t in times:
        print(f"cell {index:2d}  {t - previous:7.2f} s")
        previous = t
    print(f"all {len(nb.cells)} cells ran in {time.monotonic() - start:.1f} s")
    if args.save:
        nbformat.write(nb, args.save)


if __name__ == "__main__":
    main()
