#!/usr/bin/env python3
"""The interface state of a coefficient file on one plastic asperity contact (deck in.interface_shear,
pair_coeff ... file potentials/Steel1020.runin ... interface STATE): m and S_y are read from the file here, and
  - friction strength: at every sheared step the adhesion part over the real area is tau_s = m S_y / sqrt(3)
    (1e-9), and once the slip passed d_c the tangential force is the kinetic limit tau_s A_r + groove ploughing;
  - friction junction: F_t / F_n at gross sliding is Tabor's f / sqrt(alpha (1 - f^2)) with f = m, alpha = 12
(stdlib only).

The same on fix runin/wall (keyword interface, deck in.wall_interface_shear) with --host wall.

  interface_state.py --lmp LMP --workdir DIR --friction strength|junction --states clean oxidised ... [--host wall]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECKS = {"pair": os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.interface_shear"),
         "wall": os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.wall_interface_shear")}
COEFFS = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
ALPHA = 12.0    # the pair's default


def file_values():
    """S_y, d_c and m per state of Steel1020 on itself, read from the coefficient file."""
    yield_strength, d_c, factors = None, None, {}
    for line in open(COEFFS):
        words = line.split("#")[0].split()
        if words[:2] == ["material", "Steel1020"]:
            yield_strength = float(words[6])
        elif words[:1] == ["pair"]:
            d_c = float(words[6])
        elif words[:1] == ["interface"]:
            factors[words[3]] = float(words[4])
    return yield_strength, d_c, factors


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--friction", choices=["strength", "junction"], required=True)
    parser.add_argument("--states", nargs="+", required=True)
    parser.add_argument("--host", choices=["pair", "wall"], default="pair")
    args = parser.parse_args()
    fresh_dir(args.workdir)
    yield_strength, d_c, factors = file_values()
    for state in args.states:
        m = factors[state]
        text = run_lammps(args, DECKS[args.host], {"state": state, "friction": args.friction, "coeffs": COEFFS},
                          log=f"log.{args.host}.{args.friction}.{state}")
        press, shear = thermo_blocks(text)[:2]
        if press[-1]["c_fric[4]"] != 1 or not press[-1]["c_fric[9]"] > 0.0:
            fail(f"{state}: the asperities are not in contact after pressing")
        p_m = press[-1]["c_fric[1]"] / press[-1]["c_fric[9]"]
        if not p_m > 2.0 * yield_strength:
            fail(f"{state}: mean pressure {p_m:.4g} Pa: the junction is not plastic")
        last = shear[-1]
        if last["c_fric[8]"] != 0:
            fail(f"{state}: still sticking after {len(shear) - 1} shear steps")
        fn, ft = last["c_fric[1]"], last["c_fric[2]"]
        if args.friction == "strength":
            tau_s = m * yield_strength / math.sqrt(3.0)
            worst = max(abs(row["c_fric[6]"] * row["c_fric[1]"] / row["c_fric[9]"] - tau_s) / tau_s for row in shear)
            if worst > 1e-9:
                fail(f"{state}: adhesion / real area differs from m S_y / sqrt(3) = {tau_s:.6g} Pa by {worst:.3g}")
            slip = float(shear[-1]["Step"] - shear[0]["Step"]) * 1.0e-9 * 0.1
            if slip < 2.0 * d_c:
                fail(f"{state}: {slip:.3g} m of shear does not pass d_c = {d_c:.3g} m")
            kinetic = (last["c_fric[6]"] + last["c_fric[7]"]) * fn
            error = abs(ft - kinetic) / kinetic
            if error > 1e-9:
                fail(f"{state}: sliding F_t = {ft!r} N vs tau_s A_r + F_pl = {kinetic!r} N ({error:.3g})")
            print(f"ok: {args.host}, strength, {state}: m = {m}, tau_s = {tau_s:.6g} Pa over A_r (worst {worst:.2g}); kinetic "
                  f"F_t / F_n = {ft / fn:.6f} = tau_s / p_m {last['c_fric[6]']:.6f} + ploughing {last['c_fric[7]']:.6f}")
        else:
            want = m / math.sqrt(ALPHA * (1.0 - m * m))
            error = abs(ft / fn - want) / want
            if error > 1e-9:
                fail(f"{state}: F_t / F_n at gross sliding {ft / fn!r} vs Tabor {want!r} with f = m = {m} ({error:.3g})")
            print(f"ok: {args.host}, junction, {state}: f = m = {m}: F_t / F_n = {ft / fn:.6f} (Tabor {want:.6f}, {error:.2g})")


if __name__ == "__main__":
    main()
