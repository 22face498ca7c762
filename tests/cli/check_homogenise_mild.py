#!/usr/bin/env python3
"""`runin homogenise` of a mild-wear law ([wear] k = 1e-5 with cycle jumping) and of a dry junction law ([contact]
friction junction at the file's oxidised state) on inputs/in.rve_rough.

  check_homogenise_mild.py --runin RUNIN --lmp LMP --workdir DIR [--mode wear|contact|deep]

AISI 1020 (potentials/Steel1020.runin, whose pair k is the severe 7e-3), 8^2 + 7^2 summits, 2 and 8 MPa, one seed,
to h = 0.5 nm on a geometric depth grid (grid.depth_first). Asserted: the law records the wear table (k,
jump_max_depth, jump_every, jump_reference_pressure) and each sample ran at the tolerance D p / P_ref; its wear rate at every
grid point is Archard's at the case's k, k p / H, within 1 % (the rates are physical: the cell ran at k, not at an
acceleration of the file's k); the sliding distance to the last depth is h H / (k p) within 1 % (the jumps'
sliding counted), far beyond what the cell slid physically.
contact: the same cell at the file's k with [contact] friction = "junction", interface = "oxidised": the law records
the table, and its mu_body at every grid point is Tabor's f / sqrt(alpha (1 - f^2)) for f = the file's oxidised m
and alpha = 12, within 5 % (every contact of a worn rough-on-rough cell is a plastic junction; the rest is the
normal forces' tilt, ~2-3 %, doc/interface_strength.md).
deep: the wear case with the jumps controlled by the state (wear.jump_max_change 16 nm, wear.jump_rate 2 %,
inputs/homogenise_steel_mild_deep.toml's keys) to h = 3 nm: the law records them, each sample's fix runin/wear/jump
ran with max_change and rate v_rq, and wear rates and sliding distances stay Archard's (1 %), as above.
"""
import math
import argparse
import json
import os
import re
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tests", "lammps"))
from run_deck import mpi_env  # noqa: E402
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from runin_common import fail, fresh_dir, interface_factor  # noqa: E402

K, H = 1.0e-5, 1.19e9
P_REF = 4.0e6    # the jump tolerance 5e-11 m holds here; proportional to p elsewhere
CASE = f"""title = "mild-wear law check"
[material]
file = "{SOURCE}/potentials/Steel1020.runin"
rough = "Steel1020"
counterface = "Steel1020"
[surface]
nside = 8
[sliding]
speed = 1.0
[grid]
pressure_min = 2.0e6
pressure_max = 8.0e6
pressures = 2
seeds = 1
depth = 5.0e-10
depth_points = 4
depth_first = 1.0e-10
nslide = 400000
nout = 200
[wear]
k = {K}
jump_max_depth = 5.0e-11
jump_reference_pressure = {P_REF}
"""


def oxidised_m():
    """m of the Steel1020 pair's 'interface ... oxidised m' line."""
    return interface_factor(os.path.join(SOURCE, "potentials", "Steel1020.runin"), "Steel1020", "Steel1020", "oxidised")


def check_contact(law):
    f = oxidised_m()
    # the junction's f (the state's m) and alpha (the deck's default) are recorded for an element's surface film
    if law["samples"].get("contact") != {"friction": "junction", "interface": "oxidised", "f": f, "alpha": 12.0}:
        fail(f"the law's samples.contact is {law['samples'].get('contact')}")
    tabor = f / math.sqrt(12.0 * (1.0 - f * f))
    mu = [v for row in law["fields"]["mu_body"]["mean"] for v in row[1:]]
    worst = max(abs(v / tabor - 1.0) for v in mu)
    print(f"junction, oxidised (m = {f}): mu_body {min(mu):.4f}-{max(mu):.4f}, Tabor {tabor:.4f}, "
          f"worst {100 * worst:.2f} %")
    if worst > 0.05:
        fail(f"mu_body {min(mu):.4f}-{max(mu):.4f} is not within 5 % of Tabor's {tabor:.4f}")
    # the fraction of the rough body's summits in contact (v_contacts / nside^2): in (0, 1), more at the higher
    # pressure at every depth (the contacts carry the load)
    phi = law["fields"]["contact_fraction"]["mean"]
    if not all(0.0 < v < 1.0 for row in phi for v in row):
        fail(f"contact_fraction outside (0, 1): {phi}")
    if not all(hi > lo for lo, hi in zip(phi[0], phi[-1])):
        fail(f"contact_fraction does not grow with the pressure: {phi}")
    print(f"contact_fraction {phi[0][0]:.4f} .. {phi[-1][0]:.4f} at h = 0 over the pressures")
    print("PASS")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--mode", choices=("wear", "contact", "deep"), default="wear")
    a = ap.parse_args()
    fresh_dir(a.workdir)
    case = os.path.join(a.workdir, "mild.toml")
    text = CASE
    if a.mode == "deep":
        text = text.replace("depth = 5.0e-10\n", "depth = 3.0e-9\n") + "jump_max_change = 1.6e-8\njump_rate = 0.02\n"
    if a.mode == "contact":
        # the even grid 0, 0.25, 0.5 nm: the geometric one's 0.1 nm point sits in the first encounters' 5 % bump
        text = text[:text.index("[wear]")].replace("depth_points = 4\ndepth_first = 1.0e-10\n", "depth_points = 3\n")
        text += '[contact]\nfriction = "junction"\ninterface = "oxidised"\n'
    with open(case, "w") as f:
        f.write(text)
    law_path = os.path.join(a.workdir, "law.json")
    result = subprocess.run([a.runin, "homogenise", case, "--output", law_path, "--cache-dir",
                             os.path.join(a.workdir, "cache"), "--np", "2", "--lmp", a.lmp, "--deck",
                             os.path.join(SOURCE, "inputs", "in.rve_rough")],
                            cwd=a.workdir, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"runin homogenise exited {result.returncode}: {result.stderr[-1500:]}")
    law = json.load(open(law_path))
    if a.mode == "contact":
        check_contact(law)
        return
    wear = law["samples"].get("wear")
    want_wear = {"k": K, "jump_max_depth": 5.0e-11, "jump_every": 1000, "jump_reference_pressure": P_REF}
    if a.mode == "deep":
        want_wear.update(jump_max_change=1.6e-8, jump_rate=0.02)
    if wear != want_wear:
        fail(f"the law's samples.wear is {wear}, want {want_wear}")
    if a.mode == "deep":    # each sample's jump fix ran with the state's controls
        for entry in law["samples"]["list"]:
            log = open(os.path.join(a.workdir, "cache", entry["key"], "log.lammps")).read()
            ran = re.findall(r"runin/wear/jump 1000 1e12 max_depth \S+ max_change ([0-9.e+-]+) rate v_rq ([0-9.e+-]+)",
                             log)
            if not ran or abs(float(ran[-1][0]) / 1.6e-8 - 1) > 1e-12 or abs(float(ran[-1][1]) / 0.02 - 1) > 1e-12:
                fail(f"sample at p = {entry['pressure']:g} Pa: its log has no fix runin/wear/jump with max_change "
                     f"1.6e-08 and rate v_rq 0.02 (found {ran})")
    # each sample's deck got the tolerance D p / P_REF (wear.jump_reference_pressure)
    for entry in law["samples"]["list"]:
        deck = open(os.path.join(a.workdir, "cache", entry["key"], "sample.in")).read()
        got = float(deck.split("variable jump_max_depth index")[1].split()[0].strip('"'))
        want = 5.0e-11 * entry["pressure"] / P_REF
        if abs(got / want - 1.0) > 1e-12:
            fail(f"sample at p = {entry['pressure']:g} Pa ran with jump_max_depth {got:g}, want D p / P_ref = {want:g}")
    # the geometric depth grid (grid.depth_first): 0, then 1e-10 .. 5e-10 m in ratio 5^(1/2)
    grid = law["worn_depth"]
    if a.mode == "deep" and grid[-1] != 3.0e-9:
        fail(f"worn-depth grid {grid}: does not end at the case's 3 nm")
    if a.mode == "wear" and (len(grid) != 4 or grid[0] != 0.0 or abs(grid[1] / 1e-10 - 1) > 1e-12
                             or abs(grid[2] / (1e-10 * 5 ** 0.5) - 1) > 1e-12):
        fail(f"worn-depth grid {grid}: not 0, then geometric from 1e-10 to 5e-10 m")
    worst = 0.0
    for i, p in enumerate(law["pressure"]):
        for j, h in enumerate(law["worn_depth"]):
            rate = law["fields"]["wear_rate"]["mean"][i][j]
            error = abs(rate / (K * p / H) - 1.0)
            worst = max(worst, error)
            if error > 0.01:
                fail(f"p = {p:g} Pa, h = {h:g} m: wear rate {rate:.6g}, Archard k p / H = {K * p / H:.6g}")
        s = law["fields"]["sliding_distance"]["mean"][i][-1]
        want = law["worn_depth"][-1] * H / (K * p)
        if abs(s / want - 1.0) > 0.01:
            fail(f"p = {p:g} Pa: sliding distance to h = {law['worn_depth'][-1]:g} m is {s:.6g} m, h H / (k p) = "
                 f"{want:.6g} m")
        print(f"p = {p:g} Pa: sliding to h = {law['worn_depth'][-1]:g} m {s:.5g} m (h H / (k p) {want:.5g} m)")
    print(f"wear rates within {100 * worst:.3f} % of k p / H at every grid point")
    print("PASS")


if __name__ == "__main__":
    main()
