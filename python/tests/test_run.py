"""magnus.run: the demo case against the command line and the exact solution; dict cases, overrides."""
import json
import math

import numpy as np
import pytest

import magnus
from conftest import DEMO, cli

TWO_PI = 2.0 * math.pi


def demo_dict():
    """The demo case file as a dict."""
    return {
        "title": "Spinning cylinder, spin ratio 1",
        "cylinder": {"radius": 0.1, "spin": 100.0},
        "flow": {"speed": 10.0, "density": 1.225, "pressure": 101325.0},
        "domain": {"outer_radius": 20.0, "far_field": "exact"},
        "grid": {"n_theta": 256, "spacing": "geometric"},
        "solver": {"method": "auto", "stencil": "5-point"},
        "output": {"file": "magnus.h5"},
    }


def test_demo_lift_equals_the_command_line_and_the_exact_lift(in_tmp):
    r = magnus.run(DEMO)
    assert list(in_tmp.iterdir()) == []  # no file unless asked
    out = json.loads(cli("run", DEMO, "-o", in_tmp / "cli.h5", "--json").stdout)
    for key in ("cl", "cd", "lift", "cl_kutta_joukowski", "circulation_measured"):
        assert r.forces[key] == pytest.approx(out["forces"][key]["value"], rel=0, abs=1e-10), key
        assert r.units["forces"][key] == out["forces"][key]["units"], key
    alpha = r.parameters["spin_ratio"]
    assert alpha == 1.0
    assert r.forces["cl_kutta_joukowski"] == pytest.approx(-TWO_PI * alpha, rel=0, abs=1e-10)
    # The 5-point demo grid's C_L is second-order accurate: within 1e-4 of −2πα, not exact.
    assert abs(r.forces["cl"] + TWO_PI * alpha) < 1e-4 * TWO_PI
    assert abs(r.forces["cl"] + TWO_PI * alpha) > 1e-8
    # The 9-point stencil on the same grid reaches −2πα to 1e-10.
    r9 = magnus.run(DEMO, solver__stencil="9-point")
    assert r9.forces["cl"] == pytest.approx(-TWO_PI * alpha, rel=0, abs=1e-10)


def test_a_dict_case_is_the_same_case_as_its_file():
    a, b = magnus.run(DEMO), magnus.run(demo_dict())
    assert a.forces == b.forces
    assert a.parameters == b.parameters
    for name, field in a.fields.items():
        assert np.array_equal(field, b.fields[name]), name


def test_keyword_and_set_overrides():
    r = magnus.run(demo_dict(), grid__n_theta=64, set={"cylinder.spin_ratio": 2.0})
    assert r.grid["theta"].shape == (64,)
    assert r.parameters["n_theta"] == 64
    assert r.parameters["spin_ratio"] == 2.0
    assert r.parameters["spin"] == pytest.approx(200.0, rel=1e-15)  # ω = αU/a replaces the file's spin
    assert r.forces["cl_kutta_joukowski"] == pytest.approx(-2.0 * TWO_PI, rel=1e-14)
    # A string value and a bool-free text value pass as TOML strings.
    assert magnus.run(DEMO, grid__n_theta=64, grid__spacing="uniform").parameters["spacing"] == "uniform"


def test_the_case_text_round_trips_strings_that_need_escaping():
    case = demo_dict()
    case["title"] = 'a "quoted" title \\ with a backslash'
    assert magnus.run(case, grid__n_theta=16).attributes["title"] == case["title"]


def test_output_writes_the_file_as_the_command_line_does(in_tmp):
    r = magnus.run(DEMO, output=in_tmp / "r.h5", grid__n_theta=64)
    assert sorted(p.name for p in in_tmp.iterdir()) == ["r.h5", "r.xmf"]
    back = magnus.read(in_tmp / "r.h5")
    assert back.forces == r.forces


def test_fields_have_the_grid_shape_and_are_views():
    r = magnus.run(DEMO, grid__n_theta=64)
    n_r, n_theta = r.grid["r"].size, r.grid["theta"].size
    assert n_theta == 64 and n_r == r.parameters["n_r"]
    assert set(r.fields) == {"psi", "u_r", "u_theta", "u_x", "u_y", "pressure", "cp", "psi_exact", "psi_error"}
    for name, f in r.fields.items():
        assert f.shape == (n_r, n_theta), name
        assert f.dtype == np.float64
        assert not f.flags.writeable
    # Two looks at a field are the same memory (a view of the result, not a copy per access).
    assert np.shares_memory(r.fields["psi"], r.fields["psi"])
    # The view outlives the Result object it came from.
    psi = magnus.run(DEMO, grid__n_theta=64).fields["psi"]
    assert np.isfinite(psi).all() and psi.shape == (n_r, n_theta)
    # ψ on the body is the same at every θ (a streamline) and x = r cos θ.
    assert np.ptp(r.fields["psi"][0]) < 1e-12 * np.abs(r.fields["psi"]).max()
    assert np.allclose(r.grid["x"], np.outer(r.grid["r"], np.cos(r.grid["theta"])), rtol=0, atol=1e-15)
    assert r.units["fields"]["psi"] == "m^2/s" and r.units["fields"]["pressure"] == "Pa"
    assert r.history is None  # potential flow has no time history
