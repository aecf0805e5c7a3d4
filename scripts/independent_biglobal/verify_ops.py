#!/usr/bin/python3
"""Verification of bg.py:
 (1) the polar (cylindrical) linearised equations used in bg.py are checked symbolically
     against the Cartesian linearised NS (chain rule only, no vector-calculus curvature terms);
 (2) method of manufactured fields: the discrete operator rows of bg.assemble applied to sampled
     analytic fields converge at second order to the Cartesian-derived exact result.
"""
import numpy as np
import sympy as s

import bg

r, t, beta, nu = s.symbols("r theta beta nu", positive=True)
a = 0.5
R = 20.0
# analytic base and perturbation (arbitrary smooth functions)
Ub = s.cos(t) * (1 - a**2 / r**2) + s.sin(2 * t) * s.exp(-r / 3) * (r - a) ** 2 / r
Vb = -s.sin(t) * (1 + a**2 / r**2) + s.cos(3 * t) * s.exp(-r / 4) * (r - a)
ur = s.sin(r / 2) * s.cos(2 * t) + s.cos(t) / r
ut = s.cos(r / 3) * s.sin(t) + s.sin(3 * t) * s.exp(-r / 5)
w = s.exp(-r / 6) * s.cos(t + 0.3) * r
p = s.sin(r / 4 + t) + s.cos(2 * t) / r

C, S = s.cos(t), s.sin(t)


def dx(f):
    return C * s.diff(f, r) - S / r * s.diff(f, t)


def dy(f):
    return S * s.diff(f, r) + C / r * s.diff(f, t)


# Cartesian components
UX, UY = Ub * C - Vb * S, Ub * S + Vb * C
ux, uy = ur * C - ut * S, ur * S + ut * C


def lap(f):  # 2D Cartesian laplacian minus beta^2
    return dx(dx(f)) + dy(dy(f)) - beta**2 * f


# real form: ux,uy,p ~ cos(beta z), w ~ sin(beta z); d/dz(cos) = -beta sin, d/dz(sin) = beta cos
Fx = -(UX * dx(ux) + UY * dy(ux)) - (ux * dx(UX) + uy * dy(UX)) - dx(p) + nu * lap(ux)
Fy = -(UX * dx(uy) + UY * dy(uy)) - (ux * dx(UY) + uy * dy(UY)) - dy(p) + nu * lap(uy)
Fz = -(UX * dx(w) + UY * dy(w)) + beta * p + nu * lap(w)  # -(d/dz)(p cos) = beta p sin
Div = dx(ux) + dy(uy) + beta * w
Fr = Fx * C + Fy * S
Ft = -Fx * S + Fy * C

# the polar forms used in bg.py
Dr = lambda f: s.diff(f, r)
Dt = lambda f: s.diff(f, t)
lp = lambda f: s.diff(r * Dr(f), r) / r + Dt(Dt(f)) / r**2 - beta**2 * f
Pr = (-(Ub * Dr(ur) + Vb / r * Dt(ur) - 2 * Vb * ut / r + ur * Dr(Ub) + ut / r * Dt(Ub)) - Dr(p)
      + nu * (lp(ur) - ur / r**2 - 2 / r**2 * Dt(ut)))
Pt = (-(Ub * Dr(ut) + Vb / r * Dt(ut) + Vb * ur / r + ur * Dr(Vb) + ut / r * Dt(Vb) + ut * Ub / r)
      - Dt(p) / r + nu * (lp(ut) - ut / r**2 + 2 / r**2 * Dt(ur)))
Pz = -(Ub * Dr(w) + Vb / r * Dt(w)) + beta * p + nu * lp(w)
Pd = s.diff(r * ur, r) / r + Dt(ut) / r + beta * w

rng = np.random.default_rng(1)
vals = {beta: 0.7, nu: 1 / 60.0}
print("(1) polar equations vs Cartesian (max abs difference at 20 random points):")
for name, E1, E2 in (("r", Fr, Pr), ("theta", Ft, Pt), ("z", Fz, Pz), ("div", Div, Pd)):
    f1 = s.lambdify((r, t), E1.subs(vals), "numpy")
    f2 = s.lambdify((r, t), E2.subs(vals), "numpy")
    rr = rng.uniform(0.5, 5, 20)
    tt = rng.uniform(0, 2 * np.pi, 20)
    d = np.abs(f1(rr, tt) - f2(rr, tt)).max()
    print("   %-6s %.2e   (scale %.2e)" % (name, d, np.abs(f1(rr, tt)).max()))

# ---------------- (2) MMS of the discrete operator ----------------
L = lambda e: s.lambdify((r, t), e.subs(vals) if hasattr(e, "subs") else e, "numpy")
fb = {"U": L(Ub), "V": L(Vb), "U_r": L(s.diff(Ub, r)), "U_th": L(s.diff(Ub, t)),
      "V_r": L(s.diff(Vb, r)), "V_th": L(s.diff(Vb, t))}


def basefun(rr, tt):
    return {k: f(rr, tt) * np.ones_like(rr) for k, f in fb.items()}


fu, fv, fw, fp = L(ur), L(ut), L(w), L(p)
eFr, eFt, eFz, eD = L(Fr), L(Ft), L(Fz), L(Div)
base = bg.FuncBase(a, R, basefun)
print("(2) discrete operator vs exact (max abs error over interior rows), beta=0.7, nu=1/60")
prev = None
for N in (32, 64, 128, 256):
    g = bg.Grid(N, N, a, np.log(R / a))
    A, B, info = bg.assemble(g, base, vals[nu], vals[beta], bc="pzero")
    q = np.zeros(g.n)
    ex = np.zeros(g.n)
    Nr, Nt = g.Nr, g.Nt
    # sample u at faces 0..Nr+1
    I, J = np.meshgrid(np.arange(Nr + 2), np.arange(Nt), indexing="ij")
    rr, tt = a * np.exp(I * g.h), g.thc[J]
    q[g.Iu(I, J)] = fu(rr, tt)
    ex[g.Iu(I, J)] = eFr(rr, tt)
    I, J = np.meshgrid(np.arange(-1, Nr + 1), np.arange(Nt), indexing="ij")
    rr = a * np.exp((I + 0.5) * g.h)
    q[g.Iv(I, J)] = fv(rr, g.thf[J])
    ex[g.Iv(I, J)] = eFt(rr, g.thf[J])
    q[g.Iw(I, J)] = fw(rr, g.thc[J])
    ex[g.Iw(I, J)] = eFz(rr, g.thc[J])
    I, J = np.meshgrid(np.arange(Nr + 1), np.arange(Nt), indexing="ij")
    rr = a * np.exp((I + 0.5) * g.h)
    q[g.Ip(I, J)] = fp(rr, g.thc[J])
    ex[g.Ip(I, J)] = eD(rr, g.thc[J])
    Aq = A @ q
    errs = []
    for lo, hi, nm in ((g.oU, g.oV, "u"), (g.oV, g.oW, "v"), (g.oW, g.oP, "w"), (g.oP, g.oP + Nr * Nt, "div")):
        rows = np.arange(lo, hi)
        if nm != "div":
            rows = np.intersect1d(rows, info["brows"])  # momentum rows only
        else:
            rows = rows[rows != g.Ip(0, 0)] if False else rows
        errs.append(np.abs(Aq[rows] - ex[rows]).max())
    msg = "   N=%4d  err u %.3e  v %.3e  w %.3e  div %.3e" % ((N,) + tuple(errs))
    if prev is not None:
        msg += "   order " + " ".join("%.2f" % np.log2(p_ / e_) for p_, e_ in zip(prev, errs))
    print(msg)
    prev = errs
