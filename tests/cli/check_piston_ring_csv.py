#!/usr/bin/python3
"""Checks of a `runin piston-ring` output directory (stdlib only).

usage: check_piston_ring_csv.py DIR --t-end T --mu-static MU --k-over-h K_H
           [--breakaway T_B] [--sweep N] [--liner-peak-within MM] [--vtk N] [--png]
           [--rings A B ...] [--land-geometry BORE WIDTH THICKNESS E NU] [--breakaway-closed-form]

--rings: a ring pack. piston_ring.csv holds the pack (friction, land force and W summed over the
  rings; these sums are checked against the per-ring columns) and piston_ring_<X>.csv each ring with
  the one-ring columns; every one-ring check runs on each ring's CSV, the Archard check on the sum.
--land-geometry: recompute each ring's land stiffness (piston_ring_rings.csv) from its groove
  diameter and land width with the plate-strip + ring-shear formula of doc/piston_ring.md (rel 1e-9).
--breakaway-closed-form: each ring's first break-away at t_b = (mu_s W - c v_p) / (k v_p) (rel 1e-6),
  with W and v_p from its CSV and k, c from piston_ring_rings.csv; a start above the static limit
  (t_b <= 0) must break away in the first row.

--k-over-h: Archard factor k/H (1/Pa) of the case; the total wear volume must equal
  k/H * integral W ds along the CSV (trapezoid, rel 2e-3: the CSV is a sampling of the run).
--sweep N: piston_ring_mu0.csv holds N mu0 curves.
--claims PEAK TIME START: thesis claims 2 and 3 on those curves with these relative margins
  (tests/cli/thesis_claims.py: peak, time to equilibrium in a 2 % band, start-up vs steady friction).
"""
import argparse
import math
import os
import re
import sys

from output_checks import close, finish, leftover_problems, png_problems, read_csv, time_series_problems

COLUMNS = ["t_s", "crank_angle_deg", "piston_position_m", "piston_velocity_m_s", "ring_position_m", "speed_m_s",
           "sliding_distance_m", "friction_force_N", "land_force_N", "normal_load_N", "mu", "mu_law", "state_slip",
           "wear_ring_m3", "wear_liner_m3", "wear_volume_m3", "contact_width_m", "peak_pressure_Pa",
           "mean_pressure_Pa", "roughness"]
PACK_COLUMNS = ["t_s", "crank_angle_deg", "piston_position_m", "piston_velocity_m_s", "speed_m_s", "friction_force_N",
                "land_force_N", "normal_load_N", "mu", "state_slip", "wear_ring_m3", "wear_liner_m3", "wear_volume_m3"]
RING_COLUMNS = ["friction_{}_N", "normal_load_{}_N", "state_slip_{}", "ring_position_{}_m", "sliding_distance_{}_m",
                "peak_pressure_{}_Pa"]


def land_stiffness(bore, groove, land, width, thickness, e, nu):
    """Plate strip (bending + Timoshenko shear, uniform flank load) in series with the ring section's shear."""
    g = e / (2.0 * (1.0 + nu))
    length = 0.5 * (bore - groove)
    rigidity = e * land ** 3 / (12.0 * (1.0 - nu * nu))
    k_land = math.pi * 0.5 * (bore + groove) / (length ** 3 / (20.0 * rigidity) + length / (3.0 * 5.0 / 6.0 * g * land))
    k_ring = 2.0 * math.pi * g * width / math.log(bore / (bore - 2.0 * thickness))
    return 1.0 / (1.0 / k_land + 1.0 / k_ring)


def ring_problems(path, args, name=""):
    """The one-ring checks on one ring's CSV; returns (problems, rows, integral of W ds)."""
    problems = []
    rows = read_csv(path, COLUMNS)
    col = {c: [r[i] for r in rows] for i, c in enumerate(COLUMNS)}
    problems += [name + p for p in time_series_problems(rows, args.t_end)]
    for r in rows:
        f, w, slip, speed = r[7], r[9], r[12], r[5]
        if slip == 0 and (speed != 0.0 or abs(f) > args.mu_static * w * (1 + 1e-6)):
            problems.append(f"{name}stick row at t={r[0]}: speed {speed}, |F| {abs(f)} > mu_s W {args.mu_static * w}")
            break
        if abs(abs(f) - r[10] * w) > 1e-9 * max(abs(f), 1.0):
            problems.append(f"{name}row at t={r[0]}: mu {r[10]} != |F|/W")
            break
    ring, liner, total = col["wear_ring_m3"], col["wear_liner_m3"], col["wear_volume_m3"]
    if any(b < a * (1 - 1e-12) for a, b in zip(total, total[1:])):
        problems.append(name + "wear volume decreases")
    if abs(ring[-1] + liner[-1] - total[-1]) > 1e-9 * total[-1]:
        problems.append(f"{name}ring {ring[-1]} + liner {liner[-1]} != total {total[-1]}")
    x, w = col["ring_position_m"], col["normal_load_N"]
    integral = sum(0.5 * (w[i] + w[i + 1]) * abs(x[i + 1] - x[i]) for i in range(len(x) - 1))
    expected = args.k_over_h * integral
    if not abs(total[-1] - expected) <= 2e-3 * expected:
        problems.append(f"{name}wear volume {total[-1]} != k/H int W ds = {expected}")
    s_total = sum(abs(b - a) for a, b in zip(x, x[1:]))
    if abs(s_total - col["sliding_distance_m"][-1]) > 1e-4 * s_total:
        problems.append(f"{name}sliding distance {col['sliding_distance_m'][-1]} != sum |dx_ring| {s_total}")
    return problems, rows, integral


def first_breakaway(rows):
    starts = [rows[i + 1][0] for i in range(len(rows) - 1) if rows[i][12] == 0 and rows[i + 1][12] == 1]
    if rows and rows[0][12] == 1:
        return 0.0
    return starts[0] if starts else None


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
    parser.add_argument("--rings", nargs="+", help="ring names of a pack (piston_ring_<X>.csv)")
    parser.add_argument("--land-geometry", type=float, nargs=5, metavar=("BORE", "WIDTH", "THICKNESS", "E", "NU"))
    parser.add_argument("--breakaway-closed-form", action="store_true")
    args = parser.parse_args()

    problems = []
    if not args.rings:
        problems, rows, integral = ring_problems(os.path.join(args.dir, "piston_ring.csv"), args)
        total = [r[15] for r in rows]
        expected = args.k_over_h * integral
        ring_rows = {"": rows}
    else:
        # The pack: per-ring files with the one-ring checks, the sums in piston_ring.csv.
        header = PACK_COLUMNS + [c.format(x) for x in args.rings for c in RING_COLUMNS]
        rows = read_csv(os.path.join(args.dir, "piston_ring.csv"), header)
        problems += time_series_problems(rows, args.t_end)
        ring_rows, integral = {}, 0.0
        for x in args.rings:
            more, ring_rows[x], w_ds = ring_problems(os.path.join(args.dir, f"piston_ring_{x}.csv"), args, f"ring {x}: ")
            problems += more
            integral += w_ds
            if len(ring_rows[x]) != len(rows):
                problems.append(f"ring {x}: {len(ring_rows[x])} rows, the pack has {len(rows)}")
        col = {c: i for i, c in enumerate(header)}
        for i, r in enumerate(rows):
            for total_name, ring_name, ring_index in (("friction_force_N", "friction_{}_N", 7),
                                                      ("normal_load_N", "normal_load_{}_N", 9),
                                                      ("land_force_N", None, 8)):
                parts = [ring_rows[x][i][ring_index] for x in args.rings]
                if ring_name and any(r[col[ring_name.format(x)]] != p for x, p in zip(args.rings, parts)):
                    problems.append(f"row at t={r[0]}: {ring_name} differs from piston_ring_X.csv")
                if abs(r[col[total_name]] - sum(parts)) > 1e-9 * max(sum(abs(p) for p in parts), 1.0):
                    problems.append(f"row at t={r[0]}: {total_name} {r[col[total_name]]} != sum over the rings {sum(parts)}")
            slip = max(ring_rows[x][i][12] for x in args.rings)
            if r[col["state_slip"]] != slip:
                problems.append(f"row at t={r[0]}: state_slip {r[col['state_slip']]}, rings {slip}")
            if slip == 0 and abs(r[col["friction_force_N"]]) > args.mu_static * r[col["normal_load_N"]] * (1 + 1e-6):
                problems.append(f"stick row at t={r[0]}: pack |F| above mu_s W")
            if problems:
                break
        total = [r[col["wear_volume_m3"]] for r in rows]
        per_ring = sum(ring_rows[x][-1][15] for x in args.rings)
        if abs(total[-1] - per_ring) > 1e-9 * per_ring:
            problems.append(f"pack wear volume {total[-1]} != sum of the rings' {per_ring}")
        expected = args.k_over_h * integral
        if not abs(total[-1] - expected) <= 2e-3 * expected:
            problems.append(f"pack wear volume {total[-1]} != k/H sum int W ds = {expected}")
    if args.breakaway is not None:
        first = first_breakaway(next(iter(ring_rows.values())))
        if first is None or abs(first - args.breakaway) > 1e-6 * args.breakaway:
            problems.append(f"break-away at {first}, expected {args.breakaway}")
    if args.land_geometry or args.breakaway_closed_form:
        with open(os.path.join(args.dir, "piston_ring_rings.csv"), newline="") as f:
            import csv
            table = {r["ring"]: r for r in csv.DictReader(f)}
        for x, rrows in ring_rows.items():
            spec = table[x or "A"]
            k, c = float(spec["land_stiffness_N_m"]), float(spec["land_damping_N_s_m"])
            if args.land_geometry:
                bore, width, thickness, e, nu = args.land_geometry
                expect_k = land_stiffness(bore, float(spec["groove_diameter_m"]), float(spec["land_width_m"]), width,
                                          thickness, e, nu)
                if not close(k, expect_k, 1e-9):
                    problems.append(f"ring {x}: land stiffness {k} != plate strip + ring shear {expect_k}")
            if args.breakaway_closed_form:
                w, v_p = rrows[0][9], rrows[0][3]
                t_b = (args.mu_static * w - c * abs(v_p)) / (k * abs(v_p))
                first = first_breakaway(rrows)
                if t_b <= 0.0:
                    if first != 0.0:
                        problems.append(f"ring {x}: start above the static limit, first slip at {first}")
                elif first is None or abs(first - t_b) > 1e-6 * t_b:
                    problems.append(f"ring {x}: break-away at {first}, closed form {t_b}")
                else:
                    print(f"ring {x}: break-away at {first:.9g} s, closed form {t_b:.9g} s (k {k:.6g} N/m)")

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
        for stem in ["liner", "ring_face"] + [f"ring_face_{x}" for x in (args.rings or [])[1:]]:
            frames = [n for n in names if re.fullmatch(re.escape(stem) + r"_\d+\.vts", n)]
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
