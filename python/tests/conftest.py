"""Shared paths: the source tree (cases) and the magnus command line of the same build."""
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MAGNUS_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
MAGNUS_EXE = os.environ.get("MAGNUS_EXE", str(SOURCE_DIR / "build" / "magnus"))
DEMO = SOURCE_DIR / "cases" / "spin_ratio_1.toml"
NS_CASE = SOURCE_DIR / "cases" / "re100_alpha1.toml"
# A navier-stokes run small enough for the default suite: 32 × 21 nodes, one convective time unit.
NS_TINY = {"grid.n_theta": 32, "domain.outer_radius": 10, "time.end": 1}


def cli(*args, check=True):
    """Run the magnus command line; returns the CompletedProcess (text)."""
    p = subprocess.run([MAGNUS_EXE, *map(str, args)], capture_output=True, text=True)
    if check and p.returncode != 0:
        raise AssertionError(f"magnus {' '.join(map(str, args))} failed: {p.stderr}")
    return p


def cli_error(*args):
    """The command line's one-line error message, without its 'magnus: error: ' prefix."""
    p = cli(*args, check=False)
    assert p.returncode != 0
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1, p.stderr
    prefix = "magnus: error: "
    assert lines[0].startswith(prefix), lines[0]
    return lines[0][len(prefix):]


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Run in an empty directory (to see that nothing is written unasked)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
