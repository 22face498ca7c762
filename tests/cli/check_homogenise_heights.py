#!/usr/bin/env python3
"""`runin homogenise` with a summit list (surface.heights) on the cell inputs/in.rve_wall.

  check_homogenise_heights.py --runin RUNIN --lmp LMP --workdir DIR

A 6 x 6 summit list (tests/data/cli/homogenise_heights_36.txt) at 2 pressures, one seed: the law is written and
records the list (path and SHA-256); its Rq at h = 0 is the list's RMS height within 25 % (the loading flattens
the highest summits a little); a rerun costs nothing; changing one height of the list reruns every sample (the
list's content is part of each sample's cache key).
"""
import argparse
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tests", "lammps"))
from run_deck import mpi_env  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402
LIST = os.path.join(SOURCE, "tests", "data", "cli", "homogenise_heights_36.txt")


def run(a, case, law):
    result = subprocess.run([a.runin, "homogenise", case, "--output", law, "--cache-dir",
                             os.path.join(a.workdir, "cache"), "--np", "2", "--lmp", a.lmp, "--deck",
                             os.path.join(SOURCE, "inputs", "in.rve_wall")],
                            cwd=a.workdir, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"runin homogenise exited {result.returncode}: {result.stderr[-1500:]}")
    return result.stderr + result.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    a.workdir = os.path.abspath(a.workdir)
    shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir)
    heights = os.path.join(a.workdir, "heights.txt")
    shutil.copy(LIST, heights)
    case = os.path.join(a.workdir, "case.toml")
    with open(case, "w") as f:
        f.write(f'''title = "summit list"
[material]
file = "{os.path.join(SOURCE, 'potentials', 'Steel1020.runin')}"
rough = "Steel1020"
counterface = "Steel1020"
[surface]
nside = 6
heights = "heights.txt"
[grid]
pressure_min = 1.0e6
pressure_max = 4.0e6
pressures = 2
seeds = 1
acceleration = 1000.0
depth = 2.0e-9
depth_points = 5
nslide = 4000
nout = 10
''')
    law_path = os.path.join(a.workdir, "law.json")
    run(a, case, law_path)
    with open(law_path) as f:
        law = json.load(f)
    with open(heights, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    surface = law["surface"]
    # portable: relative to the source tree when inside it, else the name alone (never this machine's path)
    real, tree = os.path.realpath(heights), os.path.realpath(SOURCE)
    recorded = os.path.relpath(real, tree) if real.startswith(tree + os.sep) else os.path.basename(real)
    if surface.get("heights") != recorded or surface.get("heights_sha256") != sha:
        fail(f"the law does not record the summit list: {surface}")
    values = []
    with open(heights) as f:
        rows = [line.split() for line in f if line.strip() and not line.startswith("#")]
    values = [float(r[1]) for r in rows[1:]]
    mean = sum(values) / len(values)
    rms = math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))
    rq0 = law["fields"]["rq"]["mean"][0][0]
    print(f"Rq at h = 0: {rq0:.4g} m, the list's RMS {rms:.4g} m")
    if abs(rq0 / rms - 1.0) > 0.25:
        fail(f"Rq at h = 0 ({rq0:.4g} m) is not the list's RMS height ({rms:.4g} m) within 25 %")
    if "0 samples to run" not in run(a, case, law_path):
        fail("a rerun with the same list ran samples again")
    rows[1][1] = repr(float(rows[1][1]) + 1e-8)
    with open(heights, "w") as f:
        f.write("# changed\n" + "\n".join(" ".join(r) for r in rows) + "\n")
    if "2 samples to run" not in run(a, case, law_path):
        fail("changing the summit list did not rerun the samples")
    print("PASS: the law records the list, a rerun is cached, a changed list reruns every sample")


if __name__ == "__main__":
    main()
