#!/usr/bin/python3
"""Track the wake-mode eigenvalue in beta on one (base, own grid) pair; append results to a
JSON-lines file.  Tracking: shift sigma = extrapolated prediction, pick the Ritz value whose
eigenvector has the largest overlap (u, v components) with the previous beta's eigenvector.

  /usr/bin/python3 study.py --base base_64.h5 --Nr 64 --Nt 64 --betas 0 0.25 0.5 --out results.jsonl
"""
import argparse
import json
import time

import numpy as np

import bg


def diagnostics(g, q):
    Nr, Nt, a, h, k = g.Nr, g.Nt, g.a, g.h, g.k
    I, J = np.meshgrid(np.arange(Nr), np.arange(Nt), indexing="ij")
    rc = a * np.exp((I + 0.5) * h)
    # velocity magnitude at cell centres (averages of faces)
    u = 0.5 * (q[g.Iu(I, J)] + q[g.Iu(I + 1, J)])
    v = 0.5 * (q[g.Iv(I, J)] + q[g.Iv(I, J + 1)])
    w = q[g.Iw(I, J)]
    e = np.abs(u) ** 2 + np.abs(v) ** 2 + np.abs(w) ** 2
    dA = rc**2 * h * k
    x = rc * np.cos(g.thc[J])
    E = (e * dA).sum()
    xc = (x * e * dA).sum() / E
    # fraction of energy in the outer 10% of xi (near r = R)
    fo = (e * dA)[I >= int(0.9 * Nr)].sum() / E
    ew = (np.abs(w) ** 2 * dA).sum() / E
    # symmetry of v about theta=0: v(theta) vs v(-theta); u(theta) vs u(-theta)
    Jm = (Nt - 1 - J)  # theta_c -> -theta_c
    us = np.linalg.norm(q[g.Iu(I, J)] - q[g.Iu(I, Jm)]) / np.linalg.norm(q[g.Iu(I, J)])
    return {"xc": float(xc), "f_outer": float(fo), "f_w": float(ew), "u_sym_defect": float(us)}


def overlap(g, q1, q2):
    # interior u and v values only (ghost layers excluded: with a Dirichlet outflow they can be large)
    I, J = np.meshgrid(np.arange(1, g.Nr), np.arange(g.Nt), indexing="ij")
    I2, J2 = np.meshgrid(np.arange(g.Nr), np.arange(g.Nt), indexing="ij")
    idx = np.concatenate([g.Iu(I, J).ravel(), g.Iv(I2, J2).ravel()])
    a1, a2 = q1[idx], q2[idx]
    return float(np.abs(np.vdot(a1, a2)) / (np.linalg.norm(a1) * np.linalg.norm(a2)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--base", required=True)
    ap.add_argument("--Nr", type=int, required=True)
    ap.add_argument("--Nt", type=int, required=True)
    ap.add_argument("--betas", type=float, nargs="+", default=[0.0, 0.25, 0.5, 0.75, 1.0])
    ap.add_argument("--sigma0", type=complex, default=0.05 + 0.7j)
    ap.add_argument("--k", type=int, default=6)
    ap.add_argument("--bc", default="pzero")
    ap.add_argument("--wall", default="quad")
    ap.add_argument("--out", default="results.jsonl")
    ap.add_argument("--tag", default="")
    ap.add_argument("--R", type=float, default=None, help="outer radius [m] of own grid (default: the base's R)")
    ap.add_argument("--sym", type=int, default=0, help="0: full domain; -1/+1: mirror-symmetry subspace")
    args = ap.parse_args()

    mb = bg.MagnusBase(args.base)
    XI = mb.XI if args.R is None else np.log(args.R / mb.a)
    assert XI <= mb.XI + 1e-12
    g = bg.Grid(args.Nr, args.Nt, mb.a, XI)
    hist = []  # (beta, lam, q)
    for beta in args.betas:
        if len(hist) == 0:
            sigma = args.sigma0
        elif len(hist) == 1:
            sigma = hist[-1][1] - 0.01
        else:
            (b1, l1, _), (b2, l2, _) = hist[-2], hist[-1]
            sigma = l2 + (l2 - l1) * (beta - b2) / (b2 - b1)
        # shift slightly to the right so that the target is not exactly at sigma
        sigma = complex(round(sigma.real + 0.01, 3), round(sigma.imag, 3))
        t0 = time.time()
        A, B, info = bg.assemble(g, mb, mb.nu, beta, bc=args.bc, wall=args.wall,
                                 pin=(False if args.sym == -1 else None))
        if args.sym:
            P, rows = bg.symmetry_basis(g, args.sym)
            Ah, Bh = bg.reduce(A, B, P, rows)
            lam, Xh, (tf, te, nnz) = bg.shift_invert(Ah, Bh, sigma, k=args.k, ncv=max(24, 2 * args.k + 2))
            X = P @ Xh
        else:
            lam, X, (tf, te, nnz) = bg.shift_invert(A, B, sigma, k=args.k, ncv=max(24, 2 * args.k + 2))
        if hist:
            ov = [overlap(g, hist[-1][2], X[:, n]) for n in range(len(lam))]
            n = int(np.argmax(ov))
        else:
            ov = [float("nan")] * len(lam)
            # beta = 0 : the unstable one with largest growth near sigma, positive frequency
            # (exclude w-only modes: at beta = 0 the w equation is a decoupled passive scalar)
            cand = [n for n in range(len(lam)) if lam[n].imag > 0 and diagnostics(g, X[:, n])["f_w"] < 0.5]
            n = max(cand, key=lambda m: lam[m].real)
        q = X[:, n]
        res = A @ q - lam[n] * (B @ q)
        div = np.abs(res[g.oP: g.oP + g.Nr * g.Nt]).max() / np.abs(q[: g.oP]).max()
        d = diagnostics(g, q)
        rec = {"tag": args.tag, "base": args.base, "N_base": mb.N, "Nr": g.Nr, "Nt": g.Nt,
               "bc": args.bc, "wall": args.wall, "sym": args.sym, "R": float(mb.a * np.exp(XI)), "betaD": beta * 2 * mb.a, "sigma": [sigma.real, sigma.imag],
               "lam": [lam[n].real, lam[n].imag], "overlap": ov[n],
               "others": [[l.real, l.imag, o] for l, o in zip(lam, ov)],
               "resid": float(np.linalg.norm(res) / np.linalg.norm(q)), "div_rel": float(div),
               "t_lu": tf, "t_eig": te, "nnzLU": int(nnz), "n": g.n, **d}
        print("N=%d grid %dx%d beta*D=%.3f lam=%+.6f%+.6fi ov=%.3f xc=%.2f f_out=%.1e f_w=%.2f res=%.1e div=%.1e (%.0fs)"
              % (mb.N, g.Nr, g.Nt, beta, lam[n].real, lam[n].imag, ov[n], d["xc"], d["f_outer"], d["f_w"],
                 rec["resid"], div, time.time() - t0), flush=True)
        print("     others: " + "  ".join("%+.4f%+.4fi(%.2f)" % (l.real, l.imag, o) for l, o in zip(lam, ov)),
              flush=True)
        with open(args.out, "a") as f:
            f.write(json.dumps(rec) + "\n")
        hist.append((beta, lam[n], q))


if __name__ == "__main__":
    main()
