"""magnus results, sweeps and maps as xarray Datasets, with CF-style `units` and `long_name` on every variable.

    import magnus
    ds = magnus.open("re100.h5")          # a result: fields (r, theta), x and y as 2-D coordinates, …
    ds.vorticity.plot(x="x", y="y")       # the wake in the plane
    ds.cl.plot()                          # navier-stokes: C_L against t (s)
    m = magnus.open("map.h5")             # a map: variables indexed by (reynolds, spin_ratio)
    m.strouhal.sel(reynolds=100)          # S against α at Re 100

A result's Dataset holds, by the file's groups:
- /fields: data variables over (r, theta) named as the fields; coordinates r (m), theta (rad) and the 2-D
  x = r cos θ, y = r sin θ (m). Their values, units and long_name are those `xarray.open_dataset(path,
  engine="h5netcdf", group="fields")` gives.
- /forces and /errors (numbers): 0-d variables with units and long_name (cl, cd, cl_mean, strouhal,
  cl_mean_rel_estimate, …). A navier-stokes result's last-step cl, cd, cm, lift, drag, torque are the
  last values of its force history, so there the name is the history variable, indexed by t.
- /history (navier-stokes): cl, cd, cm, lift, drag, torque over the time axis t (s), t_convective (D/U)
  its second coordinate.
- /surface: surface_cp, surface_pressure, surface_u_theta [, surface_shear_stress] over theta.
- /snapshots (navier-stokes with output.snapshots): snapshot_psi, snapshot_vorticity over
  (t_snapshot, r, theta).
- /stagnation (potential): stagnation_r, stagnation_theta [, …_exact] over stagnation_point.
- attributes: the file's root attributes (model, title, case, …), every parameter (NAME with NAME_units),
  the text entries of /errors, and `undefined`: the names of the values the result leaves undefined.
Missing values in a sweep or map Dataset are NaN, xarray's mark for "no value": a map cell the branch did
not reach, a Strouhal number of a steady point.
"""
import os

import numpy as np

_FLOW, _SWEEP = "magnus-flow", "magnus-sweep"


def _xr():
    try:
        import xarray
    except ImportError:
        raise ImportError("magnus: xarray is not installed (apt-get install python3-xarray python3-h5netcdf)") from None
    return xarray


def _attrs(units, description):
    """A variable's CF-style attributes: units, and the one-line description as long_name (and description,
    as the file stores it)."""
    a = {"units": units}
    if description:
        a["long_name"] = description
        a["description"] = description
    return a


def _text(v):
    return v.decode() if isinstance(v, bytes) else v


def _result_coords(r, xr):
    u, d = r.units["grid"], r.descriptions["grid"]
    g = r.grid
    return {
        "r": xr.Variable(("r",), np.asarray(g["r"]), _attrs(u["r"], d["r"])),
        "theta": xr.Variable(("theta",), np.asarray(g["theta"]), _attrs(u["theta"], d["theta"])),
        "x": xr.Variable(("r", "theta"), np.asarray(g["x"]), _attrs(u["x"], d["x"])),
        "y": xr.Variable(("r", "theta"), np.asarray(g["y"]), _attrs(u["y"], d["y"])),
    }


def _history(r, xr, coords, data):
    """navier-stokes: the force history on its own time axis t (s)."""
    h, u, d = r.history, r.units["history"], r.descriptions["history"]
    if not h or "t" not in h:
        return
    coords["t"] = xr.Variable(("t",), np.asarray(h["t"]), _attrs(u["t"], d["t"]))
    if "t_convective" in h:
        coords["t_convective"] = xr.Variable(("t",), np.asarray(h["t_convective"]),
                                             _attrs(u["t_convective"], d["t_convective"]))
    for name, values in h.items():
        if name not in ("t", "t_convective"):
            data[name] = xr.Variable(("t",), np.asarray(values), _attrs(u[name], d[name]))


def _per_point(r, xr, group, dim, prefix, data, skip=()):
    """The 1-D datasets of a group (surface, stagnation) as prefix+name over dim."""
    values, u, d = getattr(r, group), r.units[group], r.descriptions[group]
    for name, v in (values or {}).items():
        if name not in skip:
            data[prefix + name] = xr.Variable((dim,), np.asarray(v), _attrs(u[name], d[name]))


def _scalars(r, xr, group, data, attrs, undefined):
    """A group's numeric attributes as 0-d variables (undefined ones named in `undefined`), its text ones as
    Dataset attributes. A name the history already holds (a navier-stokes last-step value) stays there."""
    values, u, d = getattr(r, group), r.units[group], r.descriptions[group]
    for name, v in values.items():
        if isinstance(v, str):
            attrs[f"{group}_{name}"] = v
        elif v is None:
            undefined.append(name)
        elif name not in data:
            data[name] = xr.Variable((), v, _attrs(u[name], d[name]))


def result_dataset(r):
    """The Dataset of a Result (see the module's docstring)."""
    xr = _xr()
    coords = _result_coords(r, xr)
    data = {}
    fu, fd = r.units["fields"], r.descriptions["fields"]
    for name, v in r.fields.items():
        data[name] = xr.Variable(("r", "theta"), np.asarray(v), _attrs(fu[name], fd[name]))
    if r.model == "navier-stokes":
        _history(r, xr, coords, data)
        snaps = r.snapshots
        if snaps is not None and len(snaps["t"]):
            su, sd = r.units["snapshots"], r.descriptions["snapshots"]
            coords["t_snapshot"] = xr.Variable(("t_snapshot",), np.asarray(snaps["t"]), _attrs(su["t"], sd["t"]))
            for name in ("psi", "vorticity"):
                data["snapshot_" + name] = xr.Variable(("t_snapshot", "r", "theta"), np.asarray(snaps[name]),
                                                       _attrs(su[name], sd[name]))
    surface = r.surface
    if "theta" in surface and not np.array_equal(surface["theta"], r.grid["theta"]):
        raise RuntimeError("magnus: the surface's theta differs from the grid's")  # the format says they agree
    _per_point(r, xr, "surface", "theta", "surface_", data, skip=("theta",))
    _per_point(r, xr, "stagnation", "stagnation_point", "stagnation_", data)
    attrs = {k: v for k, v in r.attributes.items() if v is not None}
    for name, v in r.parameters.items():
        if v is not None:
            attrs[name] = v
            if name in r.units["parameters"]:
                attrs[name + "_units"] = r.units["parameters"][name]
    undefined = []
    for group in ("forces", "errors"):
        _scalars(r, xr, group, data, attrs, undefined)
    attrs["undefined"] = ", ".join(undefined)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _column_attrs(sweep, name):
    return _attrs(sweep.units.get(name, ""), sweep.descriptions.get(name, ""))


def _filled(column):
    """A column as float with NaN where it is undefined (masked)."""
    if isinstance(column, np.ma.MaskedArray):
        return column.astype(np.float64).filled(np.nan)
    return np.asarray(column, dtype=np.float64)


def sweep_dataset(sweep):
    """The Dataset of a 1-D sweep (magnus.sweep or a `magnus sweep` file): the columns over spin_ratio (or
    circulation, for a sweep in Γ), the other sweep variable a second coordinate. Undefined values: NaN."""
    xr = _xr()
    dim = "circulation" if getattr(sweep, "variable", "spin_ratio") == "circulation" else "spin_ratio"
    index = "circulation" if dim == "circulation" else "alpha"
    coords = {dim: xr.Variable((dim,), _filled(sweep[index]), _column_attrs(sweep, index))}
    other = "alpha" if dim == "circulation" else "circulation"
    if other in sweep:
        coords[other] = xr.Variable((dim,), _filled(sweep[other]), _column_attrs(sweep, other))
    data = {name: xr.Variable((dim,), _filled(v), _column_attrs(sweep, name))
            for name, v in sweep.items() if name not in (index, other)}
    return xr.Dataset(data, coords=coords, attrs=dict(getattr(sweep, "attrs", {})))


def map_dataset(sweep, reynolds, alpha, axis_attrs):
    """The Dataset of an S(Re, α) map: every column placed at (row, column) of the (reynolds, spin_ratio)
    grid; a cell no point reached is NaN."""
    xr = _xr()
    rows, cols = np.asarray(sweep["row"], dtype=int), np.asarray(sweep["column"], dtype=int)
    coords = {"reynolds": xr.Variable(("reynolds",), np.asarray(reynolds), axis_attrs["reynolds"]),
              "spin_ratio": xr.Variable(("spin_ratio",), np.asarray(alpha), axis_attrs["alpha"])}
    data = {}
    for name, column in sweep.items():
        if name in ("row", "column", "reynolds", "alpha"):
            continue
        grid = np.full((len(reynolds), len(alpha)), np.nan)
        grid[rows, cols] = _filled(column)
        data[name] = xr.Variable(("reynolds", "spin_ratio"), grid, _column_attrs(sweep, name))
    return xr.Dataset(data, coords=coords, attrs=dict(getattr(sweep, "attrs", {})))


class _FileSweep(dict):
    """The columns of a magnus-sweep file read with h5py: name → array (NaN at the fill value)."""

    def __init__(self, f):
        super().__init__()
        self.units, self.descriptions = {}, {}
        for name, d in f["sweep"].items():
            v = np.asarray(d[()], dtype=np.float64)
            if "_FillValue" in d.attrs:
                v = np.where(v == d.attrs["_FillValue"], np.nan, v)
            self[name] = v
            self.units[name] = _text(d.attrs.get("units", ""))
            self.descriptions[name] = _text(d.attrs.get("description", ""))
        self.variable = _text(f.attrs.get("variable", "spin_ratio"))
        self.attrs = {k: _text(v) for k, v in f.attrs.items()}
        for k, v in f["parameters"].attrs.items() if "parameters" in f else ():
            self.attrs[k] = _text(v)


def _axis_attrs(d):
    return _attrs(_text(d.attrs.get("units", "")), _text(d.attrs.get("description", "")))


def open_dataset(path):
    """magnus.open: the Dataset of any file magnus writes: a result (magnus-flow), a sweep or a map
    (magnus-sweep). Raises FileNotFoundError, or ValueError naming the file when it is not one of them."""
    _xr()
    import h5py
    from . import read
    p = os.fspath(path)
    if not os.path.isfile(p):
        raise FileNotFoundError(f"{p}: no such file")
    if not h5py.is_hdf5(p):
        raise ValueError(f"{p}: not an HDF5 file (magnus.open reads magnus result, sweep and map files)")
    with h5py.File(p, "r") as f:
        fmt = _text(f.attrs.get("format", ""))
        if fmt == _SWEEP:
            sweep = _FileSweep(f)
            if "axes" in f:
                axes = f["axes"]
                return map_dataset(sweep, axes["reynolds"][()], axes["alpha"][()],
                                   {"reynolds": _axis_attrs(axes["reynolds"]), "alpha": _axis_attrs(axes["alpha"])})
            return sweep_dataset(sweep)
    if fmt != _FLOW:
        raise ValueError(f"{p}: format '{fmt}' is not a magnus result, sweep or map file")
    ds = result_dataset(read(p))
    ds.encoding["source"] = p
    return ds
