#!/usr/bin/python3
"""Tables from results.jsonl (tag 'conv'): leading pair per base / own grid / beta, shifts,
Richardson extrapolation in the own grid (second order, two finest grids) and observed order."""
import json
import sys
from collections import defaultdict

import numpy as np

fn = sys.argv[1] if len(sys.argv) > 1 else "results.jsonl"
tag = sys.argv[2] if len(sys.argv) > 2 else "conv"
magnus = {  # lambda D/U from the brief
    (64, 0.0): 0.040048 + 0.699150j, (96, 0.0): 0.044312 + 0.725038j, (128, 0.0): 0.0445,
    (64, 0.5): -0.00512, (96, 0.5): 0.00352, (128, 0.5): 0.00664,
}
D = defaultdict(dict)
for line in open(fn):
    d = json.loads(line)
    if d.get("tag") != tag:
        continue
    D[(d["N_base"], d["Nr"], d["Nt"])][round(d["betaD"], 4)] = complex(*d["lam"])


def fmt(z):
    return "%+.5f %+.5fi" % (z.real, z.imag)


print("%-5s %-9s %-22s %-22s %-22s %-10s %-10s" % ("base", "own grid", "beta*D=0", "beta*D=0.5", "beta*D=1.0",
                                                    "shift0.5", "shift1.0"))
for key in sorted(D):
    r = D[key]
    l0, l5, l1 = r.get(0.0), r.get(0.5), r.get(1.0)
    s5 = (l5 - l0).real if (l0 is not None and l5 is not None) else None
    s1 = (l1 - l0).real if (l0 is not None and l1 is not None) else None
    print("%-5d %-9s %-22s %-22s %-22s %-10s %-10s" % (
        key[0], "%dx%d" % key[1:], fmt(l0) if l0 is not None else "-", fmt(l5) if l5 is not None else "-",
        fmt(l1) if l1 is not None else "-", "%+.5f" % s5 if s5 is not None else "-",
        "%+.5f" % s1 if s1 is not None else "-"))

print("\nRichardson in own grid (Nr = Nt = G, h ~ 1/G, order 2, two finest square grids); observed order p from 3 finest")
for N in sorted({k[0] for k in D}):
    sq = sorted([k for k in D if k[0] == N and k[1] == k[2]], key=lambda k: k[1])
    for b in (0.0, 0.5, 1.0):
        pts = [(k[1], D[k][b]) for k in sq if b in D[k]]
        if len(pts) < 2:
            continue
        (g1, z1), (g2, z2) = pts[-2], pts[-1]
        rr = (g2 / g1) ** 2
        ext = z2 + (z2 - z1) / (rr - 1)
        msg = "  base %3d beta*D=%.1f  grids %s  extrap %s" % (N, b, [p[0] for p in pts], fmt(ext))
        if len(pts) >= 3:
            (g0, z0) = pts[-3]
            # observed order for real part, assuming grids ratio not constant: solve numerically
            e1, e2 = (z1 - z0).real, (z2 - z1).real
            f = lambda p: (g0 ** -p - g1 ** -p) / (g1 ** -p - g2 ** -p) - e1 / e2
            ps = np.linspace(0.3, 4, 3701)
            v = np.array([f(p) for p in ps])
            i = np.where(np.sign(v[:-1]) != np.sign(v[1:]))[0]
            msg += "  p_obs(Re)=%s" % ("%.2f" % ps[i[0]] if len(i) else "n/a")
        if (N, b) in magnus:
            msg += "   magnus %s" % fmt(magnus[(N, b)])
        print(msg)
    # shift
    pts = [(k[1], (D[k][0.5] - D[k][0.0]).real) for k in sq if 0.5 in D[k] and 0.0 in D[k]]
    if len(pts) >= 2:
        (g1, s1), (g2, s2) = pts[-2], pts[-1]
        ext = s2 + (s2 - s1) / ((g2 / g1) ** 2 - 1)
        ms = (magnus[(N, 0.5)] - magnus[(N, 0.0)]).real
        print("  base %3d shift(0.5) own grids %s -> %s ; extrap %+.5f ; magnus %+.5f"
              % (N, [p[0] for p in pts], " ".join("%+.5f" % p[1] for p in pts), ext, ms))
