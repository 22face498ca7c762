#!/usr/bin/env python3
"""Physics of a material pair's dry state law (inputs/homogenise_cual.toml, inputs/homogenise_cast_iron.toml):
the shipped law, and a reduced rebuild of its case on inputs/in.rve_rough.

  check_pair_law.py law --law LAW.json
  check_pair_law.py rebuild --case CASE.toml --runin RUNIN --lmp LMP --workdir DIR [--nside N] [--depth H]
                    [--depth-points N]

Asserted on the law (the shipped one, or the rebuild's):
  - Amontons: the steady mu_body (the mean over the grid depths h >= depth / 2) at the lowest and the highest
    grid pressure (a decade apart in both cases) differ by less than 10 %;
  - Archard per body: wear_rate = k p / H_rough and counterface_wear_rate = k p / H_counterface within 1 % at
    every grid point, k the law's samples.wear.k, H each body's hardness from the law's material file.
Printed per pressure: steady mu_body, the peak (largest grid value over h) and peak / steady; doc/validation.md
quotes these for the shipped laws (tests/doc_numbers.toml).
rebuild: the case with its surface.nside (16), grid.pressures (2: its pressure_min and pressure_max), grid.seeds (1),
grid.depth (1 nm) and grid.depth_points (2) reduced, everything else (material, bodies, [contact], [wear]) as shipped.
"""
import argparse
import json
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from runin_common import fail, fresh_dir, law_material_file, material_hardness, mpi_env  # noqa: E402


def steady_and_peak(law, i):
    """Steady mu_body (mean over h >= depth / 2) and the peak (largest grid value) at pressure index i."""
    depths, mu = law["worn_depth"], law["fields"]["mu_body"]["mean"][i]
    late = [m for h, m in zip(depths, mu) if h >= 0.5 * depths[-1] - 1e-15]
    steady = sum(late) / len(late)
    return steady, max(mu)


def check(law):
    material = law["material"]
    path = law_material_file(law)
    h_rough, h_cf = material_hardness(path, material["rough"]), material_hardness(path, material["counterface"])
    wear = law["samples"].get("wear")
    if not wear or "k" not in wear:
        fail(f"the law has no samples.wear.k: {wear}")
    k = wear["k"]
    print(f"{law['title']}: {material['rough']} on {material['counterface']}, contact {law['samples'].get('contact')}, "
          f"k = {k:g}")
    worst = 0.0
    for i, p in enumerate(law["pressure"]):
        for field, h in (("wear_rate", h_rough), ("counterface_wear_rate", h_cf)):
            for j, rate in enumerate(law["fields"][field]["mean"][i]):
                error = abs(rate / (k * p / h) - 1.0)
                worst = max(worst, error)
                if error > 0.01:
                    fail(f"p = {p:g} Pa, h = {law['worn_depth'][j]:g} m: {field} {rate:.6g}, Archard k p / H = "
                         f"{k * p / h:.6g} (H = {h:g} Pa)")
        steady, peak = steady_and_peak(law, i)
        print(f"p = {p:.4g} Pa: steady mu_body {steady:.4f}, peak {peak:.4f}, peak / steady {peak / steady:.4f}, "
              f"mu_body at h = 0 {law['fields']['mu_body']['mean'][i][0]:.4f}")
    print(f"wear rates of both bodies within {100 * worst:.3f} % of k p / H at every grid point")
    low, high = steady_and_peak(law, 0)[0], steady_and_peak(law, len(law["pressure"]) - 1)[0]
    change = abs(high / low - 1.0)
    print(f"Amontons: steady mu_body {low:.4f} at {law['pressure'][0]:.4g} Pa, {high:.4f} at "
          f"{law['pressure'][-1]:.4g} Pa: change {100 * change:.2f} %")
    if change >= 0.10:
        fail(f"steady mu_body changes by {100 * change:.2f} % over the pressure grid (Amontons: < 10 %)")
    print("PASS")


def reduced_case(text, nside, depth, depth_points):
    """The case with a smaller cell and grid (see the module doc)."""
    for key, value in (("nside", nside), ("pressures", 2), ("seeds", 1), ("depth", depth), ("depth_points", depth_points)):
        text, n = re.subn(rf"^{key} = .*$", f"{key} = {value}", text, flags=re.M)
        if n != 1:
            fail(f"the case has {n} '{key} = ' lines, expected 1")
    # relative paths of the shipped case are the source tree's
    text = re.sub(r'^file = "(potentials/[^"]+)"', rf'file = "{SOURCE}/\1"', text, flags=re.M)
    return re.sub(r'^deck = .*$', "", text, flags=re.M)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=("law", "rebuild"))
    ap.add_argument("--law")
    ap.add_argument("--case")
    ap.add_argument("--runin")
    ap.add_argument("--lmp")
    ap.add_argument("--workdir")
    ap.add_argument("--nside", type=int, default=16)
    ap.add_argument("--depth", type=float, default=1e-9)
    # 2: one grid step over the whole depth, so that each wear rate is fitted over many jumps (a window of few
    # jumps, cut mid-phase, biases the slope by up to ~1 %)
    ap.add_argument("--depth-points", type=int, default=2)
    a = ap.parse_args()
    if a.mode == "law":
        check(json.load(open(a.law)))
        return
    a.workdir = os.path.abspath(a.workdir)
    fresh_dir(a.workdir)
    case = os.path.join(a.workdir, "reduced.toml")
    with open(case, "w") as f:
        f.write(reduced_case(open(a.case).read(), a.nside, a.depth, a.depth_points))
    law_path = os.path.join(a.workdir, "law.json")
    result = subprocess.run([os.path.abspath(a.runin), "homogenise", case, "--output", law_path, "--cache-dir",
                             os.path.join(a.workdir, "cache"), "--np", "2", "--lmp", os.path.abspath(a.lmp), "--deck",
                             os.path.join(SOURCE, "inputs", "in.rve_rough")],
                            cwd=a.workdir, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"runin homogenise exited {result.returncode}: {result.stderr[-1500:]}")
    check(json.load(open(law_path)))


if __name__ == "__main__":
    main()
