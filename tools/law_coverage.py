#!/usr/bin/env python3
"""How far below its state law's grid an element looks: the share of its law lookups below each given pressure.

  law_coverage.py --runin RUNIN --element ELEMENT --case CASE [--law LAW] --workdir DIR P [P ...]

Runs the element (journal-bearing, piston-ring, pin-on-disk) on its case once per pressure P below the law's lowest
grid pressure p0, each time with a copy of the law that has one more row at P: friction and surface state those of
the p0 row, the fields the reader keeps proportional to p (wear rates, area and contact fractions) scaled by P / p0.
Between P and p0 the reader's power-law interpolation then gives exactly what out_of_range = "archard" gives below
p0 (the same friction, wear ~ p), so the run is the case's own and the summary's count of lookups clamped below P
is the count of its lookups at p < P. Prints, per P, that count over all lookups (the summary's 'law lookups').
Used for the coverage numbers of doc/state_law_continuum.md ("Out-of-range policy").
"""
import argparse
import copy
import json
import os
import re
import subprocess
import sys

PROPORTIONAL = {"wear_rate", "counterface_wear_rate", "area_fraction", "contact_fraction"}  # as StateLaw


def law_with_row(law, pressure):
    out = copy.deepcopy(law)
    scale = pressure / law["pressure"][0]
    out["pressure"] = [pressure] + law["pressure"]
    for name, bands in out["fields"].items():
        for band, rows in bands.items():
            first = [v * scale for v in rows[0]] if name in PROPORTIONAL else list(rows[0])
            bands[band] = [first] + rows
    acceleration = out.get("samples", {}).get("acceleration")
    if isinstance(acceleration, list):
        out["samples"]["acceleration"] = [acceleration[0]] + acceleration
    return out


def lookups(runin, element, case, law_path, out):
    result = subprocess.run([runin, element, case, "--law", law_path, "--no-plot", "--output-dir", out],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"law_coverage: {element} failed (exit {result.returncode}): {result.stderr.strip()}")
    found = re.search(r"law lookups\s+(\d+) lookups: (\d+) clamped below p = (\S+) Pa", result.stdout)
    if not found:
        sys.exit(f"law_coverage: no 'law lookups' line in the {element} summary")
    return int(found.group(1)), int(found.group(2))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--element", required=True, choices=["journal-bearing", "piston-ring", "pin-on-disk"])
    ap.add_argument("--case", required=True)
    ap.add_argument("--law", help="the law to extend (default: the case's friction.law)")
    ap.add_argument("--workdir", required=True)
    ap.add_argument("pressures", nargs="+", type=float)
    a = ap.parse_args()
    law_path = a.law
    if not law_path:
        import tomllib
        with open(a.case, "rb") as f:
            named = tomllib.load(f)["friction"]["law"]
        source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
        tried = [os.path.join(os.path.dirname(a.case), named), named, os.path.join(source, named)]  # as runin
        law_path = next((p for p in tried if os.path.isfile(p)), None)
        if not law_path:
            sys.exit(f"law_coverage: the case's friction.law {named} is not found (tried {', '.join(tried)})")
    with open(law_path) as f:
        law = json.load(f)
    os.makedirs(a.workdir, exist_ok=True)
    total, below = lookups(a.runin, a.element, a.case, os.path.abspath(law_path), os.path.join(a.workdir, "law"))
    p0 = law["pressure"][0]
    print(f"{a.element}: {below} of {total} lookups ({100 * below / total:.2f} %) below the law's p0 = {p0:.6g} Pa")
    for p in sorted(a.pressures, reverse=True):
        if not 0.0 < p < p0:
            sys.exit(f"law_coverage: pressure {p:g} Pa must be in (0, {p0:g}) Pa, below the law's grid")
        extended = os.path.join(a.workdir, f"law_{p:.6g}.json")
        with open(extended, "w") as f:
            json.dump(law_with_row(law, p), f)
        n, k = lookups(a.runin, a.element, a.case, extended, os.path.join(a.workdir, f"run_{p:.6g}"))
        if n != total:
            print(f"  (this run made {n} lookups)")
        print(f"{a.element}: {k} of {n} lookups ({100 * k / n:.2f} %) below p = {p:.6g} Pa")


if __name__ == "__main__":
    main()
