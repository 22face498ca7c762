#!/usr/bin/env python3
"""The papers of the models a deck runs are in LAMMPS's citation list (stdlib only).

  citations.py --lmp LMP --workdir DIR

Each case runs a shipped deck briefly with -cite log.cite and checks that log.cite holds the BibTeX keys of the
models the deck uses and none of the models it does not (runin_citations.h):
  - inputs/in.runin_wall (fix runin/wall, elastic/plastic, strength friction, Archard): Jackson-Green,
    Etsion-Kligerman-Kadin, Mindlin, Archard, Greenwood-Williamson;
  - the same with -var normal hertz -var friction coulomb: Hertz instead of Jackson-Green and EKK;
  - inputs/in.rough_slider (pair runin/asperity) with -var friction brizmer -var wear no: Jackson-Green, EKK,
    Mindlin, Brizmer-Kligerman-Etsion; no Archard, no Greenwood-Williamson.
The log file lists each entry's first line (without -cite it holds the full entries: LAMMPS's default).
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, mpi_env  # noqa: E402

KEYS = ["Hertz1882", "JacksonGreen2005", "EtsionKligermanKadin2005", "Mindlin1949", "BrizmerKligermanEtsion2007",
        "Archard1953", "GreenwoodWilliamson1966", "Tabor1959"]
WALL = ["-var", "nload", "100", "-var", "nslide", "100", "-var", "thermo_every", "50"]
SLIDER = ["-var", "nsettle", "100", "-var", "nslide", "100", "-var", "thermo_every", "50", "-var", "coeffs",
          os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")]
CASES = [
    ("wall", "in.runin_wall", WALL,
     {"JacksonGreen2005", "EtsionKligermanKadin2005", "Mindlin1949", "Archard1953", "GreenwoodWilliamson1966"}),
    ("wall_hertz", "in.runin_wall", WALL + ["-var", "normal", "hertz", "-var", "friction", "coulomb"],
     {"Hertz1882", "Mindlin1949", "Archard1953", "GreenwoodWilliamson1966"}),
    ("slider_brizmer", "in.rough_slider", SLIDER + ["-var", "friction", "brizmer", "-var", "wear", "no"],
     {"JacksonGreen2005", "EtsionKligermanKadin2005", "Mindlin1949", "BrizmerKligermanEtsion2007"}),
]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    for name, deck, variables, expected in CASES:
        workdir = os.path.join(os.path.abspath(args.workdir), name)
        fresh_dir(workdir)
        command = [args.lmp, "-in", os.path.join(SOURCE_DIR, "inputs", deck), "-log", "log.lammps", "-screen", "none",
                   "-cite", "log.cite"] + variables
        result = subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True, text=True)
        if result.returncode != 0:
            fail(f"{name}: LAMMPS exited with {result.returncode}\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
        cite_path = os.path.join(workdir, "log.cite")
        if not os.path.exists(cite_path):
            fail(f"{name}: no log.cite written")
        cite = open(cite_path).read()
        log = open(os.path.join(workdir, "log.lammps")).read()
        found = {key for key in KEYS if "{" + key + "," in cite}
        if found != expected:
            fail(f"{name}: log.cite holds {sorted(found)}, expected {sorted(expected)}")
        # with -cite FILE the log file lists each entry's first line ("- RunIn ...")
        listed = [line for line in log.splitlines() if line.startswith("- RunIn ")]
        if len(listed) != len(expected):
            fail(f"{name}: the log file lists {listed}, expected {len(expected)} RunIn entries")
        print(f"{name}: log.cite holds {', '.join(sorted(found))}")
    print("PASS")


if __name__ == "__main__":
    main()
