#!/usr/bin/env python3
"""The three dry machine elements, each on its own pair's dry state law (oxidised junctions, mild wear k = 1e-5 by
cycle jumping): the Cu pin on the Al disk on inputs/state_law_cual.json, the steel journal bearing on
inputs/state_law_steel_mild_deep.json (the pipeline's cell taken to the settled depth; the pipeline itself passes the
shallow law it builds), the grey-iron ring pack on inputs/state_law_cast_iron.json.

  check_dry_law_elements.py --runin RUNIN --workdir DIR

Runs inputs/{pin_on_disk,journal_bearing,piston_ring}_state_law.toml as shipped (the law each case names) and
asserts:
  - each case runs on its pair's law (the summary's 'state law' line);
  - Archard's invariant for every body: worn volume = k integral W ds / H within 2 % (pin and disk; both bearing
    halves and their shaft sides; rings A and B and the liner under each), k from the law's samples.wear.k and H
    of that body (the law's rough material for the pin, bearing halves and rings, its counterface material for
    the disk, shaft and liner): the law's wear rate is Archard's at any pressure (out_of_range = "archard");
  - no lookup beyond the law's last worn depth (each summary's 'law lookups' line), and it reports the lookups
    clamped below the lowest grid pressure (printed; not bounded here: the conformal contacts' edges reach p -> 0);
  - the friction the bodies feel is the law's: the pressure-weighted mu_eff at the end within 5 % of Tabor's
    junction closed form f / sqrt(12 (1 - f^2)) at the pair's oxidised m (the calibrated dry level, each file's mu_k).
"""
import argparse
import csv
import json
import math
import os
import re
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from runin_common import fail, interface_factor, law_material_file, material_hardness, run_or_fail  # noqa: E402

LAWS = {"pin-on-disk": "state_law_cual.json", "journal-bearing": "state_law_steel_mild_deep.json",
        "piston-ring": "state_law_cast_iron.json"}
TOLERANCE = 0.02
# element, case, [(csv, [(label, volume column, load column or None for the pin's constant load, rough body?)])]
BODIES = {
    "pin-on-disk": ("pin_on_disk_state_law.toml",
                    [("pin_on_disk.csv", [("pin", "wear_volume_m3", None, True), ("disk", "disk_wear_volume_m3", None, False)])]),
    "journal-bearing": ("journal_bearing_state_law.toml",
                        [("journal_bearing.csv",
                          [("lower half", "lower_wear_volume_m3", "lower_normal_force_N", True),
                           ("shaft under the lower half", "lower_counterface_volume_m3", "lower_normal_force_N", False),
                           ("upper half", "upper_wear_volume_m3", "upper_normal_force_N", True),
                           ("shaft under the upper half", "upper_counterface_volume_m3", "upper_normal_force_N", False)])]),
    "piston-ring": ("piston_ring_state_law.toml",
                    [("piston_ring_A.csv", [("ring A", "wear_ring_m3", "normal_load_N", True),
                                            ("liner under ring A", "wear_liner_m3", "normal_load_N", False)]),
                     ("piston_ring_B.csv", [("ring B", "wear_ring_m3", "normal_load_N", True),
                                            ("liner under ring B", "wear_liner_m3", "normal_load_N", False)])]),
}
END_MU = {"pin-on-disk": ("pin_on_disk.csv", "mu_eff"), "journal-bearing": ("journal_bearing.csv", "mu_eff"),
          "piston-ring": ("piston_ring_A.csv", "mu_eff")}


def material(law):
    """H of the law's rough and counterface bodies and the pair's oxidised m, from the law's material file."""
    path = law_material_file(law)
    rough, counterface = law["material"]["rough"], law["material"]["counterface"]
    return (material_hardness(path, rough), material_hardness(path, counterface),
            interface_factor(path, rough, counterface, "oxidised"))


def work_integral(rows, load_column, constant):
    work = 0.0
    for a, b in zip(rows, rows[1:]):
        ds = float(b["sliding_distance_m"]) - float(a["sliding_distance_m"])
        w = constant if load_column is None else 0.5 * (float(a[load_column]) + float(b[load_column]))
        work += w * ds
    return work


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    problems = []
    for element, (case, files) in BODIES.items():
        law = json.load(open(os.path.join(SOURCE, "inputs", LAWS[element])))
        k = law["samples"]["wear"]["k"]
        h_rough, h_counterface, m = material(law)
        tabor = m / math.sqrt(12.0 * (1.0 - m * m))
        print(f"{element}: law {LAWS[element]} over p = {law['pressure'][0]:.6g}-{law['pressure'][-1]:.6g} Pa, h to "
              f"{law['worn_depth'][-1]:.6g} m")
        out = os.path.join(a.workdir, element)
        result = run_or_fail([a.runin, element, os.path.join(SOURCE, "inputs", case), "--output-dir", out, "--no-plot"])
        if LAWS[element] not in result.stdout:
            problems.append(f"{element}: the case does not run on inputs/{LAWS[element]}")
        lookups = re.search(r"law lookups\s+(\d+) lookups: (\d+) clamped below p = (\S+) Pa, (\d+) above p = \S+ Pa, "
                            r"(\d+) beyond the last worn depth", result.stdout)
        if not lookups:
            fail(f"{element}: no 'law lookups' line in the summary")
        total, below, p_min, above, beyond = lookups.groups()
        print(f"{element}: {total} lookups, {below} ({100 * int(below) / int(total):.1f} %) below p = {p_min} Pa, "
              f"{above} above, {beyond} beyond the last worn depth")
        if int(beyond) != 0:
            problems.append(f"{element}: {beyond} lookups beyond the law's last worn depth")
        constant = None
        if element == "pin-on-disk":
            import tomllib
            with open(os.path.join(SOURCE, "inputs", case), "rb") as f:
                constant = float(tomllib.load(f)["pin"]["normal_load"])
        for csv_name, bodies in files:
            rows = list(csv.DictReader(open(os.path.join(out, csv_name))))
            for label, volume, load, rough in bodies:
                hardness = h_rough if rough else h_counterface
                ratio = float(rows[-1][volume]) / (k * work_integral(rows, load, constant) / hardness)
                print(f"  {label}: worn volume / (k integral W ds / H) = {ratio:.5f}")
                if not abs(ratio - 1.0) <= TOLERANCE:
                    problems.append(f"{element}, {label}: Archard ratio {ratio:.5f} not within {TOLERANCE} of 1")
        csv_name, column = END_MU[element]
        rows = list(csv.DictReader(open(os.path.join(out, csv_name))))
        mu_end = float(rows[-1][column])
        print(f"  {column} at the end {mu_end:.4f}; Tabor at the oxidised m = {m} of {law['material']['rough']} on "
              f"{law['material']['counterface']}: {tabor:.4f}")
        if not abs(mu_end / tabor - 1.0) <= 0.05:
            problems.append(f"{element}: {column} {mu_end:.4f} not within 5 % of Tabor's {tabor:.4f}")
    if problems:
        fail("; ".join(problems))
    print("PASS")


if __name__ == "__main__":
    main()
