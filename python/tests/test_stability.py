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
    assert sp["growth_rate"][0] == pytest.approx(s["eigenvalues"][0].real, rel=0, abs=1e-9)
    assert sp["verdict"] == j["spanwise"]["verdict"]
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
    o = magnus.onset_3d(S_MAP, reynolds=(30, 60), spanwise=[1.0, 2.0], **kw)
    j = json.loads(cli("stability", S_MAP, "--set", "grid.n_theta=32", "--set", "cylinder.spin_ratio=3",
                       "--spanwise", "--beta", "1:2:1", "--critical-reynolds", "30:60", "--json").stdout)
    assert o["found"] is False and j["found"] is False
    assert o["message"] == j["undefined"]
    assert "critical_reynolds" not in o
    assert list(o["evaluations"]["reynolds"]) == [30.0, 60.0]
    assert list(o["evaluations"]["periodic"]) == [0.0, 0.0]
    for k in range(2):
        assert o["evaluations"]["growth_rate"][k] == pytest.approx(j["evaluations"][k]["growth_rate"], rel=0, abs=1e-12)
    with pytest.raises(ValueError, match="0 < Re_a < Re_b"):
        magnus.onset_3d(S_MAP, reynolds=(60, 30), spanwise=[1.0])
