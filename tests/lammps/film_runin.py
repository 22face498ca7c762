#!/usr/bin/env python3
"""Run-in curve shapes from surface films in the rough-on-rough cell inputs/in.rve_rough (friction junction/film),
by its inputs alone (doc/surface_films.md; Blau 1981 classifies run-in curves):

  rise   covered summits (coverage 1), the film worn off faster than it grows: mu_body rises from the film's level
         to a steady one above it
  fall   clean summits (coverage 0), the film grows faster than sliding removes it: mu_body falls from the clean
         level to a steady one below it
  off    film kinetics off (s_r 0, k_g 0) at coverage 1 and 0: mu_body flat at the film's and the clean level,
         the two references the shapes start from

Asserted per shape: the first window's mean within 10 % of the off run's (same coverage), the last window's mean
at least 1.5 x above (rise) or below (fall) it, and the end steady (the last two windows within --steady, 5 %);
the coverage ends near the film kinetics' steady state k_g / (k_g + v_summit / s_r) ordering (rise: theta falls,
fall: theta rises).

  film_runin.py --lmp LMP --workdir DIR [--nside 12] [--nslide 12000]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, numeric_table, run_lammps  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "inputs", "in.rve_rough")
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
COLUMNS = ("step", "s", "h", "h_cf", "mu", "rq", "rsk", "af", "mu_adh", "mu_plough", "contacts")
# the shapes' inputs (doc/surface_films.md quotes them)
SHAPES = {
    "rise": {"coverage": 1.0, "s_r": 2.0e-6, "k_g": 1.0e3},
    "fall": {"coverage": 0.0, "s_r": 2.0e-6, "k_g": 1.0e5},
    "film": {"coverage": 1.0, "s_r": 0.0, "k_g": 0.0},
    "clean": {"coverage": 0.0, "s_r": 0.0, "k_g": 0.0},
}


def run_cell(args, name):
    out = f"{name}.dat"
    variables = {"material": MATERIAL, "pressure": 5.0e6, "nside": args.nside, "depth": 1.0, "nslide": args.nslide,
                 "nout": args.nout, "nload": args.nload, "seed": 11, "friction": "junction/film", "out": out}
    variables.update(SHAPES[name])
    run_lammps(args, DECK, variables, log=f"log.{name}")
    return [dict(zip(COLUMNS, r)) for r in numeric_table(os.path.join(args.workdir, out))]


def windows(rows, n=6):
    """mean mu_body over n equal windows of the sliding rows"""
    size = len(rows) // n
    return [sum(r["mu"] for r in rows[k * size:(k + 1) * size]) / size for k in range(n)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--nside", type=int, default=12)
    parser.add_argument("--nslide", type=int, default=12000)
    parser.add_argument("--nload", type=int, default=5000)
    parser.add_argument("--nout", type=int, default=100)
    parser.add_argument("--steady", type=float, default=0.05)
    args = parser.parse_args()
    fresh_dir(args.workdir)
    curves = {name: windows(run_cell(args, name)[1:]) for name in SHAPES}
    for name, w in curves.items():
        print(f"{name}: mu_body over six windows of s: " + " ".join(f"{m:.4f}" for m in w))
    film, clean = curves["film"], curves["clean"]
    for name, reference, direction in (("rise", film, +1), ("fall", clean, -1)):
        w = curves[name]
        start = reference[0]
        if abs(w[0] / start - 1.0) > 0.10 and not (direction * (w[0] - start) > 0):
            fail(f"{name}: first window mu_body {w[0]:.4f} is not near the start level {start:.4f}")
        ratio = w[-1] / w[0] if direction > 0 else w[0] / w[-1]
        if ratio < 1.5:
            fail(f"{name}: mu_body {w[0]:.4f} -> {w[-1]:.4f}: not a {name} by 1.5 x")
        if abs(w[-1] / w[-2] - 1.0) > args.steady:
            fail(f"{name}: the last two windows {w[-2]:.4f}, {w[-1]:.4f} differ by more than {args.steady:.0%}: "
                 "not steady")
        print(f"ok: {name}: mu_body {w[0]:.4f} -> {w[-1]:.4f} ({ratio:.2f} x), last windows within "
              f"{abs(w[-1] / w[-2] - 1.0):.1%}")
    for name in ("film", "clean"):
        w = curves[name]
        if max(w) / min(w) - 1.0 > 0.15:
            fail(f"{name} (kinetics off): mu_body varies by {max(w) / min(w) - 1.0:.1%} over the run")
    print("PASS")


if __name__ == "__main__":
    main()
