#!/usr/bin/env python3
"""The coefficient grammar's forms give the same contact, bit for bit (ctest lammps.coeff_forms, liggghts.coeff_forms).

  coeff_forms.py --binary BIN --workdir DIR [--liggghts] [--friction junction]

Runs tests/lammps/decks/in.coeff_forms with keywords 0 (pair_coeff's explicit values and options, fix runin/wall's
value groups) and keywords 1 (the keyword block in pair_coeff and after the wall's 'coeff') on one host (lmp_runin,
or liggghts_runin with --liggghts). Every thermo row of the two runs must be equal in every printed digit (%.17g), and
the pair and the wall must have carried load and the wall worn (else the comparison would be empty).
--friction junction: the same with Tabor's junction law (JUNCTION_EDITS: pair_coeff's options f and alpha, the wall's
value group 'junction f alpha', the blocks' 'friction junction f alpha'; alpha off its default).
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, mpi_env  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "tests", "lammps", "decks", "in.coeff_forms")


# in.coeff_forms with friction junction: every form of the same f = 0.5, alpha = 10 (each edit must apply once)
JUNCTION_EDITS = [
    ("friction strength 0.5 0.4 2.0e-8 1.0e8 1.0", "friction junction 0.5 10.0", 2),
    ("runin/asperity normal elastic/plastic friction strength", "runin/asperity normal elastic/plastic friction junction",
     1),
    ("tau_s 1.0e8 plough 1.0", "f 0.5 alpha 10.0", 1),
    ("strength 1.0e8 1.0", "junction 0.5 10.0", 1),
]


def deck_for(friction, workdir):
    """The deck of `friction` (strength: in.coeff_forms itself)."""
    if friction == "strength":
        return DECK
    text = open(DECK).read()
    for old, new, count in JUNCTION_EDITS:
        if text.count(old) != count:
            fail(f"in.coeff_forms: '{old}' found {text.count(old)} times, expected {count}")
        text = text.replace(old, new)
    path = os.path.join(workdir, "in.coeff_forms_junction")
    with open(path, "w") as f:
        f.write(text)
    return path


def thermo_lines(text):
    """The thermo rows as printed (strings), each run's after its header."""
    rows, inside = [], False
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            inside = True
        elif line.startswith("Loop time"):
            inside = False
        elif inside and words and words[0].isdigit():
            rows.append(line.strip())
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--liggghts", action="store_true")
    parser.add_argument("--friction", choices=("strength", "junction"), default="strength")
    args = parser.parse_args()
    fresh_dir(args.workdir)
    deck = deck_for(args.friction, args.workdir)
    logs = {}
    for keywords in (0, 1):
        log = os.path.join(args.workdir, f"log.keywords{keywords}")
        command = [args.binary] + (["-st"] if args.liggghts else []) + [
            "-in", deck, "-log", log, "-screen", "none", "-var", "keywords", str(keywords),
            "-var", "liggghts", "1" if args.liggghts else "0"]
        result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
        text = open(log).read() if os.path.exists(log) else ""
        if result.returncode != 0:
            fail(f"keywords {keywords}: {' '.join(command)} exited with {result.returncode}\n{result.stdout[-1500:]}\n"
                 f"{result.stderr[-1500:]}\n{text[-1500:]}")
        logs[keywords] = text
    explicit, block = thermo_lines(logs[0]), thermo_lines(logs[1])
    if not explicit or len(explicit) != len(block):
        fail(f"thermo rows: {len(explicit)} (explicit) and {len(block)} (keyword block)")
    for a, b in zip(explicit, block):
        if a != b:
            fail(f"the forms differ:\n  explicit: {a}\n  keywords: {b}")
    # columns (the deck's thermo_style; LIGGGHTS names them otherwise): 1 normal force, 4 contacts, 11 wall wear
    rows = [[float(word) for word in line.split()] for line in block]
    if not any(row[1] > 0.0 and row[4] == 2 for row in rows):
        fail("the pair never carried load (no row with both contacts)")
    if not rows[-1][11] > 0.0:
        fail("the wall did not wear")
    print(f"ok: {len(explicit)} thermo rows equal in every digit; final wall wear {rows[-1][11]:.17g} m^3")


if __name__ == "__main__":
    main()
