#!/usr/bin/env python3
"""Junction growth through pair_style runin/asperity friction junction (deck in.junction_shear; or fix runin/wall
keyword junction, --deck wall_junction): a plastic
junction of two asperities sheared at constant normal load. For each f, F_t / F_n at gross sliding (the first
step with no sticking contact) against Tabor (1959), mu = f / sqrt(alpha (1 - f^2)), within --tolerance; the
real area (compute runin/friction entry 9) against sqrt(1 + alpha (F_t / F_n)^2) times the unsheared area,
i.e. sqrt(F_n^2 + alpha F_t^2) / p_m with p_m = F_n / A_0; with --compare-np2 the same run on 2 MPI ranks (one
asperity each) must agree with 1 rank (stdlib only).

  junction_growth.py --lmp LMP --workdir DIR [--deck NAME] [--f 0.2 0.5 ...] [--alpha 12] [--compare-np2 --mpiexec M]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECKS = os.path.join(SOURCE_DIR, "tests", "lammps", "decks")


def tabor(f, alpha):
    return f / math.sqrt(alpha * (1.0 - f * f))


def check_one(args, f, np=1):
    log = f"log.f{f}.np{np}"
    deck = os.path.join(DECKS, "in." + args.deck)
    text = run_lammps(args, deck, {"f": f, "alpha": args.alpha}, log=log, np=np)
    if "Tabor1959" not in text:
        fail(f"f = {f}: Tabor (1959) is not in the log's citation list")
    press, shear = thermo_blocks(text)[:2]
    unsheared = press[-1]
    if unsheared["c_fric[4]"] != 1 or not unsheared["c_fric[1]"] > 0.0:
        fail(f"f = {f}: the asperities are not in contact after pressing")
    fn0, area0 = unsheared["c_fric[1]"], unsheared["c_fric[9]"]
    p_m = fn0 / area0
    # 350 MPa yield: a plastic junction carries a mean pressure well above it (Jackson-Green: towards 2.84 S_y)
    if not p_m > 2.0 * 350e6:
        fail(f"f = {f}: mean pressure {p_m:.4g} Pa: the junction is not plastic")
    sliding = [row for row in shear if row["c_fric[8]"] == 0 and row["Step"] > shear[0]["Step"]]
    if not sliding:
        fail(f"f = {f}: no gross sliding in {len(shear) - 1} shear steps")
    first = sliding[0]
    if first["Step"] - shear[0]["Step"] < 10:
        fail(f"f = {f}: the junction slid at once (step {first['Step']}): no stick phase")
    ratio = first["c_fric[2]"] / first["c_fric[1]"]
    want = tabor(f, args.alpha)
    error = abs(ratio - want) / want
    if error > args.tolerance:
        fail(f"f = {f}: F_t / F_n at gross sliding {ratio:.6g} vs Tabor {want:.6g} ({error:.3g} > {args.tolerance})")
    worst_area = 0.0
    for row in shear:
        fn, ft = row["c_fric[1]"], row["c_fric[2]"]
        if abs(fn - fn0) > 1e-12 * fn0:
            fail(f"f = {f}: normal load changed while shearing ({fn!r} vs {fn0!r} N at step {row['Step']})")
        expected = math.sqrt(fn * fn + args.alpha * ft * ft) / p_m
        worst_area = max(worst_area, abs(row["c_fric[9]"] - expected) / expected)
    if worst_area > 1e-9:
        fail(f"f = {f}: real area differs from sqrt(F_n^2 + alpha F_t^2) / p_m by {worst_area:.3g}")
    growth = shear[-1]["c_fric[9]"] / area0
    print(f"ok: {args.deck}: f = {f}, alpha = {args.alpha}, np {np}: F_n = {fn0:.6g} N, p_m = {p_m / 350e6:.4f} S_y, gross sliding "
          f"at step {first['Step']}: F_t/F_n = {ratio:.6f} (Tabor {want:.6f}, rel. error {error:.2g}); "
          f"area growth A/A_0 = {growth:.5f} (1/sqrt(1-f^2) = {1 / math.sqrt(1 - f * f):.5f}); "
          f"area law worst rel. error {worst_area:.2g}")
    return shear


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--f", type=float, nargs="+", default=[0.2, 0.5, 0.8, 0.95])
    parser.add_argument("--alpha", type=float, default=12.0)
    parser.add_argument("--tolerance", type=float, default=0.10)
    parser.add_argument("--compare-np2", action="store_true")
    parser.add_argument("--deck", default="junction_shear", help="junction_shear (pair) or wall_junction (fix runin/wall)")
    args = parser.parse_args()
    fresh_dir(args.workdir)
    for f in args.f:
        one = check_one(args, f)
        if args.compare_np2:
            two = check_one(args, f, np=2)
            keys = ("c_fric[1]", "c_fric[2]", "c_fric[9]")
            worst = max(abs(a[k] - b[k]) / max(abs(a[k]), 1e-300) for a, b in zip(one, two) for k in keys)
            if len(one) != len(two) or worst > 1e-12:
                fail(f"f = {f}: 1 and 2 MPI ranks differ by {worst:.3g} (relative)")
            print(f"ok: f = {f}: 1 and 2 MPI ranks agree to {worst:.2g}")


if __name__ == "__main__":
    main()
