#!/bin/sh
# Convergence study: wake mode vs beta on each magnus base, own grids refined. Results -> results.jsonl
# Run in the directory holding base_64.h5, base_96.h5, base_128.h5 (see README.md).
D="$(cd "$(dirname "$0")" && pwd)"
PY=/usr/bin/python3
B="0 0.25 0.5 0.625 0.75 0.875 1.0"
for G in 64 96 128 192 256; do $PY $D/study.py --base base_64.h5  --Nr $G --Nt $G --betas $B --sym -1 --k 6 --out results.jsonl --tag conv; done
for G in 96 144 192 256;    do $PY $D/study.py --base base_96.h5  --Nr $G --Nt $G --betas $B --sym -1 --k 6 --out results.jsonl --tag conv; done
for G in 128 192 256;       do $PY $D/study.py --base base_128.h5 --Nr $G --Nt $G --betas $B --sym -1 --k 6 --out results.jsonl --tag conv; done
