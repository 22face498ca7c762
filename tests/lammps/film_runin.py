#!/usr/bin/env python3
"""Run-in curve shapes from surface films in the rough-on-rough cell inputs/in.rve_rough (friction junction/film), by
its inputs alone (doc/surface_films.md; Blau 1981 classifies run-in curves). Steel1020 on Steel1020, 5 MPa, 1 m/s,
12^2 summits, loaded for 2000 steps (vsettle 5 cm/s), then 30000 sliding steps (600 um):

  rise   covered summits (coverage 1, s_r 30 um, k_g 1e3 1/s): the film is worn off faster than it grows back, mu_body
         rises from the film's level to a steady one
  fall   clean summits (coverage 0, s_r 300 um, k_g 1e4 1/s): the film grows faster than sliding removes it, mu_body
         falls from the clean level to a steady one

  peak   two films (40000 steps, 800 um): the rough body covered by a film wiped off within a few um (coverage 1,
         s_r 3 um, k_g 0), the counter-body clean but growing a film that sliding hardly removes (coverage_cf 0,
         s_r_cf 1 mm, k_g_cf 5e3 1/s): mu_body rises to a peak while both are bare, then falls as the counter-body's
         film grows (peak at least 1.5 x the start and the end level; the end steady)

Asserted: at the end of loading (no sliding yet: only growth acted, for nload dt) the adhesion part mu_adh (entry 6,
the contacts' limits over their load) is Tabor's f / sqrt(alpha (1 - f^2)) at f = theta_L f_film + (1 - theta_L)
f_clean, theta_L the mean over the two bodies of 1 - (1 - coverage) exp(-k_g nload dt), within 3 % (elastic contacts shear at f / sqrt(alpha));
the first sliding row's mu_body within 20 % of that level; the mean mu_body of the last of six equal windows of s at
least 2.5 x above (rise) or below (fall) it; the last two windows within --steady (5 %): a steady end.

With --ranks instead: the rise inputs with faster growth (k_g 1e4 1/s) over 10000 sliding steps (200 um: the
counter-body's summits cross the ranks' subdomains, so their coverage moves with them by exchange) on 1 and 2 MPI
ranks: every output value (mu_body, its adhesion part, which follows the coverage, wear, roughness) within 1e-9.

  film_runin.py --lmp LMP --workdir DIR [--ranks --mpiexec MPIEXEC]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, numeric_table, run_lammps  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "inputs", "in.rve_rough")
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
COLUMNS = ("step", "s", "h", "h_cf", "mu", "rq", "rsk", "af", "mu_adh", "mu_plough", "contacts")
F_CLEAN, F_FILM, ALPHA, DT, NLOAD = 0.8, 0.2, 12.0, 2.0e-8, 2000
CELL = {"material": MATERIAL, "pressure": 5.0e6, "nside": 12, "depth": 1.0, "nslide": 30000, "nout": 100,
        "nload": NLOAD, "vsettle": 0.05, "seed": 11, "friction": "junction/film"}
# the shapes' inputs (doc/surface_films.md quotes them)
SHAPES = {
    "rise": ({"coverage": 1.0, "s_r": 3.0e-5, "k_g": 1.0e3}, +1),
    "fall": ({"coverage": 0.0, "s_r": 3.0e-4, "k_g": 1.0e4}, -1),
    # two films: the rough body's (a contaminant) wiped off fast and not regrown, the counter-body's (an oxide)
    # hard to remove and growing
    "peak": ({"coverage": 1.0, "s_r": 3.0e-6, "k_g": 0.0, "coverage_cf": 0.0, "s_r_cf": 1.0e-3, "k_g_cf": 5.0e3,
              "nslide": 40000}, 0),
}


def tabor(f):
    return f / math.sqrt(ALPHA * (1.0 - f * f))


def windows(rows, n=6):
    size = len(rows) // n
    return [sum(r["mu"] for r in rows[k * size:(k + 1) * size]) / size for k in range(n)]


def coverage_of(mu_adh):
    """The contacts' mean coverage that an adhesion part implies (Tabor inverted, every junction plastic)."""
    f = math.sqrt(mu_adh ** 2 * ALPHA / (1.0 + mu_adh ** 2 * ALPHA))
    return (F_CLEAN - f) / (F_CLEAN - F_FILM)


def node_closure(name, film, rows, theta_0):
    """The element's node film (continuum/node_film.h) against this cell: one coverage per node, its summits in
    contact a fraction phi = contacts / summits of the sliding (the state law's contact_fraction), and friction
    Tabor's at f(theta). Reported per window of s: the cell's contact coverage (from mu_adh) and mu_body against the
    node model's theta(s) and T(f(theta(s)))."""
    phi = sum(r["contacts"] for r in rows) / len(rows) / CELL["nside"] ** 2
    rate = phi / film["s_r"] + film["k_g"] / 1.0    # per m of sliding at v = 1 m/s
    steady = (film["k_g"] / 1.0) / rate
    theta = [steady + (theta_0 - steady) * math.exp(-rate * r["s"]) for r in rows]
    size = len(rows) // 6
    cells = [sum(coverage_of(r["mu_adh"]) for r in rows[k * size:(k + 1) * size]) / size for k in range(6)]
    nodes = [sum(theta[k * size:(k + 1) * size]) / size for k in range(6)]
    mu_cell = windows(rows)
    mu_node = [sum(tabor(t * F_FILM + (1.0 - t) * F_CLEAN) for t in theta[k * size:(k + 1) * size]) / size
               for k in range(6)]
    err = [m / c - 1.0 for m, c in zip(mu_node, mu_cell)]
    print(f"node closure: {name}: phi = contacts / summits {phi:.4f}, relaxation length {1e6 / rate:.0f} um, "
          f"steady coverage {steady:.3f}; coverage cell {' '.join(f'{c:.3f}' for c in cells)}, node "
          f"{' '.join(f'{c:.3f}' for c in nodes)}; mu_body node / cell - 1 {' '.join(f'{e:+.3f}' for e in err)}")


def ranks(args):
    cell = dict(CELL, nslide=10000, **dict(SHAPES["rise"][0], k_g=1.0e4))
    tables = []
    for np in (1, 2):
        run_lammps(args, DECK, dict(cell, out=f"np{np}.dat"), log=f"log.np{np}", np=np)
        tables.append(numeric_table(os.path.join(args.workdir, f"np{np}.dat")))
    one, two = tables
    if len(one) != len(two):
        fail(f"1 rank wrote {len(one)} rows, 2 ranks {len(two)}")
    worst = max(abs(a - b) / max(abs(a), 1e-300) for ra, rb in zip(one, two) for a, b in zip(ra, rb))
    if worst > 1e-9:
        fail(f"1 and 2 MPI ranks differ by {worst:.3g} (relative)")
    print(f"ok: {len(one)} rows, mu_adh {one[1][8]:.5f} -> {one[-1][8]:.5f}; 1 and 2 MPI ranks agree to {worst:.3g}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--steady", type=float, default=0.05)
    parser.add_argument("--ranks", action="store_true")
    parser.add_argument("--mpiexec", default="mpiexec")
    args = parser.parse_args()
    fresh_dir(args.workdir)
    if args.ranks:
        ranks(args)
        return
    for name, (film, direction) in SHAPES.items():
        run_lammps(args, DECK, dict(CELL, out=f"{name}.dat", **film), log=f"log.{name}")
        film = dict(film)
        rows = [dict(zip(COLUMNS, r)) for r in numeric_table(os.path.join(args.workdir, f"{name}.dat"))]
        # the mean coverage of the two bodies after loading (growth only)
        theta_l = 0.5 * sum(1.0 - (1.0 - film.get("coverage" + cf, film["coverage"]))
                            * math.exp(-film.get("k_g" + cf, film["k_g"]) * NLOAD * DT) for cf in ("", "_cf"))
        start = tabor(theta_l * F_FILM + (1.0 - theta_l) * F_CLEAN)
        loaded = rows[0]["mu_adh"]
        if abs(loaded / start - 1.0) > 0.03:
            fail(f"{name}: mu_adh {loaded:.5f} at the end of loading, Tabor at theta_L = {theta_l:.4f}: {start:.5f}")
        first = rows[1]["mu"]
        if direction != 0 and abs(first / start - 1.0) > 0.20:
            fail(f"{name}: the first sliding row's mu_body {first:.4f} is not near the start level {start:.4f}")
        w = windows(rows[1:])
        if direction == 0:
            # peak then fall: the highest running mean (5 rows, 10 um) at least 1.5 x the start and the end levels
            smooth = [sum(r["mu"] for r in rows[k:k + 5]) / 5 for k in range(1, len(rows) - 4)]
            top = max(smooth)
            at = rows[1 + smooth.index(top) + 2]["s"]
            drift = abs(w[-1] / w[-2] - 1.0)
            if not (top > 1.5 * start and top > 1.5 * w[-1]) or drift > args.steady:
                fail(f"{name}: start {start:.4f}, peak {top:.4f} at s = {at * 1e6:.0f} um, end windows "
                     f"{w[-2]:.4f} {w[-1]:.4f}: not a peak then a steady fall")
            print(f"ok: peak: end of loading mu_adh {loaded:.4f} (Tabor at the mean theta_L = {theta_l:.4f}: "
                  f"{start:.4f}); peak mu_body {top:.4f} (mean of 5 rows) at s = {at * 1e6:.0f} um; mu_body over six "
                  f"windows of s = {rows[-1]['s'] * 1e6:.0f} um: {' '.join(f'{m:.4f}' for m in w)} (peak / end "
                  f"{top / w[-1]:.2f} x; last two within {drift:.1%})")
            continue
        ratio = w[-1] / start if direction > 0 else start / w[-1]
        if ratio < 2.5:
            fail(f"{name}: mu_body {start:.4f} -> {w[-1]:.4f} (windows {', '.join(f'{m:.4f}' for m in w)}): not a "
                 f"{name} by 2.5 x")
        drift = abs(w[-1] / w[-2] - 1.0)
        if drift > args.steady:
            fail(f"{name}: the last two windows {w[-2]:.4f}, {w[-1]:.4f} differ by {drift:.1%}: not steady")
        if not tabor(F_FILM) < w[-1] < tabor(F_CLEAN):
            fail(f"{name}: steady mu_body {w[-1]:.4f} outside the film and clean levels")
        # the steady coverage the adhesion part implies (Tabor inverted, all junctions taken as plastic), and the
        # fraction phi of the sliding a summit spends in contact that it needs: theta* = k_g / (k_g + phi v / s_r)
        last = rows[-(len(rows) // 6):]
        mu_adh = sum(r["mu_adh"] for r in last) / len(last)
        f = math.sqrt(mu_adh ** 2 * ALPHA / (1.0 + mu_adh ** 2 * ALPHA))
        theta = (F_CLEAN - f) / (F_CLEAN - F_FILM)
        phi = film["k_g"] * (1.0 / theta - 1.0) * film["s_r"] / 1.0    # v = 1 m/s
        print(f"{name}: last window mu_adh {mu_adh:.4f}: f = {f:.3f}, mean coverage {theta:.3f}, phi = {phi:.3f}")
        node_closure(name, film, rows[1:], theta_l)
        print(f"ok: {name}: end of loading mu_adh {loaded:.4f} (Tabor at theta_L = {theta_l:.4f}: {start:.4f}); "
              f"mu_body over six windows of s = {rows[-1]['s'] * 1e6:.0f} um: {' '.join(f'{m:.4f}' for m in w)} "
              f"({ratio:.2f} x; last two within {drift:.1%})")
    print("PASS")


if __name__ == "__main__":
    main()
