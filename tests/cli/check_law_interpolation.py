#!/usr/bin/env python3
"""Interpolation of the state law between pressures against a direct cell run (state-law verification).

  check_law_interpolation.py --runin RUNIN --lmp LMP --reader READER --workdir DIR

Builds a law with `runin homogenise` on the shipped cell (inputs/in.rve_wall, 1024 summits, one seed) at two
pressures a grid step of 2.43 apart (3.0 and 7.3 MPa, the step of the shipped 8-point grid), runs the cell
directly at the geometric midpoint (4.68 MPa, same seed, same cell wear rate per distance), and compares the
law, as the continuum reads it (coupling::StateLaw through runin_read_state_law), with the direct run: mu_body(h)
and Rq(h) within 3 % at every h in [depth/10, depth].
"""
import argparse
import json
import math
import os
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tests", "lammps"))
from run_deck import mpi_env  # noqa: E402  (Open MPI as root, oversubscription, one thread per rank)
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from state_law import sample_at_depth, sample_rows  # noqa: E402  (homogenise's reduction of a sample)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402
P1, P2, PMID = 3.0e6, 7.3e6, (3.0e6 * 7.3e6) ** 0.5
DEPTH, SEED, NSIDE, DEPTH_POINTS = 3.0e-8, 4711, 32, 16
LIMIT = 0.03


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{' '.join(command[:3])} ... exited {result.returncode}\n{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    return result.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--reader", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    work = os.path.abspath(a.workdir)
    os.makedirs(work, exist_ok=True)
    material = os.path.join(SOURCE, "potentials", "Steel1020.runin")
    case = os.path.join(work, "interp.toml")
    with open(case, "w") as f:
        f.write(f'''title = "interpolation check"
[material]
file = "{material}"
rough = "Steel1020"
counterface = "Steel1020"
[surface]
R = 1.0e-4
sigma = 2.0e-7
spacing = 2.0e-5
nside = {NSIDE}
[sliding]
speed = 0.1
[grid]
pressure_min = {P1}
pressure_max = {P2}
pressures = 2
seeds = 1
acceleration = [{1e8 / P1}, {1e8 / P2}]
depth = {DEPTH}
depth_points = {DEPTH_POINTS}
nslide = 60000
nout = 50
''')
    law = os.path.join(work, "law.json")
    run([a.runin, "homogenise", case, "--output", law, "--cache-dir", os.path.join(work, "cache"), "--np", "2",
         "--lmp", a.lmp, "--deck", os.path.join(SOURCE, "inputs", "in.rve_wall")], work)
    with open(law) as f:
        seeds = json.load(f)["samples"]["seeds"]
    direct = "direct.dat"
    run([a.lmp, "-in", os.path.join(SOURCE, "inputs", "in.rve_wall"), "-log", "log.direct", "-screen", "none",
         "-var", "material", material, "-var", "nside", str(NSIDE), "-var", "pressure", repr(PMID),
         "-var", "seed", str(seeds[0]), "-var", "accel", repr(1e8 / PMID), "-var", "depth", repr(DEPTH),
         "-var", "nout", "50", "-var", "nslide", "60000", "-var", "out", direct], work)
    # the direct run reduced as `runin homogenise` reduces a sample (mu_body: the least-squares line over half a
    # grid step of the law's depths; Rq: linear between rows), so that law and run mean the same thing at h
    rows = sample_rows(os.path.join(work, direct))
    grid = [DEPTH * (0.1 + 0.9 * i / 18) for i in range(19)]
    step = DEPTH / (DEPTH_POINTS - 1)

    def direct_at(h, column):
        value = sample_at_depth(rows, column, h, step, fit=column == 4)
        if math.isnan(value):
            fail(f"direct run does not reach h = {h:g} m")
        return value

    lookups = json.loads(run([a.reader, law, repr(PMID)] + [repr(h) for h in grid], work))["lookup"]
    worst = {}
    for key, column in (("mu_body", 4), ("rq", 5)):
        rel = [lk[key] / direct_at(lk["worn_depth"], column) - 1.0 for lk in lookups]
        worst[key] = max(abs(x) for x in rel)
        print(f"{key}: law at {PMID:.4g} Pa (from {P1:g} and {P2:g} Pa) vs direct cell, relative: " +
              " ".join(f"{x:+.4f}" for x in rel))
    for key, value in worst.items():
        if not value <= LIMIT:
            fail(f"{key}: the law between grid pressures misses the direct cell by {value:.4f} (limit {LIMIT})")
    print(f"PASS: worst mu_body {worst['mu_body']:.4f}, rq {worst['rq']:.4f} (limit {LIMIT})")


if __name__ == "__main__":
    main()
