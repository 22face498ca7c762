#!/usr/bin/env python3
"""Static friction of an elastic-plastic asperity (deck in.wall_brizmer, friction_model brizmer) against
Brizmer, Kligerman & Etsion (2007): at break-away |F_t| = mu_s P with mu_s = 0.27 coth(0.27 (P / L_c)^0.35),
L_c = (8.88 nu - 10.13 (nu^2 + 0.089)) P_c (Brizmer et al. 2006), P_c of Jackson & Green (2005); after
break-away the limit falls towards the kinetic strength tau_s A_r + groove ploughing (stdlib only).

  brizmer_static.py --lmp LMP --workdir DIR
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.wall_brizmer")
R, E_STAR, S_Y, NU = 2.0e-5, 1.092e11, 350.0e6, 0.29    # the deck's asperity


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    fresh_dir(args.workdir)
    rows = thermo_blocks(run_lammps(args, DECK))[0]
    c = 1.295 * math.exp(0.736 * NU)
    p_c = 4.0 / 3.0 * (R / E_STAR) ** 2 * (c * math.pi * S_Y / 2.0) ** 3
    l_c = (8.88 * NU - 10.13 * (NU * NU + 0.089)) * p_c
    peak = max(rows, key=lambda row: abs(row["f_wall[1]"]))
    load = peak["f_wall[3]"]
    mu_s = 0.27 / math.tanh(0.27 * (load / l_c) ** 0.35)
    got = abs(peak["f_wall[1]"])
    if abs(got - mu_s * load) > 1e-9 * mu_s * load:
        fail(f"break-away force {got!r} N vs Brizmer mu_s P = {mu_s * load!r} N (P/L_c = {load / l_c:.4g})")
    sliding = [row for row in rows if row["Step"] > peak["Step"]]
    forces = [abs(row["f_wall[1]"]) for row in sliding]
    kinetic = (sliding[-1]["c_fric[6]"] + sliding[-1]["c_fric[7]"]) * sliding[-1]["f_wall[3]"]
    if len(forces) < 100 or any(b > a * (1 + 1e-12) for a, b in zip(forces, forces[1:])):
        fail("after break-away the friction force must fall monotonically towards the kinetic strength")
    if not kinetic < forces[-1] < got:
        fail(f"friction {forces[-1]!r} N after break-away not between kinetic {kinetic!r} N and static {got!r} N")
    print(f"ok: P = {load:.5e} N = {load / l_c:.3f} L_c, break-away mu_s = {got / load:.6f} "
          f"(Brizmer {mu_s:.6f}), kinetic strength mu = {kinetic / load:.4f}")


if __name__ == "__main__":
    main()
