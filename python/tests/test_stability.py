"""magnus.stability: the steady state's eigenvalues and its 3D stability against the command line's JSON."""
import json

import numpy as np
import pytest

import magnus
from conftest import SOURCE_DIR, cli

S_MAP = SOURCE_DIR / "cases" / "s_map.toml"


def test_stability_and_spanwise_match_the_command_line():
    # Re 40, α 1 (the map case's spin) on the map's grid: a steady wake, β·D = 0 and 1.
    s = magnus.stability(S_MAP, spanwise=[0.0, 1.0], flow__reynolds=40)
    j = json.loads(cli("stability", S_MAP, "--set", "flow.reynolds=40", "--spanwise", "--beta", "0:1:1",
                       "--json").stdout)
    assert s["reynolds"] == pytest.approx(40.0) and s["spin_ratio"] == j["spin_ratio"] == 1.0
    assert s["stable"] == j["stable"]
    assert s["eigenvalues"].dtype == np.complex128
    assert s["eigenvalues"][0].real == pytest.approx(j["eigenvalues"][0]["growth_rate"], rel=0, abs=1e-12)
    sp = s["spanwise"]
    assert sp["base"] == "steady"
    assert list(sp["beta_D"]) == [0.0, 1.0]
    for k in range(2):
        assert sp["growth_rate"][k] == pytest.approx(j["spanwise"]["points"][k]["growth_rate"], rel=0, abs=1e-12)
    # β = 0 is the 2D problem.
    assert sp["growth_rate"][0] < 0.0 and s["eigenvalues"][0].real < 0.0  # β = 0: the 2D verdict, stable
    assert sp["verdict"] == j["spanwise"]["verdict"]
    assert sp["accuracy_note"] == j["spanwise"]["accuracy_note"]  # the operator's measured accuracy, both ways
    # The 2D problem (β = 0) is the least stable here: no 3D wavenumber to name.
    assert sp["growth_rate"][0] > sp["growth_rate"][1]
    assert "most_unstable_beta_D" not in sp and "most_unstable_wavelength_D" not in sp


def test_bad_input_is_one_value_error():
    with pytest.raises(ValueError, match="navier-stokes"):
        magnus.stability(SOURCE_DIR / "cases" / "spin_ratio_1.toml")
    with pytest.raises(ValueError, match="spanwise"):
        magnus.stability(S_MAP, spanwise=[float("nan")])
    with pytest.raises(ValueError, match="eigensolver"):
        magnus.stability(S_MAP, eigensolver="lapack")


def test_onset_3d_matches_the_command_line():
    # α 3 on n_θ 32: stable to every wavenumber at Re 30 and 60, so there is no crossing; each end one scan.
    kw = dict(grid__n_theta=32, cylinder__spin_ratio=3)
    o = magnus.onset_3d(S_MAP, reynolds=(30, 60), spanwise=[1.0, 2.0], fine_grid=(48, 30), **kw)
    j = json.loads(cli("stability", S_MAP, "--set", "grid.n_theta=32", "--set", "cylinder.spin_ratio=3",
                       "--spanwise", "--beta", "1:2:1", "--critical-reynolds", "30:60", "--json").stdout)
    assert o["found"] is False and j["found"] is False
    assert o["message"] == j["undefined"]
    assert o["accuracy_note"] == j["accuracy_note"]
    assert "critical_reynolds" not in o
    assert list(o["evaluations"]["reynolds"]) == [30.0, 60.0]
    assert list(o["evaluations"]["periodic"]) == [0.0, 0.0]
    for k in range(2):
        assert o["evaluations"]["growth_rate"][k] == pytest.approx(j["evaluations"][k]["growth_rate"], rel=0, abs=1e-12)
    # The refinement on the finer grid is not run without an onset, and says why.
    assert o["fine_grid"]["found"] is False
    assert o["fine_grid"]["message"] == "the search on the case's grid found no onset"
    assert o["fine_grid"]["n_theta"] == 48 and o["fine_grid"]["outer_radius_over_a"] == 30.0
    with pytest.raises(ValueError, match="0 < Re_a < Re_b"):
        magnus.onset_3d(S_MAP, reynolds=(60, 30), spanwise=[1.0])
    with pytest.raises(ValueError, match="must be finer than the case's grid"):
        magnus.onset_3d(S_MAP, reynolds=(30, 60), spanwise=[1.0], fine_grid=(16, 30), **kw)
    with pytest.raises(ValueError, match="n_θ must be an even whole number"):
        magnus.onset_3d(S_MAP, reynolds=(30, 60), spanwise=[1.0], fine_grid=(0, 30), **kw)
    with pytest.raises(ValueError, match=r"fine_grid: expected \(n_theta, R/a\)"):
        magnus.onset_3d(S_MAP, reynolds=(30, 60), spanwise=[1.0], fine_grid=192)


def _onset_file(path, alpha, re_c):
    """A stability file holding a found 3D onset, with what `magnus run --onset3d` reads of one (the search
    that writes it is tested through the command line)."""
    import h5py
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "magnus-stability"
        f.attrs["format_version"] = 1
        f.attrs["spin_ratio"] = float(alpha)
        g = f.create_group("onset3d")
        g.attrs["found"] = 1
        g.attrs["critical_reynolds"] = float(re_c)
    return path


def test_run_with_a_computed_onset_matches_the_command_line(tmp_path):
    from conftest import NS_CASE, NS_TINY
    f = _onset_file(tmp_path / "onset.h5", 1.0, 150.0)  # the case's α = 1
    sets = {k.replace(".", "__"): v for k, v in NS_TINY.items()}
    below = magnus.run(NS_CASE, onset3d=f, **sets)
    assert below.parameters["onset3d_reynolds"] == 150.0
    assert below.parameters["onset3d_alpha_min"] == below.parameters["onset3d_alpha_max"] == 1.0
    assert below.parameters["onset3d_files"] == str(f)
    args = [a for k, v in NS_TINY.items() for a in ("--set", f"{k}={v}")]
    j = json.loads(cli("run", NS_CASE, "-o", tmp_path / "r.h5", "--onset3d", f, "--json", *args).stdout)
    assert j["derived"]["three_dimensional"] is False  # Re 100 < 150
    above = magnus.run(NS_CASE, onset3d=[f], flow__reynolds=160, **sets)
    assert above.parameters["reynolds"] == 160.0 and above.parameters["onset3d_reynolds"] == 150.0
    assert magnus.run(NS_CASE, **sets).parameters.get("onset3d_reynolds") is None
    with pytest.raises(ValueError, match="onset3d: only for a navier-stokes case"):
        magnus.run(SOURCE_DIR / "cases" / "spin_ratio_1.toml", onset3d=f)
    with pytest.raises(RuntimeError, match="holds no 3D onset"):
        import h5py
        with h5py.File(tmp_path / "empty.h5", "w") as e:
            e.attrs["format"] = "magnus-stability"
            e.attrs["format_version"] = 1
        magnus.run(NS_CASE, onset3d=tmp_path / "empty.h5", **sets)
