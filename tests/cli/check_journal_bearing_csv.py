#!/usr/bin/python3
"""Checks of a `runin journal-bearing` output directory (stdlib only).

usage: check_journal_bearing_csv.py DIR --t-end T [--halves 1|2] [--symmetric] [--mu-static MU] [--sweep N]
                                    [--claim3] [--archard K_OVER_H] [--vtk N] [--png]
"""
import argparse
import math
import os
import re
import sys

from output_checks import close, finish, leftover_problems, png_problems, read_csv, time_series_problems

COLUMNS = ["t_s", "drive_angle_rad", "drive_speed_rad_s", "journal_speed_rad_s", "coupling_torque_N_m",
           "friction_torque_N_m", "friction_force_N", "normal_force_N", "mu", "mu_law", "sliding_speed_m_s",
           "sliding_distance_m", "wear_volume_m3", "contact_half_angle_rad", "peak_pressure_Pa",
           "mean_pressure_Pa", "state_slip", "roughness"]
HALF = ["friction_torque_N_m", "normal_force_N", "mu", "roughness", "wear_volume_m3", "contact_half_angle_rad",
        "peak_pressure_Pa"]
HALVES = [f"{half}_{name}" for half in ("lower", "upper") for name in HALF]
SWEEP = ["mu0", "peak_friction_force_N", "peak_time_s", "breakaway_time_s", "steady_time_s", "steady_mu",
         "wear_volume_m3"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("dir")
    parser.add_argument("--t-end", type=float, required=True)
    parser.add_argument("--halves", type=int, default=2, choices=(1, 2),
                        help="bearing halves: 2 adds per-half columns (totals = sum of the halves, 1e-9), "
                             "VTK frames of the upper half")
    parser.add_argument("--symmetric", action="store_true", help="both halves equal at every row (1e-12)")
    parser.add_argument("--mu-static", type=float, help="friction force at break-away = mu_static N (rel 1e-6)")
    parser.add_argument("--sweep", type=int, help="number of mu0 values")
    parser.add_argument("--unsettled", type=int, default=0,
                        help="sweep rows not steady within the run: an empty steady_time_s cell (default 0)")
    parser.add_argument("--claims", type=float, nargs=3, metavar=("PEAK", "TIME", "START"),
                        help="thesis claims 2 and 3 on the sweep curves with these relative margins "
                             "(tests/cli/thesis_claims.py)")
    parser.add_argument("--lag", type=float, nargs=2, metavar=("MAX_RAD", "SHAFT_RADIUS"),
                        help="the journal angle s / R (it turns forward only) lags the drive angle by at most "
                             "MAX_RAD at every sample (the coupling wind-up)")
    parser.add_argument("--claim3", action="store_true", help="peak friction > 1.05 x final friction")
    parser.add_argument("--archard", type=float, help="k/H: wear volume = (k/H) int N ds (rel 1e-4)")
    parser.add_argument("--vtk", type=int, help="expected number of VTK frames")
    parser.add_argument("--png", action="store_true")
    args = parser.parse_args()
    columns = COLUMNS + (HALVES if args.halves == 2 else [])
    c = {name: i for i, name in enumerate(columns)}
    c_t, c_f, c_w = c["t_s"], c["friction_force_N"], c["journal_speed_rad_s"]

    problems = []
    rows = read_csv(os.path.join(args.dir, "journal_bearing.csv"), columns)
    problems += time_series_problems(rows, args.t_end)
    for i, r in enumerate(rows):
        # A stick row carries the coupling torque; only the row of an immediate break-away at the start
        # (the coupling's damper torque already above the static limit) carries less: the static limit.
        immediate = (r[0] == 0.0 and i + 1 < len(rows) and rows[i + 1][0] == 0.0 and rows[i + 1][c["state_slip"]] == 1
                     and abs(r[c["friction_torque_N_m"]]) < abs(r[c["coupling_torque_N_m"]]))
        if r[c["state_slip"]] == 0 and (r[c["journal_speed_rad_s"]] != 0 or
                                         not (immediate or close(r[c["friction_torque_N_m"]], r[c["coupling_torque_N_m"]], 1e-9))):
            problems.append(f"stick row at t={r[0]}: speed != 0 or friction torque != coupling torque")
            break
    if args.halves == 2:
        for total in ("friction_torque_N_m", "normal_force_N", "wear_volume_m3"):
            bad = [r[0] for r in rows
                   if not close(r[c[total]], r[c["lower_" + total]] + r[c["upper_" + total]], 1e-9)]
            if bad:
                problems.append(f"{total} != lower + upper at t = {bad[0]} ({len(bad)} rows)")
        if args.symmetric:
            bad = [r[0] for r in rows if not all(close(r[c["lower_" + n]], r[c["upper_" + n]], 1e-12) for n in HALF)]
            if bad:
                problems.append(f"symmetric load, but the halves differ at t = {bad[0]} ({len(bad)} rows)")
    for name in ("sliding_distance_m", "wear_volume_m3"):
        values = [r[c[name]] for r in rows]
        if any(b < a - 1e-18 for a, b in zip(values, values[1:])):
            problems.append(f"{name} decreases")
    if any(r[c["peak_pressure_Pa"]] < r[c["mean_pressure_Pa"]] * (1 - 1e-9) for r in rows):
        problems.append("peak pressure below mean pressure")
    if any(r[c["normal_force_N"]] < 0 for r in rows):
        problems.append("negative normal force")
    breakaway = [i for i in range(1, len(rows)) if rows[i - 1][c["state_slip"]] == 0 and rows[i][c["state_slip"]] == 1]
    if args.mu_static is not None:
        # Also at an immediate break-away (t = 0): the stick row then carries the static limit mu_s N.
        if not breakaway:
            problems.append("no break-away")
        else:
            before = rows[breakaway[0] - 1]
            expected = args.mu_static * before[c["normal_force_N"]]
            if not close(before[c["friction_force_N"]], expected, 1e-6):
                problems.append(f"friction at break-away {before[c['friction_force_N']]} != mu_s N = {expected}")
    if args.claim3:
        peak = max(abs(r[c["friction_force_N"]]) for r in rows)
        final = abs(rows[-1][c["friction_force_N"]])
        if not peak > 1.05 * final:
            problems.append(f"claim 3: peak friction {peak} not > 1.05 x final {final}")
    if args.archard is not None:
        integral = sum(0.5 * (a[c["normal_force_N"]] + b[c["normal_force_N"]]) *
                       (b[c["sliding_distance_m"]] - a[c["sliding_distance_m"]]) for a, b in zip(rows, rows[1:]))
        if not close(rows[-1][c["wear_volume_m3"]], args.archard * integral, 1e-4):
            problems.append(f"wear volume {rows[-1][c['wear_volume_m3']]} != (k/H) int N ds = {args.archard * integral}")
        half = [r[c["contact_half_angle_rad"]] for r in rows]
        if not half[-1] > 1.5 * half[0]:
            problems.append(f"contact arc did not widen: {half[0]} -> {half[-1]}")
        if not rows[-1][c["peak_pressure_Pa"]] < 0.7 * rows[0][c["peak_pressure_Pa"]]:
            problems.append("peak pressure did not fall with wear")
    if args.sweep:
        table = sorted(read_csv(os.path.join(args.dir, "journal_bearing_sweep_summary.csv"), SWEEP))
        if len(table) != args.sweep:
            problems.append(f"{len(table)} sweep rows, expected {args.sweep}")
        # Higher mu0 -> later break-away (mu0 N R wound up through the coupling), unless both break away
        # at once at t = 0 (the coupling's damper torque c w_d above both static limits).
        for lower, higher in zip(table, table[1:]):
            if not (higher[3] > lower[3] or higher[3] == lower[3] == 0.0):
                problems.append(f"break-away not later at mu0 {higher[0]} than at {lower[0]}")
        unsettled = sum(1 for r in table if math.isnan(r[4]))
        if unsettled != args.unsettled:
            problems.append(f"{unsettled} sweep rows without a steady time, expected {args.unsettled}")
        if any(r[4] < 0.0 for r in table if not math.isnan(r[4])):
            problems.append("a steady time is negative (not reached is an empty cell)")
        print("sweep break-away times (s):", ", ".join(f"mu0 {r[0]:g}: {r[3]:.6g}" for r in table))
        if args.claims:
            sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
            from thesis_claims import check_claims
            curves = {}
            for r in read_csv(os.path.join(args.dir, "journal_bearing_sweep.csv"), ["mu0"] + columns):
                curve = curves.setdefault(r[0], ([], [], []))
                curve[0].append(r[1 + c_t]), curve[1].append(r[1 + c_f]), curve[2].append(r[1 + c_w])
            problems += check_claims(curves, *args.claims)
    if args.vtk is not None:
        vtk = os.path.join(args.dir, "vtk")
        for stem in ["bore"] + (["bore_upper"] if args.halves == 2 else []):
            frames = [n for n in os.listdir(vtk) if re.fullmatch(stem + r"_\d+\.vts", n)]
            if len(frames) != args.vtk or not os.path.exists(os.path.join(vtk, stem + ".pvd")):
                problems.append(f"{len(frames)} VTK frames {stem}_*.vts (+ {stem}.pvd?), expected {args.vtk}")
            else:
                with open(os.path.join(vtk, sorted(frames)[-1])) as f:
                    text = f.read()
                for field in ("pressure", "wear_depth"):
                    if f'Name="{field}"' not in text:
                        problems.append(f"VTK frame {stem} lacks field {field}")
    if args.png:
        names = ["journal_bearing.png"] + (["journal_bearing_mu0.png"] if args.sweep else [])
        problems += png_problems(args.dir, names)
    problems += leftover_problems(args.dir)
    finish("check_journal_bearing_csv", problems, f"checked {len(rows)} rows, {len(breakaway)} break-away(s), final friction {rows[-1][c['friction_force_N']]} N")


if __name__ == "__main__":
    main()
