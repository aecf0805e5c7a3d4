#!/usr/bin/python3
"""Independent BiGlobal (3D, spanwise wavenumber beta) stability of a 2D base flow past a
circular cylinder, primitive variables on a staggered (MAC) log-polar grid.

Coordinates: xi = ln(r/a), theta (CCW from +x), z.  Cells: Nr uniform in xi on [0, ln(R/a)],
Nt uniform in theta.  Unknowns (real form, u_r,u_th,p ~ cos(beta z), w ~ sin(beta z)):
    u  (= u_r)     at radial faces   (xi_f[i] = i h,       theta_c[j] = (j+1/2) k)
    v  (= u_theta) at angular faces  (xi_c[i] = (i+1/2)h,  theta_f[j] = j k)
    w, p           at cell centres   (xi_c[i],             theta_c[j])
plus ghost layers (u at i = Nr+1, v,w at i = -1 and i = Nr, p at i = Nr) whose rows in A are the
boundary conditions (rows of B zero -> infinite eigenvalues, harmless under shift-invert).

Equations (continuous, base (U,V)(r,theta), U_z = 0):
  lam u = -[U u_r + V/r u_th - 2 V v/r + u U_r + v/r U_th] - p_r
          + nu[lap u - u/r^2 - 2/r^2 v_th - beta^2 u]
  lam v = -[U v_r + V/r v_th + V u/r + u V_r + v/r V_th + v U/r] - p_th/r
          + nu[lap v - v/r^2 + 2/r^2 u_th - beta^2 v]
  lam w = -[U w_r + V/r w_th] + beta p + nu[lap w - beta^2 w]
  0     = (1/r)(r u)_r + (1/r) v_th + beta w
with lap f = (1/r^2)(f_xixi + f_thth) (2D part).
Second-order central differences; base flow and its derivatives evaluated at each staggered
point from a Fourier (theta) x cubic-spline (xi) interpolant of the stored base.

BCs: r = a: u = v = w = 0 (v, w ghost by quadratic extrapolation through the wall value).
r = R: where the base flows in (U_r < 0 at that point): u = v = w = 0.
       where it flows out: bc='pzero'  : p = 0 on the boundary face, d/dr (u,v,w) = 0
                           bc='dirichlet': u = v = w = 0 there too (sensitivity check only)
"""
import argparse
import sys
import time

import h5py
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla
from scipy.interpolate import CubicSpline


# ----------------------------------------------------------------------------------------
# base flow
class MagnusBase:
    """Fourier (theta) x cubic spline (xi) interpolant of a magnus steady state."""

    def __init__(self, path):
        f = h5py.File(path, "r")
        self.r = f["grid/r"][:]
        self.th = f["grid/theta"][:]
        ur = f["fields/u_r"][:]
        ut = f["fields/u_theta"][:]
        p = f["parameters"].attrs
        self.a = float(p["radius"])
        self.nu = float(p["viscosity"])
        self.U0 = float(p["speed"])
        f.close()
        nr, nt = len(self.r), len(self.th)
        if ur.shape != (nr, nt):
            raise SystemExit("unexpected orientation %s" % (ur.shape,))
        self.xi = np.log(self.r / self.a)
        assert np.allclose(np.diff(self.xi), self.xi[1] - self.xi[0], rtol=1e-9, atol=1e-12)
        assert np.allclose(self.th, 2 * np.pi * np.arange(nt) / nt)
        self.R = self.r[-1]
        self.XI = self.xi[-1]
        self.N = nt
        # Fourier coefficients along theta (Nyquist mode dropped)
        self.C = {
            "U": np.fft.rfft(ur, axis=1) / nt,
            "V": np.fft.rfft(ut, axis=1) / nt,
        }
        self.fields = {"U": ur, "V": ut}

    def eval(self, xi, th):
        """Return dict with U, V, U_xi, U_th, V_xi, V_th on the tensor grid (len(xi), len(th))."""
        N = self.N
        m = np.arange(N // 2)  # drop Nyquist m = N/2
        w = np.where(m == 0, 1.0, 2.0)
        E = w[:, None] * np.exp(1j * m[:, None] * th[None, :])
        out = {}
        for name in ("U", "V"):
            C = self.C[name][:, : N // 2]
            g = np.real(C @ E)  # (nr_base, len(th))
            gt = np.real(C @ (1j * m[:, None] * E))
            s = CubicSpline(self.xi, g, axis=0)
            st = CubicSpline(self.xi, gt, axis=0)
            out[name] = s(xi)
            out[name + "_xi"] = s(xi, 1)
            out[name + "_th"] = st(xi)
        return out


class ZeroBase:
    def __init__(self, a, R):
        self.a, self.R, self.XI = a, R, np.log(R / a)

    def eval(self, xi, th):
        z = np.zeros((len(xi), len(th)))
        return {k: z for k in ("U", "V", "U_xi", "U_th", "V_xi", "V_th")}


class FuncBase:
    """analytic base given as callables of (r, theta) returning U,V,U_r,U_th,V_r,V_th"""

    def __init__(self, a, R, fun):
        self.a, self.R, self.XI, self.fun = a, R, np.log(R / a), fun

    def eval(self, xi, th):
        X, T = np.meshgrid(xi, th, indexing="ij")
        r = self.a * np.exp(X)
        d = self.fun(r, T)
        return {"U": d["U"], "V": d["V"], "U_xi": r * d["U_r"], "U_th": d["U_th"],
                "V_xi": r * d["V_r"], "V_th": d["V_th"]}


# ----------------------------------------------------------------------------------------
class Grid:
    def __init__(self, Nr, Nt, a, XI):
        self.Nr, self.Nt, self.a, self.XI = Nr, Nt, a, XI
        self.h = XI / Nr
        self.k = 2 * np.pi / Nt
        self.xif = np.arange(Nr + 2) * self.h  # faces 0..Nr+1 (Nr+1 ghost)
        self.xic = (np.arange(-1, Nr + 1) + 0.5) * self.h  # centres -1..Nr (ghosts at ends)
        self.thc = (np.arange(Nt) + 0.5) * self.k
        self.thf = np.arange(Nt) * self.k
        n = Nt
        self.nU = (Nr + 2) * n
        self.nV = (Nr + 2) * n
        self.nW = (Nr + 2) * n
        self.nP = (Nr + 1) * n
        self.oU = 0
        self.oV = self.nU
        self.oW = self.oV + self.nV
        self.oP = self.oW + self.nW
        self.n = self.oP + self.nP

    def Iu(self, i, j):
        return self.oU + i * self.Nt + np.mod(j, self.Nt)

    def Iv(self, i, j):
        return self.oV + (i + 1) * self.Nt + np.mod(j, self.Nt)

    def Iw(self, i, j):
        return self.oW + (i + 1) * self.Nt + np.mod(j, self.Nt)

    def Ip(self, i, j):
        return self.oP + i * self.Nt + np.mod(j, self.Nt)


def assemble(grid, base, nu, beta, bc="pzero", wall="quad", bcbase=None, pin=None):
    """bcbase: base flow used only to decide inflow/outflow on r = R (default: base)"""
    g = grid
    Nr, Nt, h, k, a = g.Nr, g.Nt, g.h, g.k, g.a
    rows, cols, vals = [], [], []
    brow = []  # rows with B = 1

    def add(R, C, V):
        R, C, V = np.broadcast_arrays(R, C, V)
        rows.append(R.ravel())
        cols.append(C.ravel())
        vals.append(V.ravel().astype(float))

    def transport(row, Ix, I, J, U, V, r, diag):
        """Centred convection -(U f_r + V f_th / r) and viscosity nu (lap f - beta^2 f) of the field
        indexed by Ix at (I, J), r there; diag: the extra diagonal coefficient (curvature terms)."""
        add(row, Ix(I + 1, J), -U / (2 * r * h))
        add(row, Ix(I - 1, J), +U / (2 * r * h))
        add(row, Ix(I, J + 1), -V / (2 * r * k))
        add(row, Ix(I, J - 1), +V / (2 * r * k))
        c = nu / r**2
        add(row, Ix(I + 1, J), c / h**2)
        add(row, Ix(I - 1, J), c / h**2)
        add(row, Ix(I, J + 1), c / k**2)
        add(row, Ix(I, J - 1), c / k**2)
        add(row, Ix(I, J), -2 * c / h**2 - 2 * c / k**2 - nu * beta**2 + diag)
        return c

    # base on the staggered points
    bu = base.eval(g.xif[: Nr + 1], g.thc)  # u points, faces 0..Nr
    bv = base.eval(g.xic[1: Nr + 1], g.thf)  # v points, cells 0..Nr-1
    bw = base.eval(g.xic[1: Nr + 1], g.thc)  # w/p points
    # outflow masks at r = R
    bb = base if bcbase is None else bcbase
    out_u = bb.eval(np.array([g.XI]), g.thc)["U"][0] > 0  # at theta_c
    out_v = bb.eval(np.array([g.XI]), g.thf)["U"][0] > 0  # at theta_f
    if bc == "dirichlet":
        out_u[:] = False
        out_v[:] = False
    elif bc != "pzero":
        raise ValueError(bc)

    jj = np.arange(Nt)
    # ---------------- u momentum ----------------
    I, J = np.meshgrid(np.arange(1, Nr + 1), jj, indexing="ij")
    keep = (I < Nr) | out_u[J]
    I, J = I[keep], J[keep]
    r = a * np.exp(I * h)
    U = bu["U"][I, J]
    V = bu["V"][I, J]
    Uxi = bu["U_xi"][I, J]
    Uth = bu["U_th"][I, J]
    row = g.Iu(I, J)
    brow.append(row)
    # convection and viscosity (moved to the rhs: minus signs), the curvature term -nu u/r^2, -u U_r
    c = transport(row, g.Iu, I, J, U, V, r, -nu / r**2 - Uxi / r)
    cvb = -(Uth - 2 * V) / r  # coefficient on vbar
    for (di, dj) in ((-1, 0), (-1, 1), (0, 0), (0, 1)):
        add(row, g.Iv(I + di, J + dj), 0.25 * cvb)
    # pressure
    add(row, g.Ip(I, J), -1.0 / (r * h))
    add(row, g.Ip(I - 1, J), +1.0 / (r * h))
    # -2 nu/r^2 d(v)/dtheta
    for di in (-1, 0):
        add(row, g.Iv(I + di, J + 1), -2 * c / (2 * k))
        add(row, g.Iv(I + di, J), +2 * c / (2 * k))
    # u Dirichlet rows: wall, inflow at R, ghost Nr+1
    add(g.Iu(0, jj), g.Iu(0, jj), 1.0)
    jin = jj[~out_u]
    jout = jj[out_u]
    add(g.Iu(Nr, jin), g.Iu(Nr, jin), 1.0)
    add(g.Iu(Nr + 1, jin), g.Iu(Nr + 1, jin), 1.0)
    add(g.Iu(Nr + 1, jout), g.Iu(Nr + 1, jout), 1.0)
    add(g.Iu(Nr + 1, jout), g.Iu(Nr - 1, jout), -1.0)

    # ---------------- v momentum ----------------
    I, J = np.meshgrid(np.arange(Nr), jj, indexing="ij")
    I, J = I.ravel(), J.ravel()
    r = a * np.exp((I + 0.5) * h)
    U = bv["U"][I, J]
    V = bv["V"][I, J]
    Vxi = bv["V_xi"][I, J]
    Vth = bv["V_th"][I, J]
    row = g.Iv(I, J)
    brow.append(row)
    c = transport(row, g.Iv, I, J, U, V, r, -nu / r**2 - (Vth + U) / r)
    cub = -(V + Vxi) / r
    for (di, dj) in ((0, -1), (0, 0), (1, -1), (1, 0)):
        add(row, g.Iu(I + di, J + dj), 0.25 * cub)
    add(row, g.Ip(I, J), -1.0 / (r * k))
    add(row, g.Ip(I, J - 1), +1.0 / (r * k))
    for di in (0, 1):
        add(row, g.Iu(I + di, J), +2 * c / (2 * k))
        add(row, g.Iu(I + di, J - 1), -2 * c / (2 * k))

    # ---------------- w momentum ----------------
    I, J = np.meshgrid(np.arange(Nr), jj, indexing="ij")
    I, J = I.ravel(), J.ravel()
    r = a * np.exp((I + 0.5) * h)
    U = bw["U"][I, J]
    V = bw["V"][I, J]
    row = g.Iw(I, J)
    brow.append(row)
    transport(row, g.Iw, I, J, U, V, r, 0.0)
    add(row, g.Ip(I, J), beta)

    # ---------------- ghost rows for v, w ----------------
    for Ix, mask_out in ((g.Iv, out_v), (g.Iw, out_u)):
        # wall
        if wall == "quad":  # f(-1) = -2 f(0) + f(1)/3  (f = 0 at the wall, quadratic)
            add(Ix(-1, jj), Ix(-1, jj), 3.0)
            add(Ix(-1, jj), Ix(0, jj), 6.0)
            add(Ix(-1, jj), Ix(1, jj), -1.0)
        else:  # linear: f(-1) = -f(0)
            add(Ix(-1, jj), Ix(-1, jj), 1.0)
            add(Ix(-1, jj), Ix(0, jj), 1.0)
        ji = jj[~mask_out]
        jo = jj[mask_out]
        # inflow: zero at r = R
        if wall == "quad":
            add(Ix(Nr, ji), Ix(Nr, ji), 3.0)
            add(Ix(Nr, ji), Ix(Nr - 1, ji), 6.0)
            add(Ix(Nr, ji), Ix(Nr - 2, ji), -1.0)
        else:
            add(Ix(Nr, ji), Ix(Nr, ji), 1.0)
            add(Ix(Nr, ji), Ix(Nr - 1, ji), 1.0)
        # outflow: zero normal derivative
        add(Ix(Nr, jo), Ix(Nr, jo), 1.0)
        add(Ix(Nr, jo), Ix(Nr - 1, jo), -1.0)

    # ---------------- continuity ----------------
    I, J = np.meshgrid(np.arange(Nr), jj, indexing="ij")
    I, J = I.ravel(), J.ravel()
    rc = a * np.exp((I + 0.5) * h)
    rf0 = a * np.exp(I * h)
    rf1 = a * np.exp((I + 1) * h)
    row = g.Ip(I, J)
    if pin is None:  # closed box: p defined up to a constant (not needed in the p-odd subspace)
        pin = (bc == "dirichlet") and beta == 0.0
    if pin:  # replace the (redundant) continuity equation of cell (0,0) by p(0,0) = 0
        m = (I == 0) & (J == 0)
        add(g.Ip(0, 0), g.Ip(0, 0), 1.0)
        I, J, rc, rf0, rf1 = I[~m], J[~m], rc[~m], rf0[~m], rf1[~m]
        row = g.Ip(I, J)
    add(row, g.Iu(I + 1, J), rf1 / (rc**2 * h))
    add(row, g.Iu(I, J), -rf0 / (rc**2 * h))
    add(row, g.Iv(I, J + 1), 1.0 / (rc * k))
    add(row, g.Iv(I, J), -1.0 / (rc * k))
    add(row, g.Iw(I, J), beta)
    # pressure ghost at r = R: p_face = 0 at outflow (mean of p[Nr-1], p[Nr]); unused at inflow
    add(g.Ip(Nr, jout), g.Ip(Nr, jout), 1.0)
    add(g.Ip(Nr, jout), g.Ip(Nr - 1, jout), 1.0)
    add(g.Ip(Nr, jin), g.Ip(Nr, jin), 1.0)

    A = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                      shape=(g.n, g.n))
    A.sum_duplicates()
    bd = np.zeros(g.n)
    bd[np.concatenate(brow)] = 1.0
    B = sp.diags(bd).tocsr()
    info = {"out_u": out_u, "out_v": out_v, "brows": np.concatenate(brow)}
    return A, B, info


def symmetry_basis(g, s=-1):
    """Mirror symmetry theta -> -theta of the exactly symmetric base: subspace with
    u_r, w, p of parity s and u_theta of parity -s (s = -1: the von Karman / wake mode,
    u_r odd).  Returns (P, rows): full q = P q_half; keep rows 'rows' of A."""
    Nr, Nt = g.Nr, g.Nt
    assert Nt % 2 == 0
    cols_f, cols_m, vals, rows = [], [], [], []
    m = 0
    blocks = ((g.Iu, np.arange(Nr + 2), "c", s), (g.Iv, np.arange(-1, Nr + 1), "f", -s),
              (g.Iw, np.arange(-1, Nr + 1), "c", s), (g.Ip, np.arange(Nr + 1), "c", s))
    for Ix, irange, loc, par in blocks:
        for i in irange:
            if loc == "c":
                js = np.arange(Nt // 2)
                jm = Nt - 1 - js
            else:
                js = np.arange(Nt // 2 + 1)
                jm = np.mod(Nt - js, Nt)
                if par < 0:  # odd at the fixed points theta = 0, pi: zero, drop
                    js = js[1:-1]
                    jm = jm[1:-1]
            idx = m + np.arange(len(js))
            f1 = Ix(i, js)
            f2 = Ix(i, jm)
            self_ = f1 == f2
            cols_f += [f1, f2[~self_]]
            cols_m += [idx, idx[~self_]]
            vals += [np.ones(len(js)), par * np.ones(np.count_nonzero(~self_))]
            rows.append(f1)
            m += len(js)
    P = sp.csr_matrix((np.concatenate(vals), (np.concatenate(cols_f), np.concatenate(cols_m))),
                      shape=(g.n, m))
    return P, np.concatenate(rows)


def reduce(A, B, P, rows):
    Ah = (A[rows] @ P).tocsr()
    Bh = (B[rows] @ P).tocsr()
    return Ah, Bh


def check_square(A, g):
    """every row must be present exactly once (structural sanity)"""
    nz = np.diff(A.indptr)
    return np.count_nonzero(nz == 0)


def shift_invert(A, B, sigma, k=8, ncv=None, tol=1e-10, v0=None, permc="COLAMD"):
    t0 = time.time()
    M = (A - sigma * B).tocsc().astype(complex)
    lu = sla.splu(M, permc_spec=permc, options=dict(SymmetricMode=False))
    t1 = time.time()
    Bc = B.tocsr()
    op = sla.LinearOperator(M.shape, matvec=lambda x: lu.solve(Bc @ x), dtype=complex)
    mu, X = sla.eigs(op, k=k, which="LM", ncv=ncv or max(2 * k + 1, 30), tol=tol, v0=v0)
    t2 = time.time()
    lam = sigma + 1.0 / mu
    o = np.argsort(np.abs(lam - sigma))
    return lam[o], X[:, o], (t1 - t0, t2 - t1, lu.L.nnz + lu.U.nnz)


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--base", required=True)
    ap.add_argument("--Nr", type=int, default=64)
    ap.add_argument("--Nt", type=int, default=64)
    ap.add_argument("--beta", type=float, nargs="+", default=[0.0])
    ap.add_argument("--sigma", type=complex, default=0.05 + 0.7j)
    ap.add_argument("--k", type=int, default=8)
    ap.add_argument("--bc", default="pzero")
    ap.add_argument("--wall", default="quad")
    ap.add_argument("--nobase", action="store_true")
    ap.add_argument("--R", type=float, default=None, help="outer radius [m] of own grid (default: base's)")
    args = ap.parse_args(argv)

    mb = MagnusBase(args.base)
    nu = mb.nu
    base = ZeroBase(mb.a, mb.R) if args.nobase else mb
    g = Grid(args.Nr, args.Nt, mb.a, mb.XI)
    print("base %s (N=%d, n_r=%d) nu=%.6g a=%g R=%g; own grid Nr=%d Nt=%d h=%.4f k=%.4f bc=%s wall=%s"
          % (args.base, mb.N, len(mb.r), nu, mb.a, mb.R, args.Nr, args.Nt, g.h, g.k, args.bc, args.wall))
    for beta in args.beta:
        A, B, info = assemble(g, base, nu, beta, bc=args.bc, wall=args.wall, bcbase=mb)
        assert check_square(A, g) == 0
        lam, X, (tf, te, nnz) = shift_invert(A, B, args.sigma, k=args.k)
        # residuals
        for n in range(len(lam)):
            q = X[:, n]
            res = A @ q - lam[n] * (B @ q)
            vel = np.abs(q[: g.oP]).max()
            cont = np.abs(res[g.oP: g.oP + g.Nr * g.Nt]).max()
            lam[n]  # noqa
            print("  beta*D=%.3f  lam = %+.6f %+.6fi   |res|/|q|=%.1e  |div|/|u|max=%.1e"
                  % (beta * 2 * mb.a, lam[n].real, lam[n].imag,
                     np.linalg.norm(res) / np.linalg.norm(q), cont / vel))
        print("  (n=%d, LU %.1fs nnz(L+U)=%.2e, eigs %.1fs)" % (g.n, tf, nnz, te))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
