#!/usr/bin/env python3
"""pair runin/asperity against LAMMPS's own pair granular (hertz/material + tangential mindlin, no damping).

  granular_match.py --lmp LMP --workdir DIR [--rotate no|yes] [--torques no|yes] [--tol 1e-10]

Runs tests/lammps/decks/in.granular_match twice with the same binary (style runin and style granular:
wear no, reshape no, friction coulomb with mu_s = mu_k, d_c = 0, e = 1, against hertz/material E 0 nu
tangential mindlin NULL 0 mu) on a dense polydisperse packing with thermal velocities and spins, and
requires per-atom forces (and with --torques yes torques) to agree within tol times the largest
component of the stock run, at every dump (steps 0, 50, ..., 200). Also requires the same atoms and
contact counts, and that both the stick and the slip branch of the Mindlin spring are exercised.

--rotate no integrates with fix nve: the random spins stay constant but enter the tangential relative
velocity, so the contact frames rotate. Torques are then reported, not checked: pair granular applies
them at the lever arm R_i - delta/2, pair runin/asperity at R_i (as pair gran/*), a difference of order
delta/R. --rotate yes integrates the spins (fix nve/sphere): with different torques the spins, and
then the forces, separate, so it needs the same lever arm in both styles.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.granular_match")


def dump_snapshots(path):
    """{step: {id: (fx, fy, fz, tqx, tqy, tqz)}} of a dump custom id fx fy fz tqx tqy tqz."""
    snapshots, lines, k = {}, open(path).read().splitlines(), 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step, natoms = int(lines[k + 1]), int(lines[k + 3])
            rows = lines[k + 9:k + 9 + natoms]
            snapshots[step] = {int(r.split()[0]): tuple(float(w) for w in r.split()[1:7]) for r in rows}
            k += 9 + natoms
        else:
            k += 1
    return snapshots


def difference(runin, stock, columns):
    """(max, median) over atoms of max_k |runin - stock| / max |stock| for the given columns."""
    scale = max(abs(values[c]) for values in stock.values() for c in columns)
    if scale == 0.0:
        return 0.0, 0.0
    per_atom = sorted(max(abs(runin[tag][c] - stock[tag][c]) for c in columns) / scale for tag in stock)
    return per_atom[-1], per_atom[len(per_atom) // 2]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--rotate", choices=("no", "yes"), default="no")
    parser.add_argument("--torques", choices=("no", "yes"), default="no")
    parser.add_argument("--tol", type=float, default=1e-10)
    args = parser.parse_args()
    fresh_dir(args.workdir)

    logs = {}
    for style in ("granular", "runin"):
        logs[style] = run_lammps(args, DECK, {"style": style, "rotate": args.rotate}, log=f"log.{style}")
    thermo = {style: thermo_blocks(text)[-1] for style, text in logs.items()}
    dumps = {style: dump_snapshots(os.path.join(args.workdir, f"forces.{style}.dump")) for style in logs}

    steps = sorted(dumps["granular"])
    if steps != sorted(dumps["runin"]) or len(steps) < 2:
        fail(f"dumped steps differ or too few: granular {steps}, runin {sorted(dumps['runin'])}")
    for row_granular, row_runin in zip(thermo["granular"], thermo["runin"]):
        if row_granular["Atoms"] != row_runin["Atoms"] or row_granular["c_ncontact"] != row_runin["c_ncontact"]:
            fail(f"step {row_runin['Step']:.0f}: atoms/contacts differ: granular {row_granular['Atoms']:.0f}/"
                 f"{row_granular['c_ncontact']:.0f}, runin {row_runin['Atoms']:.0f}/{row_runin['c_ncontact']:.0f}")
    # the scene must exercise both branches of the spring (stick fraction 1 at step 0: no history yet)
    stick = [row["v_stick"] for row in thermo["runin"][1:]]
    if not stick or not all(0.05 < s < 0.95 for s in stick):
        fail(f"stick fraction {stick}: the scene does not exercise both stick and slip")
    print(f"{len(dumps['granular'][steps[0]])} atoms, contacts (2 x pairs) "
          f"{[int(row['c_ncontact']) for row in thermo['runin']]}, stick fraction {stick}")

    worst = 0.0
    for step in steps:
        runin, stock = dumps["runin"][step], dumps["granular"][step]
        if set(runin) != set(stock):
            fail(f"step {step}: the two dumps hold different atom IDs")
        force_max, force_median = difference(runin, stock, (0, 1, 2))
        torque_max, torque_median = difference(runin, stock, (3, 4, 5))
        print(f"step {step:4d}: force max {force_max:.3g} median {force_median:.3g}; "
              f"torque max {torque_max:.3g} median {torque_median:.3g}"
              + ("" if args.torques == "yes" else " (torques not checked: lever arm R vs R - delta/2)"))
        worst = max(worst, force_max, torque_max if args.torques == "yes" else 0.0)
        if force_max > args.tol:
            fail(f"step {step}: per-atom forces differ by {force_max:.3g} of the largest force (tol {args.tol:g})")
        if args.torques == "yes" and torque_max > args.tol:
            fail(f"step {step}: per-atom torques differ by {torque_max:.3g} of the largest torque (tol {args.tol:g})")
    print(f"PASS: pair runin/asperity matches pair granular mindlin to {worst:.3g} (tol {args.tol:g})")


if __name__ == "__main__":
    main()
