#!/usr/bin/python3
"""Sanity checks of a `runin pin-on-disk` output directory (stdlib only).

usage: check_pin_on_disk_csv.py DIR --t-end T [--breakaway T_B] [--final-speed V]
                                [--final-mu-law MU] [--png]
"""
import argparse
import csv
import math
import os
import sys

COLUMNS = ["t_s", "applied_torque_N_m", "friction_force_N", "friction_torque_N_m", "mu",
           "speed_m_s", "sliding_distance_m", "state_slip", "mu_law"]


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir")
    parser.add_argument("--t-end", type=float, required=True)
    parser.add_argument("--breakaway", type=float, help="expected break-away time (rel 1e-6)")
    parser.add_argument("--final-speed", type=float, help="expected final speed (rel 1e-3)")
    parser.add_argument("--final-mu-law", type=float, help="expected final law mu (abs 0.01)")
    parser.add_argument("--png", action="store_true", help="require pin_on_disk.png")
    args = parser.parse_args()

    problems = []
    with open(os.path.join(args.dir, "pin_on_disk.csv"), newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        if header != COLUMNS:
            sys.exit(f"header {header} != {COLUMNS}")
        rows = [[float(x) for x in row] for row in reader]
    t = [r[0] for r in rows]
    if len(rows) < 100:
        problems.append(f"only {len(rows)} rows")
    if t[0] != 0.0 or not close(t[-1], args.t_end, 1e-12):
        problems.append(f"time runs {t[0]}..{t[-1]}, expected 0..{args.t_end}")
    if any(b < a for a, b in zip(t, t[1:])):
        problems.append("time decreases")
    if not all(math.isfinite(x) for r in rows for x in r):
        problems.append("non-finite values")
    for r in rows:
        if r[7] == 0 and (r[5] != 0 or not close(r[3], r[1], 1e-9)):
            problems.append(f"stick row at t={r[0]} has speed {r[5]} or T_f {r[3]} != T_app {r[1]}")
            break
    slip_starts = [rows[i + 1][0] for i in range(len(rows) - 1) if rows[i][7] == 0 and rows[i + 1][7] == 1]
    if args.breakaway is not None:
        if not slip_starts or not close(slip_starts[0], args.breakaway, 1e-6):
            problems.append(f"break-away at {slip_starts[:1]}, expected {args.breakaway}")
    if args.final_speed is not None and not close(rows[-1][5], args.final_speed, 1e-3):
        problems.append(f"final speed {rows[-1][5]}, expected {args.final_speed}")
    if args.final_mu_law is not None and abs(rows[-1][8] - args.final_mu_law) > 0.01:
        problems.append(f"final law mu {rows[-1][8]}, expected {args.final_mu_law}")
    distance = [r[6] for r in rows]
    if any(b < a - 1e-15 for a, b in zip(distance, distance[1:])):
        problems.append("sliding distance decreases")
    if args.png:
        with open(os.path.join(args.dir, "pin_on_disk.png"), "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                problems.append("pin_on_disk.png is not a PNG")
    leftovers = [n for n in os.listdir(args.dir) if n.startswith(".")]
    if leftovers:
        problems.append(f"temporary files left: {leftovers}")
    for p in problems:
        print("check_pin_on_disk_csv:", p, file=sys.stderr)
    print(f"checked {len(rows)} rows, break-away at {slip_starts[:1]}, final speed {rows[-1][5]}")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
