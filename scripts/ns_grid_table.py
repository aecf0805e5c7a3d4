#!/usr/bin/python3
"""The navier-stokes default grid's error across the (Re, α) plane, and its own error estimate.

For each scene the case is run on the scene's default grid (grid.refine = 1) and on the grid twice as
fine (grid.refine = 2). The reference is the Richardson extrapolation of the two at order 2:
f_ref = f_2 + (f_2 − f_1)/3. The actual error of the default grid is |f_1 − f_ref|/|f_ref|; the estimate
is what the default run states itself (from its companion run on the grid twice as coarse), so the two
come from different grid pairs. Prints a markdown table; --csv FILE keeps the numbers.

--reference-dir DIR takes the reference pair from another family's kept runs instead (DIR holds their
re…_a…_f1.json and _f2.json, e.g. the workdir of this script at an earlier commit, when the default
scheme was another): the converged value is the same solution, so any family's Richardson value judges
the default grid. Scenes without that pair are run as above.

  /usr/bin/python3 scripts/ns_grid_table.py --magnus build/magnus --reynolds 20,40,100,150,200 \
      --spin-ratio 0,1,2,4,6 --jobs 2 --csv study.csv
"""
import argparse
import concurrent.futures as cf
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

CASE = """title = "grid study"
[model]
flow = "navier-stokes"
[cylinder]
radius = 0.5
spin_ratio = {alpha}
[flow]
speed = 1.0
density = 1.0
reynolds = {re}
[time]
end = {end}
"""

QUANTITIES = [("cl_mean", "cl_mean_rel_estimate"), ("cd_mean", "cd_mean_rel_estimate"),
              ("strouhal", "strouhal_rel_estimate")]


def run(magnus, re, alpha, refine, end, extra, workdir):
    """One run: its --json as a dict, with the wall seconds it took (kept in workdir: a rerun reuses it)."""
    tag = f"re{re:g}_a{alpha:g}_f{refine:g}"
    saved = os.path.join(workdir, tag + ".json")
    if os.path.exists(saved):
        with open(saved) as f:
            return json.load(f)
    case = os.path.join(workdir, tag + ".toml")
    with open(case, "w") as f:
        f.write(CASE.format(alpha=alpha, re=re, end=end))
    cmd = [magnus, "run", case, "-o", os.path.join(workdir, tag + ".h5"), "--json",
           "--set", f"grid.refine={refine}"] + sum((["--set", s] for s in extra), [])
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        return {"error": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "failed", "wall": wall}
    d = json.loads(p.stdout)
    d["wall"] = wall
    with open(saved, "w") as f:
        json.dump(d, f)
    return d


def unwrap(x):
    """A JSON value: plain, or {"value": v, "units": u}."""
    return x.get("value") if isinstance(x, dict) else x


def value(d, key):
    """A force value, or the steady value when the run has no mean (steady: cl, cd)."""
    f = d.get("forces", {})
    v = unwrap(f.get(key))
    if v is None and key in ("cl_mean", "cd_mean"):
        v = unwrap(f.get(key[:2]))
    return v


def kept_pair(reference_dir, re, alpha):
    """The reference family's (f1, f2) runs of a scene from reference_dir, or None."""
    pair = []
    for refine in (1, 2):
        path = os.path.join(reference_dir, f"re{re:g}_a{alpha:g}_f{refine}.json")
        if not os.path.exists(path):
            return None
        with open(path) as f:
            pair.append(json.load(f))
    return pair


def row(magnus, re, alpha, end, extra, workdir, reference_dir=None):
    coarse = run(magnus, re, alpha, 1, end, extra, workdir)
    pair = kept_pair(reference_dir, re, alpha) if reference_dir else None
    # The finer grid solves what the default run found: Newton's steady state on its own (time.mode
    # steady: no eigenvalue search on the large grid), or the march.
    steady = "error" not in coarse and bool(unwrap(coarse.get("timing", {}).get("newton_s")))
    mode = ["time.mode=steady"] if steady and not unwrap(coarse.get("timing", {}).get("march_s")) \
        else ["time.mode=unsteady"]
    ref1, fine = pair if pair else (coarse, run(magnus, re, alpha, 2, end, extra + mode, workdir))
    out = {"re": re, "alpha": alpha, "wall": coarse.get("wall"), "wall_fine": fine.get("wall")}
    if "error" in coarse or "error" in fine or "error" in ref1:
        out["note"] = coarse.get("error") or fine.get("error") or ref1.get("error")
        return out
    p = coarse["parameters"]
    out["grid"] = f'{unwrap(p["n_theta"])} × {unwrap(p["n_r"])}'
    out["status"] = str(unwrap(coarse.get("status", "")))
    errors = coarse.get("errors", {})
    for key, est in QUANTITIES:
        f1, r1, f2 = value(coarse, key), value(ref1, key), value(fine, key)
        # A coefficient that is 0 by symmetry (C_L at α = 0) has no relative error, as in the run's estimate.
        if f1 is None or r1 is None or f2 is None or abs(f2) < 1e-3:
            continue
        ref = f2 + (f2 - r1) / 3.0
        out[key] = f1
        out[key + "_ref"] = ref
        out[key + "_actual"] = abs(f1 - ref) / abs(ref) if ref != 0.0 else None
        out[key + "_estimate"] = unwrap(errors.get(est))
    return out


def pct(x):
    return "—" if x is None else f"{100.0 * x:.2f}%"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--magnus", default="build/magnus")
    ap.add_argument("--reynolds", default="20,40,100,150,200")
    ap.add_argument("--spin-ratio", default="0,1,2,4,6")
    ap.add_argument("--end", type=float, default=300.0, help="time.end, D/U")
    ap.add_argument("--set", action="append", default=[], help="extra --set for every run")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--csv")
    ap.add_argument("--workdir", help="keep each run's JSON here; a rerun reuses them")
    ap.add_argument("--reference-dir", help="take each scene's reference pair (f1, f2) from these kept runs")
    a = ap.parse_args()
    scenes = [(float(r), float(s)) for r in a.reynolds.split(",") for s in a.spin_ratio.split(",")]
    workdir = a.workdir or tempfile.mkdtemp(prefix="magnus-grid-table-")
    os.makedirs(workdir, exist_ok=True)
    with cf.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        rows = list(ex.map(lambda sc: row(a.magnus, sc[0], sc[1], a.end, a.set, workdir, a.reference_dir),
                           scenes))
    print("| Re | α | default grid | C_L: actual (estimate) | C_D: actual (estimate) | St: actual (estimate) "
          "| bracketed | wall (default, 2× finer) |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        if "note" in r:
            print(f'| {r["re"]:g} | {r["alpha"]:g} | — | {r["note"]} | | | | |')
            continue
        cells, ok = [], True
        for key, _ in QUANTITIES:
            act, est = r.get(key + "_actual"), r.get(key + "_estimate")
            cells.append("—" if act is None else f"{pct(act)} ({pct(est)})")
            if act is not None and (est is None or est < act):
                ok = False
        print(f'| {r["re"]:g} | {r["alpha"]:g} | {r["grid"]} | ' + " | ".join(cells) +
              f' | {"yes" if ok else "NO"} | {r["wall"]:.1f} s, {r["wall_fine"]:.1f} s |')
    if a.csv:
        keys = sorted({k for r in rows for k in r})
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
