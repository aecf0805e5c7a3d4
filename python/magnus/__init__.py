"""magnus: flow past a spinning cylinder (potential flow and a 2D Navier–Stokes model), from Python.

    import magnus
    r = magnus.run("cases/spin_ratio_1.toml", grid__n_theta=512)   # no file unless output= is given
    r.forces["cl"], r.units["forces"]["cl"]                         # -6.283…, "1"
    r.fields["cp"].shape                                            # (n_r, n_theta)
    s = magnus.sweep("cases/spin_ratio_1.toml", spin_ratio=numpy.linspace(0, 4, 1000))
    s["alpha"], s["cl"], s.units["cl"]
    magnus.read("magnus.h5").forces
    ds = magnus.open("magnus.h5")                                   # an xarray.Dataset (also r.to_xarray())

A case is a path to a TOML case file or a dict shaped like one ({"cylinder": {"radius": 0.1, ...}, ...}).
Overrides are keyword arguments section__key=value (grid__n_theta=512) or set={"grid.n_theta": 512}.
Errors raise ValueError (bad input) or RuntimeError with the command line's one-line message.
"""
import math
import numbers
import os
import re

import numpy as np

from . import _magnus, _xarray
from ._magnus import Result

__version__ = _magnus.__version__
Result.__module__ = __name__
__all__ = ["run", "sweep", "stability", "onset_3d", "read", "open", "Result", "Sweep", "case_toml"]

_MAX_THREADS = 64
_MAX_SWEEP_POINTS = 100000  # as `magnus sweep`
_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _toml_string(s):
    out = ['"']
    for ch in s:
        if ch == '"' or ch == "\\":
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append("\\u%04X" % ord(ch))
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def _toml_key(k, where):
    if not isinstance(k, str):
        raise TypeError(f"{where}: a case key must be a string, not {type(k).__name__}")
    return k if _BARE_KEY.match(k) else _toml_string(k)


def _toml_value(v, where):
    """A Python value as a TOML value: bool, int, float, str (or path), list, dict (inline table)."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # the shortest text that reads back as the same double
    if isinstance(v, (str, os.PathLike)):
        return _toml_string(os.fspath(v))
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(x, where) for x in list(v)) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_toml_key(k, where)} = {_toml_value(x, where)}" for k, x in v.items()) + "}"
    raise TypeError(f"{where}: a {type(v).__name__} has no TOML form (use bool, int, float, str or a list)")


def case_toml(case):
    """The TOML text of a case given as a dict shaped like a case file."""
    if not isinstance(case, dict):
        raise TypeError(f"case: expected a dict, not {type(case).__name__}")
    top, sections = [], []
    for key, value in case.items():
        if isinstance(value, dict):
            lines = [f"[{_toml_key(key, key)}]"]
            for k, v in value.items():
                lines.append(f"{_toml_key(k, f'{key}.{k}')} = {_toml_value(v, f'{key}.{k}')}")
            sections.append("\n".join(lines))
        else:
            top.append(f"{_toml_key(key, key)} = {_toml_value(value, key)}")
    return "\n\n".join(["\n".join(top)] + sections if top else sections) + "\n"


def _source(case):
    """(text or path, is_path) of a case argument."""
    if isinstance(case, dict):
        return case_toml(case), False
    if isinstance(case, (str, os.PathLike)):
        return os.fspath(case), True
    raise TypeError(f"case: expected a path or a dict shaped like a case file, not {type(case).__name__}")


def _overrides(kwargs, set_):
    """Keyword overrides section__key=value and set={"section.key": value} as "section.key=value"."""
    out = []
    for name, value in kwargs.items():
        if "__" not in name:
            raise TypeError(
                f"unexpected keyword argument '{name}': a case override is section__key=value "
                f"(e.g. grid__n_theta=512)")
        section, key = name.split("__", 1)
        out.append(f"{section}.{key}={_toml_value(value, f'{section}.{key}')}")
    if set_ is not None:
        if not isinstance(set_, dict):
            raise TypeError(f"set: expected a dict {{'section.key': value}}, not {type(set_).__name__}")
        for key, value in set_.items():
            if not isinstance(key, str):
                raise TypeError(f"set: a key must be a string 'section.key', not {type(key).__name__}")
            out.append(f"{key}={_toml_value(value, key)}")
    return out


def _threads(threads):
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or not 1 <= threads <= _MAX_THREADS:
        raise ValueError(f"threads {threads!r}: must be an integer from 1 to {_MAX_THREADS}")
    return min(int(threads), os.cpu_count() or int(threads))


def run(case, /, *, set=None, output=None, threads=1, force=False, onset3d=None, **overrides):
    """Solve a case and return its Result. No file is written unless output (a path) is given: then the
    result is written there (with its .xmf sidecar) as `magnus run -o` would: an existing file there that
    magnus did not write is refused (RuntimeError) unless force=True. onset3d: stability files holding a
    computed 3D onset (`magnus stability --spanwise --critical-reynolds --output`, one per α), as
    `magnus run --onset3d`: parameters["onset3d_reynolds"] is then Re_c at the case's α, and the 2D flow is
    real below it. The GIL is released while solving; Ctrl-C stops a navier-stokes run (KeyboardInterrupt)."""
    source, is_path = _source(case)
    sets = _overrides(overrides, set)
    out = "" if output is None else os.fspath(output)
    if output is not None and out == "":
        raise ValueError("output: an empty path")
    if isinstance(onset3d, (str, os.PathLike)):
        onset3d = [onset3d]
    files = [] if onset3d is None else [os.fspath(f) for f in onset3d]
    return _magnus._run(source, is_path, sets, _threads(threads), out, bool(force), files)


def read(path):
    """The Result stored in a magnus-flow file (format version 1 or 2, potential or navier-stokes)."""
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path: expected a path, not {type(path).__name__}")
    return _magnus._read(os.fspath(path))


def open(path):  # noqa: A001 (magnus.open, as xarray.open_dataset: the name users look for)
    """The xarray.Dataset of a file magnus wrote: a result (fields over (r, theta) with x, y as 2-D
    coordinates; a navier-stokes force history over t), a sweep (over spin_ratio) or a map (over
    (reynolds, spin_ratio)). Every variable carries units and long_name. Needs python3-xarray."""
    return _xarray.open_dataset(path)


Result.to_xarray = lambda self: _xarray.result_dataset(self)
Result.to_xarray.__doc__ = "The result as an xarray.Dataset (as magnus.open gives for its file)."


class Sweep(dict):
    """The columns of a sweep (name → 1-D array, one value per point), named as the sweep file's /sweep
    datasets. A column undefined at some points is a numpy masked array (masked there); a column undefined
    at every point is left out and named in .undefined. Attributes: units, descriptions (per column),
    undefined, grid (n_r, n_theta, outer_radius), method, timing (s), case (the resolved TOML text), variable
    (the swept one: spin_ratio or circulation). to_xarray() gives it as an xarray.Dataset."""

    def __init__(self, raw, variable="spin_ratio"):
        super().__init__()
        self.variable = variable  # the swept variable: "spin_ratio" or "circulation"
        self.units, self.descriptions, self.undefined = {}, {}, []
        for name, column in raw["columns"].items():
            finite = np.isfinite(column)
            if column.size and not finite.any():
                self.undefined.append(name)
                continue
            self[name] = column if finite.all() else np.ma.masked_array(column, mask=~finite, fill_value=np.nan)
            self.units[name] = raw["units"][name]
            self.descriptions[name] = raw["descriptions"][name]
        self.grid, self.method, self.timing, self.case = raw["grid"], raw["method"], raw["timing"], raw["case"]

    def __repr__(self):
        n = len(next(iter(self.values()))) if self else 0
        return f"<magnus.Sweep {n} points: {', '.join(self)}>"

    def to_xarray(self):
        """The sweep as an xarray.Dataset over spin_ratio (or circulation): NaN where a column is undefined."""
        return _xarray.sweep_dataset(self)


def _sweep_values(values, name):
    try:
        v = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{name}: expected numbers (a list or a 1-D array)") from None
    if v.ndim > 1:
        raise ValueError(f"{name}: expected a 1-D array, not shape {v.shape}")
    v = np.atleast_1d(v)
    if v.size == 0:
        raise ValueError(f"{name}: no values")
    if v.size > _MAX_SWEEP_POINTS:
        raise ValueError(f"{name}: {v.size} points, more than the {_MAX_SWEEP_POINTS} a sweep accepts")
    bad = np.flatnonzero(~np.isfinite(v))
    if bad.size:
        raise ValueError(f"{name}: value {bad[0]} is not a finite number")
    return v


def sweep(case, /, spin_ratio=None, *, circulation=None, set=None, threads=1, **overrides):
    """Lift against spin ratio α = aω/U (or circulation Γ in m²/s with circulation.model = "given") by
    superposition: one factorization and two solves for any number of points (potential flow). Returns a
    Sweep: a dict of 1-D arrays (alpha, circulation, lift, drag, cl, cl_kutta_joukowski, cd, …) with
    .units."""
    if (spin_ratio is None) == (circulation is None):
        raise ValueError("sweep: give exactly one of spin_ratio=… and circulation=…")
    variable = "spin_ratio" if spin_ratio is not None else "circulation"
    values = _sweep_values(spin_ratio if spin_ratio is not None else circulation, variable)
    source, is_path = _source(case)
    raw = _magnus._sweep(source, is_path, variable, values, _overrides(overrides, set), _threads(threads))
    return Sweep(raw, variable)


def stability(case, /, *, spanwise=None, eigensolver="arnoldi", set=None, **overrides):
    """Linear stability of a navier-stokes case, as `magnus stability CASE [--spanwise]`. Returns a dict:
    reynolds, spin_ratio, stable (the steady state's 2D verdict), eigenvalues (complex array, λ·D/U,
    rightmost first) and covered. With spanwise = wavenumbers β·D (an iterable of numbers ≥ 0) it adds
    "spanwise": the 3D stability of the steady state (base "steady") or, when the wake sheds, of its
    periodic orbit (base "periodic", with the multipliers and period_D_over_U): beta_D, growth_rate and
    frequency arrays (U/D; an eigenvalue that did not converge is masked), stable, verdict and the most
    unstable wavenumber and wavelength (in D)."""
    beta = [] if spanwise is None else [float(b) for b in _sweep_values(spanwise, "spanwise")]
    source, is_path = _source(case)
    raw = _magnus._stability(source, is_path, _overrides(overrides, set), beta, str(eigensolver))
    if "spanwise" in raw:
        sp = raw["spanwise"]
        for key in ("growth_rate", "frequency", "multiplier"):
            if key in sp:
                sp[key] = np.ma.masked_invalid(sp[key])
    return raw


def onset_3d(case, /, *, reynolds, spanwise, tolerance=1.0, eigensolver="arnoldi", fine_grid=None, set=None,
             **overrides):
    """Where the flow turns three-dimensional, as `magnus stability CASE --spanwise --beta … --critical-reynolds
    A:B`: the Reynolds number in reynolds = (A, B) where the largest growth rate over the wavenumbers
    spanwise (β·D, an iterable of numbers ≥ 0) crosses zero, to within tolerance (in Re). Returns a dict:
    spin_ratio, found; when found critical_reynolds, change, bracket, beta_D and wavelength_D (in D), else
    message (why not); evaluations (arrays reynolds, growth_rate in U/D, beta_D, periodic: one per scan) and
    seconds. fine_grid = (n_theta, R/a), as --fine-grid N:R, then refines the onset on that grid: "fine_grid"
    holds n_theta, n_r, outer_radius_over_a, found, critical_reynolds, error_estimate, beta_D,
    line_critical_reynolds and extrapolated (or message), its two scans' evaluations (reynolds, growth_rate) and
    seconds."""
    beta = [float(b) for b in _sweep_values(spanwise, "spanwise")]
    lo, hi = (float(x) for x in reynolds)
    source, is_path = _source(case)
    fine_n, fine_r = (0.0, 0.0) if fine_grid is None else _fine_grid(fine_grid)
    return _magnus._onset_3d(source, is_path, _overrides(overrides, set), beta, lo, hi, float(tolerance),
                             str(eigensolver), fine_grid is not None, fine_n, fine_r)


def _fine_grid(fine_grid):
    """(n_theta, R/a) as two floats; a clear ValueError for anything else (the range is checked in C++)."""
    try:
        n, r = fine_grid
        return float(n), float(r)
    except (TypeError, ValueError):
        raise ValueError(f"fine_grid: expected (n_theta, R/a), e.g. (192, 60), got {fine_grid!r}") from None

