#!/usr/bin/env python3
"""Amontons's law on the rough-on-rough cell inputs/in.rve_rough (or, --cell wall, inputs/in.rve_wall) with an interface strength from data (run by ctest;
stdlib only): Steel1020 on Steel1020, the friction law from the material file's interface state (-var interface),
at two nominal pressures a decade apart. The steady mu_body (the mean of the output rows once the rough body's
worn depth h passed half of `depth`) must change by less than --tolerance (relative to their mean): the real area
of plastic summits is proportional to the load, and so is the friction of a law with a pressure-independent
tau_s / p_m (friction strength) or F_t / F_n (friction junction).

  rve_amontons.py --lmp LMP --workdir DIR [--friction strength|junction] [--interface oxidised]
                  [--pressures 2e6 2e7] [--nside 20] [--depth 3e-9] [--tolerance 0.10] [--cell rough|wall]
                  [--expect-tabor]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, numeric_table, run_lammps  # noqa: E402

DECKS = {"rough": os.path.join(SOURCE_DIR, "inputs", "in.rve_rough"), "wall": os.path.join(SOURCE_DIR, "inputs", "in.rve_wall")}
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
COLUMNS = ("step", "s", "h", "h_cf", "mu", "rq", "rsk", "af", "mu_adh", "mu_plough", "contacts")


def steady(args, pressure):
    name = f"p{pressure:g}"
    run_lammps(args, DECKS[args.cell], {"material": MATERIAL, "pressure": pressure, "accel": 1.0, "nside": args.nside,
                            "depth": args.depth, "seed": 11, "nout": args.nout, "out": f"{name}.dat",
                            "friction": args.friction, "interface": args.interface}, log=f"log.{name}")
    rows = [dict(zip(COLUMNS, r)) for r in numeric_table(os.path.join(args.workdir, f"{name}.dat"))]
    if rows[-1]["h"] < args.depth:
        fail(f"p = {pressure:g} Pa: the cell stopped at h = {rows[-1]['h']:g} m before {args.depth:g} m")
    band = [r for r in rows[1:] if r["h"] >= args.depth / 2]
    if len(band) < 3:
        fail(f"p = {pressure:g} Pa: {len(band)} output rows past h = depth / 2 (need 3)")
    # in.rve_wall writes the columns up to the area fraction only
    mean = {key: sum(r.get(key, math.nan) for r in band) / len(band)
            for key in ("mu", "mu_adh", "mu_plough", "contacts", "af")}
    print(f"p = {pressure:g} Pa: steady mu_body {mean['mu']:.4f} (adhesion {mean['mu_adh']:.4f}, ploughing "
          f"{mean['mu_plough']:.4f}), {mean['contacts']:.1f} contacts, A_r/A {mean['af']:.5f}, over {len(band)} rows "
          f"h = {band[0]['h']:.3g}-{band[-1]['h']:.3g} m")
    return mean["mu"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--friction", default="strength", choices=["strength", "brizmer", "junction"])
    parser.add_argument("--interface", default="oxidised")
    parser.add_argument("--pressures", type=float, nargs=2, default=[2.0e6, 2.0e7])
    parser.add_argument("--nside", type=int, default=20)
    parser.add_argument("--depth", type=float, default=3.0e-9)
    parser.add_argument("--tolerance", type=float, default=0.10)
    parser.add_argument("--nout", type=int, default=100)
    parser.add_argument("--cell", choices=["rough", "wall"], default="rough", help="in.rve_rough or in.rve_wall")
    parser.add_argument("--expect-tabor", action="store_true",
                        help="friction junction on the flat wall: mu_body is Tabor's closed form with f = m (1e-6)")
    args = parser.parse_args()
    args.workdir = os.path.abspath(args.workdir)
    fresh_dir(args.workdir)
    low, high = (steady(args, p) for p in args.pressures)
    change = abs(high - low) / (0.5 * (high + low))
    print(f"Amontons ({args.friction}, interface {args.interface}): mu_body {low:.4f} at {args.pressures[0]:g} Pa, "
          f"{high:.4f} at {args.pressures[1]:g} Pa: change {100 * change:.2f} % (limit {100 * args.tolerance:g} %)")
    if args.expect_tabor:
        # a flat counterface: every contact normal is the wall's, so mu_body is the contacts' own ratio
        m = [float(line.split()[4]) for line in open(MATERIAL)
             if line.split()[:4] == ["interface", "Steel1020", "Steel1020", args.interface]][0]
        tabor = m / math.sqrt(12.0 * (1.0 - m * m))
        worst = max(abs(mu - tabor) / tabor for mu in (low, high))
        print(f"Tabor's f / sqrt(alpha (1 - f^2)) with f = m = {m}, alpha = 12: {tabor:.6f}; worst {worst:.2g}")
        if worst > 1e-6:
            fail(f"steady mu_body differs from Tabor's {tabor:.6f} by {worst:.3g} (relative)")
    if change > args.tolerance:
        fail(f"mu_body changes by {100 * change:.2f} % over a decade of pressure (limit {100 * args.tolerance:g} %)")
    print("PASS")


if __name__ == "__main__":
    main()
