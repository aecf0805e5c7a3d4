#!/usr/bin/python3
"""sweep_files_equal.py A.h5 B.h5: are two magnus sweep files the same map, bit for bit?

Every group, dataset and attribute of either file must be in the other, with the same type, shape and
bytes (so a NaN equals only a NaN of the same bits, and -0.0 differs from 0.0), except what measures the
run rather than the flow: the values of /sweep/seconds (each point's wall time), and the attributes
/timing total_s (the map's wall time) and /timing threads (threads it ran on, summed over the shards
when merged). Their units and descriptions are still compared.
Prints one line; exits 0 when the same, 1 when not (naming the first differences), 2 on bad input.
Used by scripts/slurm_map_test.sh."""
import sys

import numpy as np

try:
    import h5py
except ImportError:
    print("sweep_files_equal: python3-h5py is missing (apt-get install python3-h5py)", file=sys.stderr)
    sys.exit(2)

# Measurements of the run: wall times and the thread count (see the docstring).
SKIP_VALUES = {"/sweep/seconds"}
SKIP_ATTRS = {("/timing", "total_s"), ("/timing", "threads")}


def objects(f):
    """Every group and dataset by path, the root included."""
    found = {"/": f}
    f.visititems(lambda name, obj: found.__setitem__("/" + name, obj))
    return found


def same_value(a, b):
    """Same numpy type, shape and bytes (variable-length strings: same values)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    if a.dtype.kind == "O":
        return a.tolist() == b.tolist()
    return a.tobytes() == b.tobytes()


def differences(fa, fb):
    """(differences, datasets compared, attributes compared) of two open files."""
    oa, ob = objects(fa), objects(fb)
    diffs = [f"{p} only in {'the first' if p in oa else 'the second'}" for p in sorted(set(oa) ^ set(ob))]
    n_data = n_attr = 0
    for path in sorted(set(oa) & set(ob)):
        a, b = oa[path], ob[path]
        if isinstance(a, h5py.Dataset) != isinstance(b, h5py.Dataset):
            diffs.append(f"{path} is a dataset in one file and a group in the other")
            continue
        if isinstance(a, h5py.Dataset) and path not in SKIP_VALUES:
            n_data += 1
            if not same_value(a[()], b[()]):
                diffs.append(f"{path} differs")
        for name in sorted(set(a.attrs) ^ set(b.attrs)):
            diffs.append(f"{path} attribute {name} in one file only")
        for name in sorted(set(a.attrs) & set(b.attrs)):
            if (path, name) in SKIP_ATTRS:
                continue
            n_attr += 1
            if not same_value(a.attrs[name], b.attrs[name]):
                diffs.append(f"{path} attribute {name} differs")
    return diffs, n_data, n_attr


def main():
    if len(sys.argv) != 3:
        print("usage: sweep_files_equal.py A.h5 B.h5", file=sys.stderr)
        return 2
    try:
        with h5py.File(sys.argv[1], "r") as fa, h5py.File(sys.argv[2], "r") as fb:
            diffs, n_data, n_attr = differences(fa, fb)
    except OSError as e:
        print(f"sweep_files_equal: cannot read: {e}", file=sys.stderr)
        return 2
    if diffs:
        more = f" (and {len(diffs) - 5} more)" if len(diffs) > 5 else ""
        print(f"differ: {'; '.join(diffs[:5])}{more}")
        return 1
    skipped = ", ".join(sorted(SKIP_VALUES) + [f"{p} {n}" for p, n in sorted(SKIP_ATTRS)])
    print(f"same: {n_data} datasets and {n_attr} attributes bit for bit (not compared: {skipped})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
