"""magnus.read: results written by the module or the command line, potential and navier-stokes."""
import h5py
import numpy as np
import pytest

import magnus
from conftest import DEMO, NS_CASE, NS_TINY, cli


def test_fields_agree_with_read_of_the_written_file(tmp_path):
    r = magnus.run(DEMO, grid__n_theta=128)
    path = tmp_path / "r.h5"
    r.write(path)
    back = magnus.read(path)
    assert set(back.fields) == set(r.fields)
    for name in r.fields:
        assert np.array_equal(back.fields[name], r.fields[name]), name
    for name in r.surface:
        assert np.array_equal(back.surface[name], r.surface[name]), name
    assert np.array_equal(back.grid["r"], r.grid["r"]) and np.array_equal(back.grid["theta"], r.grid["theta"])
    assert back.forces == r.forces
    assert back.parameters == r.parameters
    assert back.units == r.units
    # And the same values as the file holds, as h5py reads them.
    with h5py.File(path, "r") as f:
        assert np.array_equal(f["fields/cp"][...], r.fields["cp"])
        assert f["forces"].attrs["cl"] == r.forces["cl"]
        units = f["forces"].attrs["cl_units"]
        assert (units.decode() if isinstance(units, bytes) else units) == r.units["forces"]["cl"]


def test_read_of_a_command_line_navier_stokes_result(tmp_path):
    path = tmp_path / "ns.h5"
    cli("run", NS_CASE, "-o", path, "-q", *[a for k, v in NS_TINY.items() for a in ("--set", f"{k}={v}")])
    r = magnus.read(path)
    assert r.model == "navier-stokes"
    h = r.history
    assert set(h) >= {"t", "t_convective", "cl", "cd", "cm"}
    n = h["t"].size
    assert n > 10 and all(v.shape == (n,) for v in h.values())
    assert h["t_convective"][-1] == pytest.approx(1.0, abs=0.05)  # time.end = 1 D/U
    assert "vorticity" in r.fields and "psi_exact" not in r.fields
    assert r.fields["vorticity"].shape == (r.parameters["n_r"], 32)
    assert "shear_stress" in r.surface
    assert r.units["history"]["t"] == "s"
    with h5py.File(path, "r") as f:
        assert np.array_equal(f["history/cl"][...], h["cl"])
        assert f["forces"].attrs["cl_mean"] == r.forces["cl_mean"]
    assert r.snapshots["t"].size == 0 and r.snapshots["psi"].shape == (0, r.parameters["n_r"], 32)
    # Solved through the module: the same run, step for step.
    m = magnus.run(NS_CASE, set=NS_TINY)
    assert np.array_equal(m.history["cl"], h["cl"])
    assert m.forces["cl_mean"] == r.forces["cl_mean"]


def test_ctrl_c_stops_a_navier_stokes_run():
    import _thread
    import threading
    import time

    # Some 4600 steps (about a second alone on a core): Ctrl-C after 0.2 s stops it between two steps.
    case = {"grid.n_theta": 64, "domain.outer_radius": 20, "time.end": 300, "time.mode": "unsteady"}
    timer = threading.Timer(0.2, _thread.interrupt_main)
    t0 = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            magnus.run(NS_CASE, set=case)
    finally:
        timer.cancel()
    assert time.perf_counter() - t0 < 5.0


def test_snapshots_of_a_navier_stokes_run(tmp_path):
    r = magnus.run(NS_CASE, set=dict(NS_TINY, **{"output.snapshots": 3}), output=tmp_path / "s.h5")
    s = r.snapshots
    n_r = r.parameters["n_r"]
    assert s["t"].shape == (3,) and s["psi"].shape == (3, n_r, 32) and s["vorticity"].shape == (3, n_r, 32)
    assert np.all(np.diff(s["t"]) > 0) and 0 < s["t"][0] and s["t"][-1] <= r.history["t"][-1]
    assert np.isin(s["t"], r.history["t"]).all()  # each stored state is one of the steps
    with h5py.File(tmp_path / "s.h5", "r") as f:
        assert np.array_equal(f["snapshots/psi"][...], s["psi"])
    assert r.units["snapshots"]["vorticity"] == "1/s"
    assert magnus.run(DEMO, grid__n_theta=16).snapshots is None


def test_a_navier_stokes_run_states_its_error(tmp_path):
    # The companion run on the grid twice as coarse gives every run its error estimate, relative.
    path = tmp_path / "e.h5"
    r = magnus.run(NS_CASE, set=NS_TINY, output=path)
    e = r.errors
    for k in ("cl_mean_rel_estimate", "cd_mean_rel_estimate"):
        assert np.isfinite(e[k]) and e[k] > 0, k
        assert r.units["errors"][k] == "1"
    assert e["means_converged"] == 0  # one convective time unit: far from converged
    assert e["companion_n_theta"] == 16
    back = magnus.read(path)
    assert back.errors["cl_mean_rel_estimate"] == e["cl_mean_rel_estimate"]
    with h5py.File(path, "r") as f:
        assert f["errors"].attrs["cd_mean_rel_estimate"] == e["cd_mean_rel_estimate"]
