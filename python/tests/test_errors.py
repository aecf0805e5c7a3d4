"""Errors: ValueError for bad input, RuntimeError otherwise, each with the command line's one line."""
import pytest

import magnus
from conftest import DEMO, NS_CASE, cli_error


@pytest.mark.parametrize(
    "kwargs, sets",
    [
        ({"cylinder__radus": 0.1}, ["cylinder.radus=0.1"]),
        ({"grid__n_theta": 7}, ["grid.n_theta=7"]),
        ({"set": {"grid.spacing": "cubic"}}, ['grid.spacing="cubic"']),
        ({"flow__speed": -1.0}, ["flow.speed=-1.0"]),
        ({"model__flow": "navier-stoke"}, ['model.flow="navier-stoke"']),
        ({"set": {"solver.method": "ftt"}}, ['solver.method="ftt"']),
    ],
)
def test_bad_overrides_raise_the_command_lines_message(kwargs, sets):
    args = [a for s in sets for a in ("--set", s)]
    expected = cli_error("run", DEMO, *args)
    with pytest.raises(ValueError) as e:
        magnus.run(DEMO, **kwargs)
    assert str(e.value) == expected
    # A value given as an override is blamed on the override, never on the case file.
    assert str(e.value).startswith("--set "), str(e.value)


def test_a_missing_case_file(tmp_path):
    missing = tmp_path / "nope.toml"
    expected = cli_error("run", missing)
    with pytest.raises(ValueError) as e:
        magnus.run(missing)
    assert str(e.value) == expected


def test_a_dict_case_names_its_origin():
    with pytest.raises(ValueError, match=r"^<dict>: .*cylinder\.radius"):
        magnus.run({"cylinder": {"spin": 1.0}, "flow": {"speed": 1.0}})


def test_reading_a_file_that_is_not_a_result(tmp_path):
    with pytest.raises(RuntimeError) as e:
        magnus.read(DEMO)
    assert str(e.value) == cli_error("inspect", DEMO)
    assert "\n" not in str(e.value)


def test_bad_python_arguments():
    with pytest.raises(TypeError, match="section__key"):
        magnus.run(DEMO, n_theta=64)
    with pytest.raises(ValueError, match="threads"):
        magnus.run(DEMO, threads=0)
    with pytest.raises(TypeError, match="case"):
        magnus.run(42)
    with pytest.raises(ValueError, match="exactly one"):
        magnus.sweep(DEMO)
    with pytest.raises(ValueError, match="finite"):
        magnus.sweep(DEMO, spin_ratio=[0.0, float("nan")])
    with pytest.raises(ValueError, match="1-D"):
        magnus.sweep(DEMO, spin_ratio=[[0.0, 1.0]])


def test_a_navier_stokes_sweep_is_refused_in_one_line_naming_the_command():
    with pytest.raises(RuntimeError) as e:
        magnus.sweep(NS_CASE, spin_ratio=[0.0, 1.0])
    message = str(e.value)
    assert message.startswith(str(NS_CASE) + ": model.flow = \"navier-stokes\"")
    assert "magnus sweep CASE --spin-ratio" in message and "\n" not in message


def test_an_output_that_magnus_did_not_write_is_refused_unless_forced(tmp_path):
    mine = tmp_path / "notes.h5"
    mine.write_text("my notes\n")
    with pytest.raises(RuntimeError, match=r"magnus replaces only its own outputs"):
        magnus.run(DEMO, output=mine, grid__n_theta=32)
    assert mine.read_text() == "my notes\n"
    magnus.run(DEMO, output=mine, grid__n_theta=32, force=True)
    assert mine.read_bytes().startswith(b"\x89HDF\r\n\x1a\n")
    # Its own result now: replaced without force (force does not stay on after the call).
    magnus.run(DEMO, output=mine, grid__n_theta=32)
    other = tmp_path / "other.h5"
    other.write_text("more notes\n")
    with pytest.raises(RuntimeError):
        magnus.run(DEMO, output=other, grid__n_theta=32)
