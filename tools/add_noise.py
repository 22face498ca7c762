#!/usr/bin/python3
"""Multiply columns of a CSV by (1 + relative * N(0, 1)), seeded: a noisy copy of a run to try a fit on.

usage: add_noise.py IN.csv OUT.csv --columns mu,R [--relative 0.01] [--seed 1]

The header and the other columns are copied unchanged; values are written with repr (round trip exact).
Each column draws its own noise, row by row in the order given (numpy's default_rng(seed)).
Uses Debian's numpy: run with /usr/bin/python3.
"""
import argparse
import csv
import sys

import numpy as np


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--columns", required=True, help="comma-separated column names")
    parser.add_argument("--relative", type=float, default=0.01)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    with open(args.input, newline="") as f:
        rows = [row for row in csv.reader(f) if row and not row[0].lstrip().startswith("#")]
    header, data = rows[0], rows[1:]
    names = args.columns.split(",")
    missing = [n for n in names if n not in header]
    if missing:
        sys.exit(f"add_noise.py: {args.input}: no column {missing[0]!r} (columns: {', '.join(header)})")
    index = [header.index(n) for n in names]
    rng = np.random.default_rng(args.seed)
    for row in data:
        for i in index:
            row[i] = repr(float(row[i]) * (1.0 + args.relative * rng.standard_normal()))
    with open(args.output, "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(data)


if __name__ == "__main__":
    main()
