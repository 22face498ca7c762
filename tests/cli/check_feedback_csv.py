#!/usr/bin/python3
"""Sanity checks of a `runin feedback` output directory (stdlib only).

usage: check_feedback_csv.py DIR --t-end T --r0 R0 --r-star RS --mu-final MU [--sweep N] [--png]
R starts at R0 and moves monotonically towards R* (never crossing it), wear grows, the
last R is within 1e-5 of R* and the last mu within 1e-8 (relative) of MU.
"""
import argparse
import csv
import math
import os
import sys

from output_checks import close, finish, leftover_problems, png_problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir")
    parser.add_argument("--t-end", type=float, required=True)
    parser.add_argument("--r0", type=float, required=True)
    parser.add_argument("--r-star", type=float, required=True)
    parser.add_argument("--mu-final", type=float, required=True)
    parser.add_argument("--sweep", type=int, help="expected number of rows in feedback_sweep.csv")
    parser.add_argument("--png", action="store_true", help="require feedback.png (and feedback_sweep.png)")
    args = parser.parse_args()

    problems = []
    with open(os.path.join(args.dir, "feedback.csv"), newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        if header != ["t", "R", "mu", "k", "wear"]:
            sys.exit(f"header {header}")
        rows = [[float(x) for x in row] for row in reader]
    t, R, mu, k, wear = zip(*rows)
    if len(rows) < 100:
        problems.append(f"only {len(rows)} rows")
    if not all(math.isfinite(x) for r in rows for x in r):
        problems.append("non-finite values")
    if t[0] != 0.0 or not close(t[-1], args.t_end, 1e-12) or any(b <= a for a, b in zip(t, t[1:])):
        problems.append(f"time grid {t[0]}..{t[-1]} not increasing 0..{args.t_end}")
    if R[0] != args.r0:
        problems.append(f"R(0) = {R[0]} != {args.r0}")
    side = 1.0 if args.r0 > args.r_star else -1.0
    if any(side * (b - a) > 1e-12 * args.r_star for a, b in zip(R, R[1:])):
        problems.append("R not monotone towards R*")
    if any(side * (r - args.r_star) < -1e-9 * args.r_star for r in R):
        problems.append("R crosses R*")
    if not close(R[-1], args.r_star, 1e-5):
        problems.append(f"final R {R[-1]} != R* {args.r_star}")
    if not close(mu[-1], args.mu_final, 1e-8):
        problems.append(f"final mu {mu[-1]!r} != {args.mu_final}")
    if wear[0] != 0.0 or any(b <= a for a, b in zip(wear, wear[1:])):
        problems.append("wear does not start at 0 and grow")
    if any(kk <= 0 for kk in k):
        problems.append("non-positive wear rate")
    if args.sweep is not None:
        with open(os.path.join(args.dir, "feedback_sweep.csv"), newline="") as f:
            sweep = list(csv.reader(f))
        if sweep[0][1:] != ["R_star", "mu_R_star", "k_R_star", "time_to_1pct", "time_to_1pct_exact"]:
            problems.append(f"sweep header {sweep[0]}")
        if len(sweep) - 1 != args.sweep:
            problems.append(f"sweep has {len(sweep) - 1} rows, expected {args.sweep}")
        for row in sweep[1:]:
            measured, exact = float(row[4]), float(row[5])
            if not (exact - 1e-9 <= measured <= exact + (t[1] - t[0]) + 1e-9):
                problems.append(f"sweep time to 1% {measured} vs closed form {exact}")
    if os.path.exists(os.path.join(args.dir, "feedback_sweep_curves.csv")):
        problems.append("plot scratch file feedback_sweep_curves.csv left behind")
    if args.png:
        names = ["feedback.png"] + (["feedback_sweep.png"] if args.sweep is not None else [])
        problems += png_problems(args.dir, names)
    problems += leftover_problems(args.dir)
    finish("check_feedback_csv", problems, "ok" if not problems else "failed")


if __name__ == "__main__":
    main()
