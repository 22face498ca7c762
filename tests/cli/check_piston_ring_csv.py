#!/usr/bin/python3
"""Checks of a `runin piston-ring` output directory (stdlib only).

usage: check_piston_ring_csv.py DIR --t-end T --mu-static MU --k-over-h K_H
           [--breakaway T_B] [--sweep N] [--liner-peak-within MM] [--vtk N] [--png]

--k-over-h: Archard factor k/H (1/Pa) of the case; the total wear volume must equal
  k/H * integral W ds along the CSV (trapezoid, rel 2e-3: the CSV is a sampling of the run).
--sweep N: piston_ring_mu0.csv holds N mu0 curves.
--claims PEAK TIME START: thesis claims 2 and 3 on those curves with these relative margins
  (tests/cli/thesis_claims.py: peak, time to equilibrium in a 2 % band, start-up vs steady friction).
"""
import argparse
import os
import sys

from output_checks import finish, leftover_problems, png_problems, read_csv, time_series_problems

COLUMNS = ["t_s", "crank_angle_deg", "piston_position_m", "piston_velocity_m_s", "ring_position_m", "speed_m_s",
           "sliding_distance_m", "friction_force_N", "land_force_N", "normal_load_N", "mu", "mu_law", "state_slip",
           "wear_ring_m3", "wear_liner_m3", "wear_volume_m3", "contact_width_m", "peak_pressure_Pa",
           "mean_pressure_Pa", "roughness"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir")
    parser.add_argument("--t-end", type=float, required=True)
    parser.add_argument("--mu-static", type=float, required=True)
    parser.add_argument("--k-over-h", type=float, required=True)
    parser.add_argument("--breakaway", type=float, help="expected first break-away time (rel 1e-6)")
    parser.add_argument("--sweep", type=int, help="number of mu0 curves")
    parser.add_argument("--claims", type=float, nargs=3, metavar=("PEAK", "TIME", "START"),
                        help="thesis claims 2 and 3 on the sweep curves with these relative margins")
    parser.add_argument("--liner-peak-within", type=float, help="max liner wear within this many mm of TDC")
    parser.add_argument("--vtk", type=int, help="number of VTK frames per surface")
    parser.add_argument("--png", action="store_true")
    args = parser.parse_args()

    problems = []
    rows = read_csv(os.path.join(args.dir, "piston_ring.csv"), COLUMNS)
    col = {name: [r[i] for r in rows] for i, name in enumerate(COLUMNS)}
    problems += time_series_problems(rows, args.t_end)
    for r in rows:
        f, w, slip, speed = r[7], r[9], r[12], r[5]
        if slip == 0 and (speed != 0.0 or abs(f) > args.mu_static * w * (1 + 1e-6)):
            problems.append(f"stick row at t={r[0]}: speed {speed}, |F| {abs(f)} > mu_s W {args.mu_static * w}")
            break
        if abs(abs(f) - r[10] * w) > 1e-9 * max(abs(f), 1.0):
            problems.append(f"row at t={r[0]}: mu {r[10]} != |F|/W")
            break
    if args.breakaway is not None:
        starts = [rows[i + 1][0] for i in range(len(rows) - 1) if rows[i][12] == 0 and rows[i + 1][12] == 1]
        if not starts or abs(starts[0] - args.breakaway) > 1e-6 * args.breakaway:
            problems.append(f"break-away at {starts[:1]}, expected {args.breakaway}")

    # Archard bookkeeping: ring + liner = total, and total = k/H * integral W ds.
    ring, liner, total = col["wear_ring_m3"], col["wear_liner_m3"], col["wear_volume_m3"]
    if any(b < a * (1 - 1e-12) for a, b in zip(total, total[1:])):
        problems.append("wear volume decreases")
    if abs(ring[-1] + liner[-1] - total[-1]) > 1e-9 * total[-1]:
        problems.append(f"ring {ring[-1]} + liner {liner[-1]} != total {total[-1]}")
    x, w = col["ring_position_m"], col["normal_load_N"]
    integral = sum(0.5 * (w[i] + w[i + 1]) * abs(x[i + 1] - x[i]) for i in range(len(x) - 1))
    expected = args.k_over_h * integral
    if not abs(total[-1] - expected) <= 2e-3 * expected:
        problems.append(f"wear volume {total[-1]} != k/H int W ds = {expected}")
    s_total = sum(abs(b - a) for a, b in zip(x, x[1:]))
    if abs(s_total - col["sliding_distance_m"][-1]) > 1e-4 * s_total:
        problems.append(f"sliding distance {col['sliding_distance_m'][-1]} != sum |dx_ring| {s_total}")

    lrows = read_csv(os.path.join(args.dir, "piston_ring_liner.csv"))
    frows = read_csv(os.path.join(args.dir, "piston_ring_face.csv"))
    if args.liner_peak_within is not None:
        peak = max(lrows, key=lambda r: r[2])
        if not peak[1] * 1e3 <= args.liner_peak_within:
            problems.append(f"liner wear peaks {peak[1] * 1e3:.3g} mm from TDC, expected within {args.liner_peak_within}")
    if not all(r[2] >= 0.0 for r in lrows + frows):
        problems.append("negative wear depth")

    if args.sweep is not None:
        srows = read_csv(os.path.join(args.dir, "piston_ring_mu0.csv"))
        curves = {}
        for r in srows:
            curves.setdefault(r[0], []).append(r)
        if len(curves) != args.sweep:
            problems.append(f"{len(curves)} mu0 curves, expected {args.sweep}")
        if args.claims:
            sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
            from thesis_claims import check_claims
            problems += check_claims({mu0: ([r[1] for r in c], [r[2] for r in c], [r[4] for r in c])
                                      for mu0, c in curves.items()}, *args.claims)

    if args.vtk is not None:
        vtk = os.path.join(args.dir, "vtk")
        names = os.listdir(vtk)
        for stem in ("liner", "ring_face"):
            frames = [n for n in names if n.startswith(stem + "_") and n.endswith(".vts")]
            if len(frames) != args.vtk or stem + ".pvd" not in names:
                problems.append(f"vtk: {len(frames)} {stem} frames (expected {args.vtk}) or no {stem}.pvd")
            with open(os.path.join(vtk, stem + ".pvd")) as f:
                if f.read().count("<DataSet") != args.vtk:
                    problems.append(f"vtk: {stem}.pvd does not list {args.vtk} frames")
    if args.png:
        problems += png_problems(args.dir, ["piston_ring.png"] + (["piston_ring_mu0.png"] if args.sweep else []))
    problems += leftover_problems(args.dir)
    finish("check_piston_ring_csv", problems, f"checked {len(rows)} rows; wear {total[-1]:.6g} m^3 vs k/H int W ds {expected:.6g} m^3")


if __name__ == "__main__":
    main()
