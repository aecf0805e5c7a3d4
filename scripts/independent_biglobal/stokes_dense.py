#!/usr/bin/python3
"""Sanity: base switched off (U = 0), beta = 0 (and 0.5): full spectrum of a small grid by dense QZ.
All finite eigenvalues should be real and negative (Stokes modes)."""
import sys

import numpy as np, scipy.linalg as la
import bg
mb = bg.MagnusBase(sys.argv[1] if len(sys.argv) > 1 else "base_96.h5")
for beta in (0.0, 0.5):
    for bc in ("pzero", "dirichlet"):
        g = bg.Grid(20, 24, mb.a, mb.XI)
        A, B, _ = bg.assemble(g, bg.ZeroBase(mb.a, mb.R), mb.nu, beta, bc=bc, bcbase=mb)
        w = la.eigvals(A.toarray(), B.toarray())
        w = w[np.isfinite(w) & (np.abs(w) < 1e6)]
        print("beta*D=%.1f bc=%-9s n=%d finite=%d  max Re=%.3e  max|Im|=%.3e  max|Im|/|lam|=%.1e"
              % (beta, bc, g.n, len(w), w.real.max(), np.abs(w.imag).max(), (np.abs(w.imag) / np.abs(w)).max()))
