#!/usr/bin/env python3
"""One elastic-plastic asperity on fix runin/wall, loaded, unloaded and reloaded (deck in.wall_plastic_cycle),
against the published closed forms coded here independently of the C++ kernels (stdlib only):

  loading    Jackson & Green (2005): Hertz up to omega_c, their fit from 1.9 omega_c
  residual   Etsion, Kligerman & Kadin (2005): omega_res / omega_max = (1 - x^-0.28)(1 - x^-0.69)
  unloading  P = P_max ((omega - omega_res) / (omega_max - omega_res))^n, n = 1.5 x^-0.0331
  reload     retraces the unloading curve up to omega_max, then loads on the JG curve again
The asperity keeps its largest interference under the flat (fix runin/wall), so its summit, lowered by
omega_res, is explained by its own history and no elastic flat-punch reload applies.

--host pair runs the same summit as two asperities of radius 2R (R* = R) in pair runin/asperity (deck
in.pair_plastic_cycle): they separate at the end of the unloading, so the reload is a new contact without
history on flattened summits. It must follow the same curves to 1e-9, and the same force-interference curve as
the wall's run row by row (one reload physics for both hosts; doc/elastic_plastic_contact.md, "Reloading").

  plastic_cycle.py --lmp LMP --workdir DIR [--normal hertz] [--host wall|pair]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.wall_plastic_cycle")
PAIR_DECK = os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.pair_plastic_cycle")
# the deck's values: R, E*, S_y and nu of the yielding steel asperity, first depth, reload factor, steps per leg
R, E_STAR, S_Y, NU = 2.0e-5, 1.092e11, 350.0e6, 0.29
DEPTH, RELOAD, NSTEPS = 1.3e-8, 1.5, 400
TOLERANCE = 1e-9


def critical():
    c = 1.295 * math.exp(0.736 * NU)
    omega_c = (math.pi * c * S_Y / (2.0 * E_STAR)) ** 2 * R
    p_c = 4.0 / 3.0 * (R / E_STAR) ** 2 * (c * math.pi * S_Y / 2.0) ** 3
    return c, omega_c, p_c


def hertz(omega):
    return 4.0 / 3.0 * E_STAR * math.sqrt(R) * omega ** 1.5 if omega > 0 else 0.0


def jackson_green(omega):
    """JG loading force for omega >= 1.9 omega_c (their fit) and Hertz below omega_c."""
    c, omega_c, p_c = critical()
    x = omega / omega_c
    if x <= 1.0:
        return hertz(omega)
    b = 0.14 * math.exp(23.0 * S_Y / E_STAR)
    a = math.sqrt(R * omega) * (x / 1.9) ** (b / 2.0)
    h_g = 2.84 * (1.0 - math.exp(-0.82 * (a / R) ** -0.7))
    return p_c * (math.exp(-0.25 * x ** (5.0 / 12.0)) * x ** 1.5
                  + 4.0 * h_g / c * (1.0 - math.exp(-x ** (5.0 / 9.0) / 25.0)) * x)


def residual(omega_max):
    x = omega_max / critical()[1]
    return (1.0 - x ** -0.28) * (1.0 - x ** -0.69) * omega_max if x > 1.0 else 0.0


def unloading(omega, omega_max):
    x = omega_max / critical()[1]
    res = residual(omega_max)
    if omega <= res:
        return 0.0
    n = 1.5 * x ** -0.0331
    return jackson_green(omega_max) * ((omega - res) / (omega_max - res)) ** n


def check(what, got, want, scale=None):
    scale = abs(want) if scale is None else scale
    if abs(got - want) > TOLERANCE * max(scale, 1e-300):
        fail(f"{what}: got {got!r}, closed form {want!r} (relative error {abs(got - want) / scale:.3e})")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--normal", default="elastic/plastic", choices=("elastic/plastic", "hertz"))
    parser.add_argument("--host", default="wall", choices=("wall", "pair"))
    parser.add_argument("--omega-max", type=float, default=None,
                        help="first loading to this omega* = omega_max / omega_c (default: the decks' depth)")
    args = parser.parse_args()
    fresh_dir(args.workdir)
    global DEPTH
    if args.omega_max is not None:
        DEPTH = args.omega_max * critical()[1]
    depth = {"depth": repr(DEPTH)}
    log = run_lammps(args, DECK, {"normal": args.normal, **depth}, log="log.wall")
    rows = thermo_blocks(log)[0]
    _, omega_c, _ = critical()
    if args.host == "pair":
        wall = rows
        rows = []
        for row in thermo_blocks(run_lammps(args, PAIR_DECK, depth, log="log.pair"))[0]:
            # the wall's columns: force, wall position (omega = R - position), summit drop, flat
            rows.append({"Step": row["Step"], "f_wall[3]": row["v_fz2"], "f_wall[4]": R - row["v_omega"],
                         "v_drop": row["v_drop"], "v_flat": None})
        if len(rows) != len(wall):
            fail(f"pair run has {len(rows)} rows, the wall's {len(wall)}")
        scale = jackson_green(DEPTH)
        worst = 0.0
        for p, w in zip(rows, wall):
            check(f"pair vs wall interference at step {p['Step']:.0f}", R - p["f_wall[4]"], R - w["f_wall[4]"],
                  scale=DEPTH)
            check(f"pair vs wall force at step {p['Step']:.0f}", p["f_wall[3]"], w["f_wall[3]"], scale=scale)
            worst = max(worst, abs(p["f_wall[3]"] - w["f_wall[3]"]) / scale)
        print(f"pair and wall: {len(rows)} rows, largest force difference {worst:.3e} F(omega_max)")

    if args.normal == "hertz":
        for row in rows:
            check(f"Hertz force at step {row['Step']:.0f}", row["f_wall[3]"], hertz(R - row["f_wall[4]"]),
                  scale=hertz(DEPTH))
            if row["v_drop"] != 0.0:
                fail(f"the elastic (Hertz) asperity was flattened: drop {row['v_drop']!r} at step {row['Step']:.0f}")
        print(f"ok: Hertz throughout ({len(rows)} rows), no flattening")
        return

    counts = {"hertz": 0, "fit": 0, "ekk": 0, "open": 0, "reload ekk": 0, "reload plastic": 0}
    omega_max, drop, leg, previous = 0.0, 0.0, 0, 0.0
    for row in rows:
        step, force = row["Step"], row["f_wall[3]"]
        omega = R - row["f_wall[4]"]    # interference of the intact sphere (the atom sits at z = 0)
        # legs from the wall's motion (thermo every step): down, up, down again
        if (leg == 0 and omega < previous) or (leg == 1 and omega > previous):
            leg += 1
        previous = omega
        scale = jackson_green(DEPTH)
        if leg == 0:
            x = omega / omega_c
            if x <= 1.0:
                check(f"Hertz below omega_c, step {step:.0f}", force, hertz(omega), scale)
                counts["hertz"] += 1
            elif x >= 1.9:
                check(f"JG loading at omega* = {x:.3g}, step {step:.0f}", force, jackson_green(omega), scale)
                counts["fit"] += 1
            omega_max = max(omega_max, omega)
            continue
        if drop == 0.0:    # first row after the deepest point: the summit keeps the EKK residual
            drop = residual(omega_max)
            check("summit drop after loading vs EKK residual interference", row["v_drop"], drop)
            if row["v_flat"] is not None:
                check("flat radius of the flattened summit", row["v_flat"], math.sqrt(2.0 * R * drop - drop * drop))
            print(f"loading to omega_max = {omega_max:.4e} m = {omega_max / omega_c:.2f} omega_c: "
                  f"F_max {jackson_green(omega_max):.5e} N, residual {drop:.4e} m "
                  f"({drop / omega_max:.4f} omega_max)")
        if omega <= omega_max:
            want = unloading(omega, omega_max)
            check(f"{'reload' if leg == 2 else 'unloading'} at omega = {omega:.4e}, step {step:.0f}", force, want,
                  scale)
            check(f"summit drop while below omega_max, step {step:.0f}", row["v_drop"], drop)
            if want == 0.0:
                counts["open"] += 1
            else:
                counts["reload ekk" if leg == 2 else "ekk"] += 1
        else:
            # beyond the earlier maximum: plastic loading again, the summit sinks to the new residual
            check(f"JG reloading beyond omega_max, step {step:.0f}", force, jackson_green(omega), scale)
            check(f"summit drop beyond omega_max, step {step:.0f}", row["v_drop"], residual(omega))
            counts["reload plastic"] += 1
    for name in ("hertz", "fit", "ekk", "open", "reload ekk", "reload plastic"):
        if counts[name] < 3:
            fail(f"too few rows checked in the '{name}' branch: {counts}")
    print(f"ok: rows per branch {counts}")


if __name__ == "__main__":
    main()
