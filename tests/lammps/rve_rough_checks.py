#!/usr/bin/env python3
"""The rough-on-rough cell inputs/in.rve_rough and the pipeline's law built on it (state-law verification).

  rve_rough_checks.py interpolation --lmp LMP --workdir DIR
  rve_rough_checks.py cell-size     --lmp LMP --workdir DIR
  rve_rough_checks.py quasi-static  --lmp LMP --workdir DIR

Every sample at physical wear (accel 1: this cell is not acceleration-invariant, doc/rve_cell.md), AISI 1020,
sigma 0.2 um per body. Cell outputs are reduced as `runin homogenise` reduces a sample (tools/state_law.py
sample_at_depth: mu_body by a least-squares line over half a grid step, Rq linear between rows).
interpolation: direct cells at 3.075 MPa, the geometric midpoint of the shipped law's grid pressures 2.11 and
  4.47 MPa, with the law's two seeds and size (48^2 + 47^2 summits), against inputs/state_law_steel_rough.json as
  the continuum reads it: mu_body(h) and Rq(h) within 3 % at the law's depths 2-20 nm (measured 0.91 %, 0.12 %).
cell-size: 5 MPa to h = 12 nm, seed means of 32^2 + 31^2, 48^2 + 47^2 (the pipeline law's) and 64^2 + 63^2 (the full
  law's) summits, 3 seeds, against 128^2 + 127^2 with 2 seeds: each within 3 % in mu_body(h) and Rq(h), h = 1-10 nm.
quasi-static: 48^2 + 47^2 summits (the pipeline law's), 5 MPa, h to 10 nm, at 1 m/s (the deck's speed) and
  0.3 m/s: mu_body(h) and Rq(h) within 3 % at the law's depths 2-10 nm.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps_two_at_a_time  # noqa: E402
sys.path.insert(0, os.path.join(SOURCE_DIR, "tools"))
from state_law import StateLaw, sample_at_depth, sample_rows  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "inputs", "in.rve_rough")
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
LAW = os.path.join(SOURCE_DIR, "inputs", "state_law_steel_rough.json")
LIMIT = 0.03
MU, RQ = 4, 5   # columns: step s h h_cf mu_body rq ...


def run_cells(args, cells):
    """Runs the cells (name, variables) two at a time (2 cores); returns {name: sliding rows}."""
    run_lammps_two_at_a_time(args, DECK, [(name, {"material": MATERIAL, "accel": 1, "nslide": 2000000,
                                                  "out": f"{name}.dat", **variables}) for name, variables in cells])
    out = {}
    for name, _ in cells:
        path = os.path.join(args.workdir, f"{name}.dat")
        if not os.path.exists(path):
            fail(f"cell {name}: no output {path}")
        out[name] = sample_rows(path)
    return out


def seed_mean(runs, column, h, step, fit):
    values = [sample_at_depth(r, column, h, step, fit) for r in runs]
    if any(math.isnan(v) for v in values):
        fail(f"a cell did not reach h = {h:g} m")
    return sum(values) / len(values)


def check(label, rel):
    worst = max(abs(x) for x in rel)
    print(f"{label}: " + " ".join(f"{x:+.4f}" for x in rel) + f"  worst {worst:.4f} (limit {LIMIT})")
    if not worst <= LIMIT:
        fail(f"{label}: {worst:.4f} > {LIMIT}")


def interpolation(args):
    law = StateLaw(LAW)
    with open(LAW) as f:
        doc = json.load(f)
    seeds = doc["samples"]["seeds"]
    surface = doc["surface"]
    p_mid = math.sqrt(law.p[1] * law.p[2])
    step = law.h[1] - law.h[0]
    runs = run_cells(args, [(f"mid_s{s}", {"nside": surface["nside"], "pressure": repr(p_mid), "seed": s,
                                          "speed": doc["speed"], "depth": law.h[-1], "nout": 200}) for s in seeds])
    runs = list(runs.values())
    grid = law.h[1:]
    for key, column, fit in (("mu_body", MU, True), ("rq", RQ, False)):
        check(f"{key}: law at {p_mid:.4g} Pa vs direct cells",
              [law.value(key, p_mid, h) / seed_mean(runs, column, h, step, fit) - 1.0 for h in grid])
    print("PASS")


def cell_size(args):
    seeds = {32: (4711, 12630, 20549), 48: (4711, 12630, 20549), 64: (4711, 12630, 20549), 128: (4711, 12630)}
    # to 12 nm, so that the fit window of every compared depth (up to 10 nm) is complete
    cells = [(f"n{n}_s{s}", {"nside": n, "pressure": "5e6", "seed": s, "depth": 1.2e-8, "nout": 200})
             for n in (128, 64, 48, 32) for s in seeds[n]]
    out = run_cells(args, cells)
    runs = {n: [out[f"n{n}_s{s}"] for s in seeds[n]] for n in seeds}
    step = 2e-9
    grid = [1e-9 * k for k in range(1, 11)]
    for key, column, fit in (("mu_body", MU, True), ("rq", RQ, False)):
        reference = [seed_mean(runs[128], column, h, step, fit) for h in grid]
        for n in (32, 48, 64):
            check(f"{key}, {n * n + (n - 1) ** 2} vs 32513 summits",
                  [seed_mean(runs[n], column, h, step, fit) / r - 1.0 for h, r in zip(grid, reference)])
    print("PASS")


def quasi_static(args):
    out = run_cells(args, [(f"v{v}", {"nside": 48, "pressure": "5e6", "seed": 11, "speed": v, "depth": 1e-8,
                                      "nout": int(round(200 / v))}) for v in (1.0, 0.3)])
    step = 2e-9
    grid = [2e-9 * k for k in range(1, 6)]  # the law's depths
    for key, column, fit in (("mu_body", MU, True), ("rq", RQ, False)):
        check(f"{key}: 1 m/s vs 0.3 m/s",
              [sample_at_depth(out["v1.0"], column, h, step, fit) / sample_at_depth(out["v0.3"], column, h, step, fit)
               - 1.0 for h in grid])
    print("PASS")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=["interpolation", "cell-size", "quasi-static"])
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--workdir", required=True)
    args = ap.parse_args()
    args.workdir = os.path.abspath(args.workdir)
    if os.sep in args.lmp:
        args.lmp = os.path.abspath(args.lmp)
    fresh_dir(args.workdir)
    {"interpolation": interpolation, "cell-size": cell_size, "quasi-static": quasi_static}[args.mode](args)


if __name__ == "__main__":
    main()
