#!/usr/bin/env python3
"""The deep steel law with its grid continued below 1.26 MPa in larger cells: what it covers and where it holds.

  check_extended_law.py --runin RUNIN --workdir DIR [--case CASE]

Builds tests/data/state_law/steel_mild_deep_extended.toml (the shipped deep case plus grid.extra_pressures 0.570 and
0.847 MPa in 48^2 and 40^2 cells; about 8 min cold on 2 cores, its grid samples shared with the deep case's cache),
runs the dry journal bearing (inputs/journal_bearing_state_law.toml) on it and prints:
  - the bearing's law lookups, those below the law's lowest pressure, and its deepest worn depth;
  - per extra pressure: the seed-mean mu_body over the depths the bearing wears and over the deepest four depths,
    the seeds' mean contacts and their output rows with no contact at all.
Asserted (doc/state_law_continuum.md, "Out-of-range policy"): the bearing makes no lookup below the law's grid; at
its depths both extra rows slide within 2 % of Tabor's junction value of the law's f (plastic junctions, as the
grid); the grid rows are those of the 8-pressure law's samples (the same keys). Reported, not asserted: the
0.570 MPa row past ~10 nm (the reason the law is not shipped).
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(SOURCE, "tests", "data", "state_law", "steel_mild_deep_extended.toml")
BEARING = os.path.join(SOURCE, "inputs", "journal_bearing_state_law.toml")


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{' '.join(command)} exited {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result.stdout


def columns(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(x) for x in line.split()])
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runin", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--case", default=CASE)
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    law_path, cache = os.path.join(args.workdir, "law.json"), os.path.join(args.workdir, "cache")
    run([args.runin, "homogenise", args.case, "--output", law_path, "--cache-dir", cache, "--np", "2"])
    with open(law_path) as f:
        law = json.load(f)
    summary = run([args.runin, "journal-bearing", BEARING, "--law", law_path, "--no-plot", "--output-dir",
                   os.path.join(args.workdir, "bearing")])
    found = re.search(r"law lookups\s+(\d+) lookups: (\d+) clamped below p = (\S+) Pa", summary)
    depth = re.search(r"lower h\s+mean \S+ m, max (\S+) m", summary)
    if not found or not depth:
        fail(f"no 'law lookups' or 'lower h' line in the bearing's summary:\n{summary}")
    lookups, below, edge, deepest = int(found.group(1)), int(found.group(2)), float(found.group(3)), float(depth.group(1))
    print(f"journal bearing: {lookups} lookups, {below} below p = {edge:.4g} Pa; deepest worn depth {deepest * 1e9:.3g} nm")
    if below != 0:
        fail(f"the bearing still looks below the extended grid: {below} of {lookups}")

    f = law["samples"]["contact"]["f"]
    alpha = law["samples"]["contact"].get("alpha", 12.0)
    tabor = f / math.sqrt(alpha * (1.0 - f * f))
    depths = law["worn_depth"]
    worn = [j for j, h in enumerate(depths) if h <= max(deepest, depths[1])]
    nside = law["surface"]["nside_at_pressure"]
    for ip, p in enumerate(law["pressure"]):
        if nside[ip] == law["surface"]["nside"]:
            continue
        mu = law["fields"]["mu_body"]["mean"][ip]
        shallow = [mu[j] for j in worn]
        deep = mu[-4:]
        contacts, empty, first_empty = [], [], []
        for sample in (s for s in law["samples"]["list"] if s["pressure"] == p):
            rows = columns(os.path.join(cache, sample["key"], "out.dat"))[1:]
            contacts.append(sum(r[10] for r in rows) / len(rows))
            none = [r[2] for r in rows if r[10] == 0.0]
            empty.append(len(none))
            first_empty.append(min(none) * 1e9 if none else float("nan"))
        print(f"p = {p:.4g} Pa ({nside[ip]}^2 summits): mu_body at the bearing's depths {min(shallow):.4f}-"
              f"{max(shallow):.4f} (Tabor {tabor:.4f}); at h = {depths[-4] * 1e9:.3g}-{depths[-1] * 1e9:.3g} nm "
              f"{min(deep):.4f}-{max(deep):.4f}; contacts {min(contacts):.1f}-{max(contacts):.1f} on average, "
              f"rows with none {min(empty)}-{max(empty)} per seed" +
              (f", the first at h = {min(h for h in first_empty if h == h):.3g} nm" if any(n > 0 for n in empty) else ""))
        worst = max(abs(m / tabor - 1.0) for m in shallow)
        if worst > 0.02:
            fail(f"p = {p:.4g} Pa: mu_body at the bearing's depths {worst:.3%} from Tabor's {tabor:.4f}")
    print("PASS")


if __name__ == "__main__":
    main()
