"""magnus.open and to_xarray: results, sweeps and maps as xarray Datasets, checked against the file itself
(as h5netcdf and h5py read it), the Result the C++ reader gives, and the exact potential flow."""
import math

import h5py
import numpy as np
import pytest

import magnus
from conftest import DEMO, NS_CASE, NS_TINY, SOURCE_DIR, cli

xr = pytest.importorskip("xarray")  # a declared dependency (python3-xarray): scripts/setup.sh installs it
MAP_CASE = SOURCE_DIR / "cases" / "s_map.toml"


def _ns_tiny_args(**more):
    sets = {**NS_TINY, **more}
    return [a for k, v in sets.items() for a in ("--set", f"{k}={v}")]


@pytest.fixture(scope="module")
def potential_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("pot") / "p.h5"
    cli("run", DEMO, "-o", path, "-q", "--set", "grid.n_theta=128")
    return path


@pytest.fixture(scope="module")
def ns_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("ns") / "ns.h5"
    cli("run", NS_CASE, "-o", path, "-q", *_ns_tiny_args(**{"output.snapshots": 3, "output.snapshot_interval": 0.25}))
    return path


def _cf_complete(ds):
    """Every variable and coordinate has a units and a non-empty long_name attribute."""
    for name, v in ds.variables.items():
        assert "units" in v.attrs, name
        assert v.attrs.get("long_name"), name


@pytest.mark.parametrize("which", ["potential_file", "ns_file"])
def test_fields_are_what_h5netcdf_reads_from_the_file(which, request):
    path = request.getfixturevalue(which)
    ds = magnus.open(path)
    with xr.open_dataset(path, engine="h5netcdf", group="fields") as fields:
        assert set(fields.data_vars) == set(magnus.read(path).fields)
        mine = ds[list(fields.data_vars)].reset_coords(drop=True).drop_vars(["r", "theta"])
        mine.attrs = {}
        xr.testing.assert_identical(mine, fields.load())
    with xr.open_dataset(path, engine="h5netcdf") as root:
        for c in ("r", "theta"):
            xr.testing.assert_identical(ds[c], root[c].load())
    with xr.open_dataset(path, engine="h5netcdf", group="grid") as grid:
        for c in ("x", "y"):
            xr.testing.assert_identical(ds[c].reset_coords(drop=True).drop_vars(["r", "theta"]),
                                        grid[c].reset_coords(drop=True).drop_vars(["r", "theta"]).load())
    _cf_complete(ds)


def test_potential_dataset_holds_the_result(potential_file):
    r = magnus.read(potential_file)
    ds = r.to_xarray()
    xr.testing.assert_identical(ds, magnus.open(potential_file))  # the same Dataset from memory and from file
    assert ds.psi.dims == ("r", "theta") and ds.x.dims == ("r", "theta")
    rr, th = np.meshgrid(ds.r.values, ds.theta.values, indexing="ij")
    np.testing.assert_allclose(ds.x.values, rr * np.cos(th), rtol=0, atol=1e-15 * rr.max())
    np.testing.assert_allclose(ds.y.values, rr * np.sin(th), rtol=0, atol=1e-15 * rr.max())
    assert ds.psi.attrs["units"] == "m^2/s" and ds.r.attrs["units"] == "m" and ds.theta.attrs["units"] == "rad"
    # The scalars: the forces with their units, Kutta–Joukowski C_L = −Γ/(Ua) = −2πα exactly.
    assert float(ds.cl) == r.forces["cl"] and ds.lift.attrs["units"] == "N/m"
    assert float(ds.cl_kutta_joukowski) == pytest.approx(-2 * math.pi * r.parameters["spin_ratio"], rel=1e-14)
    assert float(ds.cl_rel) == r.errors["cl_rel"]
    # The surface over theta, the stagnation points over their own axis, the parameters as attributes.
    np.testing.assert_array_equal(ds.surface_cp.values, r.surface["cp"])
    assert ds.surface_cp.dims == ("theta",) and ds.stagnation_theta.dims == ("stagnation_point",)
    assert ds.attrs["radius"] == r.parameters["radius"] and ds.attrs["radius_units"] == "m"
    assert ds.attrs["model"] == "potential"
    # Undefined values are named, never stored as numbers: a scene without a span has no totals.
    undefined = [n for g in (r.forces, r.errors) for n, v in g.items() if v is None]
    assert undefined and ds.attrs["undefined"].split(", ") == undefined
    assert not any(n in ds.variables for n in undefined)


def test_navier_stokes_history_and_snapshots(ns_file):
    r = magnus.read(ns_file)
    ds = magnus.open(ns_file)
    h = r.history
    assert ds.t.dims == ("t",) and ds.t.attrs["units"] == "s" and ds.sizes["t"] == h["t"].size
    assert ds.t_convective.dims == ("t",) and ds.t_convective.attrs["units"] == "1"
    for name in ("cl", "cd", "cm", "lift", "drag", "torque"):
        assert ds[name].dims == ("t",), name
        np.testing.assert_array_equal(ds[name].values, h[name])
        # The last-step force of /forces is the history's last value: one variable holds both.
        assert float(ds[name][-1]) == r.forces[name], name
    assert float(ds.cl_mean) == r.forces["cl_mean"] and ds.cl_mean.dims == ()
    assert float(ds.cl_mean_rel_estimate) == r.errors["cl_mean_rel_estimate"]
    assert ds.snapshot_vorticity.dims == ("t_snapshot", "r", "theta") and ds.sizes["t_snapshot"] == 3
    np.testing.assert_array_equal(ds.snapshot_vorticity.values, r.snapshots["vorticity"])
    np.testing.assert_array_equal(ds.t_snapshot.values, r.snapshots["t"])
    assert ds.surface_shear_stress.attrs["units"] == "Pa"
    _cf_complete(ds)


def test_sweep_from_python_and_from_the_file_agree(tmp_path):
    path = tmp_path / "s.h5"
    cli("sweep", DEMO, "--spin-ratio", "0:2:0.5", "-o", path, "-q")
    from_file = magnus.open(path)
    from_python = magnus.sweep(DEMO, spin_ratio=np.arange(0, 2.01, 0.5)).to_xarray()
    assert from_file.cl.dims == ("spin_ratio",)
    np.testing.assert_array_equal(from_file.spin_ratio.values, [0, 0.5, 1, 1.5, 2])
    for name in ("cl", "cl_kutta_joukowski", "lift", "circulation"):
        np.testing.assert_array_equal(from_file[name].values, from_python[name].values)
        assert from_file[name].attrs == from_python[name].attrs
    np.testing.assert_allclose(from_file.cl_kutta_joukowski, -2 * np.pi * from_file.spin_ratio, rtol=1e-14)
    # Undefined at α = 0 (the ratio KJ / seed is 0/0): NaN, in both, where the file stores its fill value.
    assert np.isnan(from_file.kj_over_seed.values[0]) and np.isnan(from_python.kj_over_seed.values[0])
    np.testing.assert_allclose(from_file.kj_over_seed.values[1:], np.pi / 2, rtol=1e-14)
    _cf_complete(from_file)
    by_gamma = magnus.sweep(DEMO, circulation=[0.0, 1.0, 2.0], circulation__model="given",
                            circulation__value=1.0).to_xarray()
    assert by_gamma.cl.dims == ("circulation",) and by_gamma.circulation.attrs["units"] == "m^2/s"


def test_map_is_indexed_by_reynolds_and_spin_ratio(tmp_path):
    whole, half = tmp_path / "map.h5", tmp_path / "half.h5"
    axes = ["--reynolds", "40:60:20", "--spin-ratio", "0:0.5:0.5", "--set", "grid.n_theta=32"]
    cli("sweep", MAP_CASE, *axes, "-o", whole, "-q")
    cli("sweep", MAP_CASE, *axes, "--shard", "1/2", "-o", half, "-q")
    ds = magnus.open(whole)
    assert ds.cl.dims == ("reynolds", "spin_ratio")
    np.testing.assert_array_equal(ds.reynolds.values, [40, 60])
    np.testing.assert_array_equal(ds.spin_ratio.values, [0, 0.5])
    with h5py.File(whole, "r") as f:
        s = f["sweep"]
        for k in range(s["cl"].shape[0]):
            at = dict(reynolds=s["reynolds"][k], spin_ratio=s["alpha"][k])
            assert float(ds.cl.sel(at)) == s["cl"][k] and float(ds.cd.sel(at)) == s["cd"][k]
    _cf_complete(ds)
    # A shard holds some of the points: the others are NaN, the ones it holds equal the whole map's.
    part = magnus.open(half)
    held = np.isfinite(part.cd.values)
    assert 0 < held.sum() < held.size
    np.testing.assert_array_equal(part.cd.values[held], ds.cd.values[held])


def test_open_refuses_what_is_not_a_magnus_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        magnus.open(tmp_path / "missing.h5")
    text = tmp_path / "notes.h5"
    text.write_text("not HDF5\n")
    with pytest.raises(ValueError, match="not an HDF5 file"):
        magnus.open(text)
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f.attrs["format"] = "something-else"
    with pytest.raises(ValueError, match="'something-else' is not a magnus result"):
        magnus.open(other)
