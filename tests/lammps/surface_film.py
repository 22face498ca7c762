#!/usr/bin/env python3
"""Surface film on a plastic junction (pair_style runin/asperity friction junction/film, deck in.film_shear): two
asperities pressed into the plastic regime and sheared at constant normal load through gross sliding.

  limits   coverage 1 with removal and growth off: F_t / F_n while sliding is Tabor's f / sqrt(alpha (1 - f^2)) at
           f = f_film; coverage 0: at f = f_clean; the lower summit covered, the upper clean: at (f_film + f_clean) / 2
           (within --tolerance, 2 %), and the coverage stays as it was
  decay    growth off: the coverage after each step is theta0 exp(-s / s_r), s the slip so far (each step's slip from
           the frictional power, entry 13: P dt / F_t), to 1e-9; F_t / F_n of every sliding step is Tabor's at the
           f of the coverage before it (1e-9)
  restart  write_restart half way, read_restart, continue (in.film_shear_restart): equal to the uninterrupted run
           (forces, coverage) to 1e-15
  ranks    1 and 2 MPI ranks (one asperity each) agree to 1e-12

  surface_film.py MODE --lmp LMP --workdir DIR [--mpiexec M]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECKS = os.path.join(SOURCE_DIR, "tests", "lammps", "decks")
F_CLEAN, F_FILM, ALPHA, DT = 0.8, 0.2, 12.0, 1.0e-9
KEYS = ("c_fric[1]", "c_fric[2]", "c_fric[13]", "c_theta1", "c_theta2")


def tabor(f, alpha=ALPHA):
    return f / math.sqrt(alpha * (1.0 - f * f))


def shear(args, variables, log, np=1, deck="film_shear"):
    text = run_lammps(args, os.path.join(DECKS, "in." + deck), variables, log=log, np=np)
    blocks = thermo_blocks(text)
    return blocks[-1]


def sliding(rows):
    return [(prev, row) for prev, row in zip(rows, rows[1:]) if row["c_fric[8]"] == 0 and row["c_fric[4]"] == 1]


def limits(args):
    # the third case: the lower summit covered, the upper one clean (per-atom initial coverage, fix RUNIN/FILM
    # coverage v_name): the contact shears at the mean coverage 1/2
    for coverage, top, f in ((1.0, 1.0, F_FILM), (0.0, 0.0, F_CLEAN), (1.0, 0.0, 0.5 * (F_FILM + F_CLEAN))):
        rows = shear(args, {"coverage": coverage, "coverage_top": top}, f"log.limits.{coverage}.{top}")
        slid = sliding(rows)
        if len(slid) < 100:
            fail(f"coverage {coverage}: only {len(slid)} sliding steps")
        want = tabor(f)
        worst = max(abs(row["c_fric[2]"] / row["c_fric[1]"] - want) / want for _, row in slid)
        if worst > args.tolerance:
            fail(f"coverage {coverage}: F_t / F_n differs from Tabor's {want:.6g} (f = {f}) by {worst:.3g}")
        if any(row["c_theta1"] != coverage or row["c_theta2"] != top for row in rows):
            fail(f"coverage {coverage}, {top}: the coverage changed with removal and growth off")
        last = slid[-1][1]
        print(f"ok: coverage {coverage}, {top}: sliding F_t/F_n = {last['c_fric[2]'] / last['c_fric[1]']:.6f}, Tabor at "
              f"f = {f}: {want:.6f} (worst rel. error {worst:.2g} over {len(slid)} sliding steps)")


def decay(args):
    s_r, theta0 = 5.0e-9, 1.0
    rows = shear(args, {"s_r": s_r, "coverage": theta0}, "log.decay")
    slid = 0.0
    worst_theta = worst_mu = 0.0
    for prev, row in zip(rows, rows[1:]):
        if row["c_fric[2]"] > 0.0:
            slid += row["c_fric[13]"] * DT / row["c_fric[2]"]
        want = theta0 * math.exp(-slid / s_r)
        for key in ("c_theta1", "c_theta2"):
            worst_theta = max(worst_theta, abs(row[key] - want))
        if row["c_fric[8]"] == 0 and row["c_fric[4]"] == 1:
            theta = 0.5 * (prev["c_theta1"] + prev["c_theta2"])
            f = theta * F_FILM + (1.0 - theta) * F_CLEAN
            worst_mu = max(worst_mu, abs(row["c_fric[2]"] / row["c_fric[1]"] - tabor(f)) / tabor(f))
    if worst_theta > 1e-9:
        fail(f"coverage differs from theta0 exp(-s / s_r) by {worst_theta:.3g}")
    if worst_mu > 1e-9:
        fail(f"F_t / F_n differs from Tabor's at the film's f by {worst_mu:.3g}")
    if not slid > 2.0 * s_r:
        fail(f"slid only {slid:.3g} m: the film was not worn")
    last = rows[-1]
    print(f"ok: growth off, s_r = {s_r} m: after s = {slid:.6g} m theta = {last['c_theta1']:.6g} "
          f"(theta0 exp(-s/s_r) = {theta0 * math.exp(-slid / s_r):.6g}, worst abs. error {worst_theta:.2g}); "
          f"F_t/F_n {last['c_fric[2]'] / last['c_fric[1]']:.6f} (worst rel. error vs Tabor at f(theta) {worst_mu:.2g})")


BOTH = {"s_r": 5.0e-9, "k_g": 1.0e6, "coverage": 1.0}


def compare(one, two, what, limit):
    if len(one) != len(two):
        fail(f"{what}: {len(one)} vs {len(two)} rows")
    worst = 0.0
    for a, b in zip(one, two):
        if a["Step"] != b["Step"]:
            fail(f"{what}: steps {a['Step']} and {b['Step']} side by side")
        for key in KEYS:
            worst = max(worst, abs(a[key] - b[key]) / max(abs(a[key]), 1e-300))
    if worst > limit:
        fail(f"{what}: differ by {worst:.3g} (relative; limit {limit})")
    return worst


def restart(args):
    full = shear(args, BOTH, "log.full")
    half = 750
    shear(args, dict(BOTH, restart_at=half), "log.first")
    text = run_lammps(args, os.path.join(DECKS, "in.film_shear_restart"), {"restart_at": half}, log="log.second")
    second = thermo_blocks(text)[-1]
    # the setup row of the continued run is a force evaluation that does not advance: compare the steps after it
    second = second[1:]
    start = second[0]["Step"]
    tail = [row for row in full if row["Step"] >= start]
    worst = compare(tail, second, "restart vs uninterrupted", 1e-15)
    print(f"ok: restart at step {start}: {len(second)} rows equal to the uninterrupted run to {worst:.2g} "
          f"(coverage at the end {second[-1]['c_theta1']:.6g})")


def ranks(args):
    one = shear(args, BOTH, "log.np1")
    two = shear(args, BOTH, "log.np2", np=2)
    worst = compare(one, two, "1 vs 2 MPI ranks", 1e-12)
    print(f"ok: 1 and 2 MPI ranks agree to {worst:.2g} over {len(one)} rows (coverage at the end "
          f"{one[-1]['c_theta1']:.6g})")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=("limits", "decay", "restart", "ranks"))
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--tolerance", type=float, default=0.02)
    args = parser.parse_args()
    fresh_dir(args.workdir)
    {"limits": limits, "decay": decay, "restart": restart, "ranks": ranks}[args.mode](args)


if __name__ == "__main__":
    main()
