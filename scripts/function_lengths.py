#!/usr/bin/env python3
"""The size limits of the house: list each source file over 400 lines and each function body over 80
lines in the given folders (default: every layer outside tests/). A brace-matching scan, not a parser:
a function is a brace block at namespace depth whose opening line (or the three before it) holds ')'.
Usage: python3 scripts/function_lengths.py [folder ...]   (run from the repository root)
Today it lists nothing."""
import sys, os, re
N = 80
roots = sys.argv[1:] or ['physics','mesh','solver','postproc','io','plot','app','python','base']
def funcs(path):
    lines = open(path, encoding='utf-8', errors='replace').read().split('\n')
    depth = 0; start = None; out = []; head = ''
    for i, l in enumerate(lines):
        code = re.sub(r'"(\\.|[^"\\])*"', '""', l)
        code = re.sub(r"'(\\.|[^'\\])*'", "''", code)
        code = code.split('//')[0]
        for ch in code:
            if ch == '{':
                if depth_fn_start(depth, lines, i) and start is None:
                    start = (i, depth)
                depth += 1
            elif ch == '}':
                depth -= 1
                if start is not None and depth == start[1]:
                    n = i - start[0] + 1
                    if n > N: out.append((n, start[0] + 1, lines[start[0]].strip()[:70]))
                    start = None
    return out
def depth_fn_start(depth, lines, i):
    # a function body opens at namespace depth (0..2) when the line (or previous) has ')' before '{'
    txt = ' '.join(lines[max(0, i-3):i+1])
    if re.search(r'\b(namespace|struct|class|enum|union)\b[^;{]*\{?\s*$', lines[i]) : return False
    if re.search(r'=\s*\{\s*$', lines[i]): return False
    return ')' in txt and depth <= 2
for r in roots:
    for dp, dn, fn in os.walk(r):
        for f in sorted(fn):
            if not f.endswith(('.cpp', '.hpp')): continue
            p = os.path.join(dp, f)
            n = sum(1 for _ in open(p, encoding='utf-8', errors='replace'))
            if n > 400: print(f'FILE {n:5d} {p}')
            for n, ln, h in funcs(p): print(f'FUNC {n:5d} {p}:{ln} {h}')
