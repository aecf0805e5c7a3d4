#!/bin/sh
# Sensitivity checks (outflow BC, wall ghost, outer radius, grid anisotropy). Results -> sens.jsonl
# Run in the directory holding base_64.h5, base_96.h5, base_128.h5 (see README.md).
D="$(cd "$(dirname "$0")" && pwd)"
PY=/usr/bin/python3
B="0 0.25 0.5"
$PY $D/study.py --base base_96.h5 --Nr 144 --Nt 144 --betas $B --sym -1 --out sens.jsonl --tag dirichlet --bc dirichlet --k 10
$PY $D/study.py --base base_96.h5 --Nr 144 --Nt 144 --betas $B --sym -1 --out sens.jsonl --tag wall_linear --wall linear
$PY $D/study.py --base base_96.h5 --Nr 133 --Nt 144 --betas $B --sym -1 --out sens.jsonl --tag R15 --R 15
$PY $D/study.py --base base_96.h5 --Nr 117 --Nt 144 --betas $B --sym -1 --out sens.jsonl --tag R10 --R 10
$PY $D/study.py --base base_96.h5 --Nr 117 --Nt 144 --betas $B --sym -1 --out sens.jsonl --tag R10dir --R 10 --bc dirichlet --k 10
$PY $D/study.py --base base_128.h5 --Nr 128 --Nt 256 --betas $B --sym -1 --out sens.jsonl --tag aniso
$PY $D/study.py --base base_128.h5 --Nr 256 --Nt 128 --betas $B --sym -1 --out sens.jsonl --tag aniso
B1="0 0.25 0.5 0.625 0.75 0.875 1.0"
$PY $D/study.py --base base_96.h5 --Nr 133 --Nt 144 --betas $B1 --sym -1 --out sens.jsonl --tag R15b1 --R 15
$PY $D/study.py --base base_96.h5 --Nr 117 --Nt 144 --betas $B1 --sym -1 --out sens.jsonl --tag R10b1 --R 10
