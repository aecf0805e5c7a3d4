"""scripts/run_notebook.py, the notebook test's runner: it must fail on a failing cell and on stored outputs."""
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

nbformat = pytest.importorskip("nbformat")  # declared (python3-nbformat, python3-nbclient): setup.sh installs
RUNNER = SOURCE_DIR / "scripts" / "run_notebook.py"


def _run(path):
    return subprocess.run([sys.executable, str(RUNNER), str(path)], capture_output=True, text=True, timeout=300)


def _notebook(path, *sources, outputs=False):
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(s) for s in sources]
    if outputs:
        nb.cells[0].outputs = [nbformat.v4.new_output("stream", name="stdout", text="stale\n")]
        nb.cells[0].execution_count = 1
    nbformat.write(nb, str(path))
    return path


def test_a_failing_cell_fails_the_run_in_one_line(tmp_path):
    p = _run(_notebook(tmp_path / "bad.ipynb", "x = 1", "assert x == 2, 'the claim does not hold'"))
    assert p.returncode == 1
    assert p.stderr.strip().splitlines()[-1].startswith(f"run_notebook: {tmp_path / 'bad.ipynb'}: cell 1 failed")
    assert "the claim does not hold" in p.stderr


def test_stored_outputs_are_refused(tmp_path):
    p = _run(_notebook(tmp_path / "dirty.ipynb", "print('stale')", outputs=True))
    assert p.returncode == 1 and "code cells [0] carry outputs" in p.stderr


def test_a_clean_notebook_runs(tmp_path):
    p = _run(_notebook(tmp_path / "ok.ipynb", "import math", "assert math.pi > 3"))
    assert p.returncode == 0, p.stderr
    assert "all 2 cells ran" in p.stdout
