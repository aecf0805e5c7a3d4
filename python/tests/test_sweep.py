"""magnus.sweep: the superposition sweep against single runs and the command line's sweep file."""
import math

import h5py
import numpy as np
import pytest

import magnus
from conftest import DEMO, cli


def test_a_sweep_matches_run_at_a_few_points():
    alphas = np.array([0.0, 0.5, 1.0, 3.0])
    s = magnus.sweep(DEMO, spin_ratio=alphas, grid__n_theta=128)
    assert np.array_equal(s["alpha"], alphas)
    for k, a in enumerate(alphas):
        r = magnus.run(DEMO, grid__n_theta=128, set={"cylinder.spin_ratio": float(a)})
        assert s["cl"][k] == pytest.approx(r.forces["cl"], rel=0, abs=1e-10), a
        assert s["cd"][k] == pytest.approx(r.forces["cd"], rel=0, abs=1e-10), a
        assert s["lift"][k] == pytest.approx(r.forces["lift"], rel=1e-10, abs=1e-9), a
        assert s["cl_kutta_joukowski"][k] == pytest.approx(-2 * math.pi * a, rel=0, abs=1e-12)
    assert s.units["cl"] == "1" and s.units["lift"] == "N/m" and s.units["stagnation_theta1"] == "rad"
    assert s.timing["linear_solves"] == 2


def test_undefined_values_are_masked_never_nan():
    # α ≥ 2: one free stagnation point, so the second surface angle is undefined there.
    s = magnus.sweep(DEMO, spin_ratio=[0.5, 1.0, 3.0], grid__n_theta=64)
    t2 = s["stagnation_theta2"]
    assert isinstance(t2, np.ma.MaskedArray)
    assert list(t2.mask) == [False, False, True]
    assert s["stagnation_r_over_a"][2] > 1.0
    for name, column in s.items():
        assert np.isfinite(np.ma.compressed(column)).all(), name


def test_columns_are_the_sweep_files(tmp_path):
    path = tmp_path / "s.h5"
    cli("sweep", DEMO, "--spin-ratio", "0:2:0.5", "-o", path, "-q", "--set", "grid.n_theta=64")
    s = magnus.sweep(DEMO, spin_ratio=np.arange(0.0, 2.01, 0.5), grid__n_theta=64)
    with h5py.File(path, "r") as f:
        g = f["sweep"]
        stored = set(g.keys()) | set(filter(None, str(g.attrs.get("undefined", "")).split(", ")))
        assert stored == set(s) | set(s.undefined)
        for name in g:
            fill = g[name].attrs.get("_FillValue")
            v = np.ma.masked_equal(g[name][...], fill) if fill is not None else g[name][...]
            assert np.ma.allclose(v, s[name], rtol=1e-12, atol=1e-12), name
            units = g[name].attrs["units"]
            assert (units.decode() if isinstance(units, bytes) else units) == s.units[name], name


def test_a_circulation_sweep():
    case = {"cylinder": {"radius": 0.1, "spin": 0.0}, "flow": {"speed": 10.0},
            "circulation": {"model": "given", "value": 0.0}, "grid": {"n_theta": 64}}
    gammas = np.array([0.0, 1.0, 2.0])
    s = magnus.sweep(case, circulation=gammas)
    assert np.array_equal(s["circulation"], gammas)
    assert s["cl_kutta_joukowski"] == pytest.approx(-gammas / (10.0 * 0.1), abs=1e-12)
