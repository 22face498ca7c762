#!/usr/bin/env python3
"""Emergent run-in in the three machine elements on laws built from the rough-on-rough cell.

  check_element_runin.py --runin RUNIN --workdir DIR

Runs the steel versions of the three state-law cases (tests/data/state_law/steel/ for the pin and the ring, whose
shipped cases now run their own pairs; inputs/journal_bearing_state_law.toml) on the two shipped
rough-on-rough steel laws: inputs/state_law_steel_rough.json (sigma = 0.2 um per body) and
inputs/state_law_steel_rough_sigma04.json (0.4 um, the rougher initial surface); both built at physical wear by
`runin homogenise inputs/homogenise_rough_{pipeline,sigma04}.toml` (doc/rve_cell.md).
No friction is put in: the laws' mu_body comes from adhesion over the real area and the summits' ploughing.
Asserted for every element (ring A for the pack):
  - friction falls from its peak: the last mu <= 0.75 x the peak (measured 0.55-0.62);
  - the roughness falls: Rq from the law at the element's mean pressure and mean worn depth, end <= 0.9 x start;
  - thesis claims 2 and 3 with physical inputs: the rougher surface gives the higher peak and the longer run-in
    (t90: the time at which mu has made 90 % of its fall from the peak to its final value); the rougher peak
    must be higher by more than the smoother law's seed band at h = 0 (measured 0.0008);
  - Archard's invariant: the rough body's worn volume over K * integral of its normal load ds, K = the law's
    wear_rate / p at its lowest grid point, within 1 % of 1 (measured 0.9996 for the bearing and ring A:
    out_of_range = "archard" keeps node wear proportional to p below the grid; "clamp" gave 4.54 and 1.41);
  - scale separation as the summary reports it (check_scale_separation).
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import tomllib

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from state_law import StateLaw  # noqa: E402  (the C++ reader's interpolation rule)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

LAWS = {"smooth": os.path.join(SOURCE, "inputs", "state_law_steel_rough.json"),
        "rough": os.path.join(SOURCE, "inputs", "state_law_steel_rough_sigma04.json")}
ELEMENTS = (("pin-on-disk", "pin_on_disk_state_law.toml", "pin_on_disk.csv", "h_mean_m"),
            ("journal-bearing", "journal_bearing_state_law.toml", "journal_bearing.csv", "lower_h_mean_m"),
            ("piston-ring", "piston_ring_state_law.toml", "piston_ring_A.csv", "h_mean_m"))
# rough body's worn volume and normal load columns (None: the case's constant pin.normal_load)
ARCHARD_COLUMNS = {"pin-on-disk": ("wear_volume_m3", None),
                   "journal-bearing": ("lower_wear_volume_m3", "lower_normal_force_N"),
                   "piston-ring": ("wear_ring_m3", "normal_load_N")}
ARCHARD_TOLERANCE = 0.01
FALL = 0.75
RQ_FALL = 0.9


def case_path(case):
    """The steel version of a shipped state-law case (the pin and ring cases in inputs/ run their own pairs)."""
    steel = os.path.join(SOURCE, "tests", "data", "state_law", "steel", case)
    return steel if os.path.exists(steel) else os.path.join(SOURCE, "inputs", case)


def run(runin, element, case, law, out):
    result = subprocess.run([runin, element, case_path(case), "--law", law,
                             "--output-dir", out, "--no-plot"], capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{element} on {law}: {result.stderr.strip()}")
    return result.stdout


def check_scale_separation(element, case, stdout, law_path):
    """The summary's scale-separation line against the law's cell: the 3 mm flat pin is 3.125 cells of 0.96 mm
    wide and its centre ring (radius a / rings) holds eta pi (a / rings)^2 summits; the bearing's and the ring's
    unworn contacts are narrower than one cell, which the summary must say in a WARNING."""
    match = re.search(r"scale separation  contact (\S+) mm wide = (\S+) cells of (\S+) mm \((holds|fails)[^)]*\); "
                      r"smallest loaded node (\S+) summits", stdout)
    if not match:
        fail(f"{element}: no scale-separation line in the summary")
    width, cells, cell, verdict, summits = match.groups()
    with open(law_path) as f:
        surface = json.load(f)["surface"]
    cell_size = surface["nside"] * surface["spacing"]
    eta = surface["summits"] / cell_size ** 2
    if abs(float(cell) * 1e-3 / cell_size - 1.0) > 1e-3 or abs(float(cells) / (float(width) / float(cell)) - 1) > 2e-3:
        fail(f"{element}: cell {cell} mm, {cells} cells for {width} mm: not the law's cell {cell_size * 1e3} mm")
    if element == "pin-on-disk":
        with open(case_path(case), "rb") as f:
            contact = tomllib.load(f)["contact"]
        a, rings = float(contact["flat_radius"]), int(contact["rings"])
        expected = eta * math.pi * (a / rings) ** 2
        if verdict != "holds" or abs(float(width) * 1e-3 / (2 * a) - 1) > 1e-3 or abs(float(summits) / expected - 1) > 1e-3:
            fail(f"{element}: scale separation {width} mm, {verdict}, {summits} summits; expected 2a = {2e3 * a} mm, "
                 f"holds, {expected:.4g} summits in the centre ring")
    elif verdict != "fails" or "WARNING: no scale separation" not in stdout:
        fail(f"{element}: a contact of {width} mm = {cells} cells must be reported as failing scale separation")
    print(f"  scale separation: {width} mm = {cells} cells of {cell} mm ({verdict}), smallest node {summits} summits")


def summary(path, law, h_column):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["t_s"]) for r in rows]
    mu = [float(r["mu"]) for r in rows]
    peak = max(mu)
    end = mu[-1]
    # t90 interpolated between output rows (the output interval is 1/50-1/20 of the run-in)
    level = end + 0.1 * (peak - end)
    k = next(k for k in range(1, len(mu)) if mu[k] <= level)
    t90 = t[k - 1] + (t[k] - t[k - 1]) * (mu[k - 1] - level) / (mu[k - 1] - mu[k]) if mu[k - 1] > mu[k] else t[k]
    p0 = float(rows[0]["mean_pressure_Pa"]) or float(rows[1]["mean_pressure_Pa"])
    rq0 = law.value("rq", p0, float(rows[0][h_column]))
    rq1 = law.value("rq", float(rows[-1]["mean_pressure_Pa"]), float(rows[-1][h_column]))
    return {"peak": peak, "end": end, "t90": t90, "rq0": rq0, "rq1": rq1, "rows": rows}


def archard_ratio(element, case, rows, law):
    """Worn volume / (K integral W ds), K = the law's wear_rate / p at its lowest grid point."""
    volume_column, load_column = ARCHARD_COLUMNS[element]
    if load_column is None:
        with open(case_path(case), "rb") as f:
            constant = float(tomllib.load(f)["pin"]["normal_load"])
    work = 0.0
    for a, b in zip(rows, rows[1:]):
        ds = float(b["sliding_distance_m"]) - float(a["sliding_distance_m"])
        w = constant if load_column is None else 0.5 * (float(a[load_column]) + float(b[load_column]))
        work += w * ds
    k = law.value("wear_rate", law.p[0], 0.0) / law.p[0]
    return float(rows[-1][volume_column]) / (k * work)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    laws = {k: StateLaw(v) for k, v in LAWS.items()}
    band = laws["smooth"].grid("mu_body", "high")
    low = laws["smooth"].grid("mu_body", "low")
    seed_band = max(hi[0] - lo[0] for hi, lo in zip(band, low))
    for element, case, csv_name, h_column in ELEMENTS:
        got = {}
        for name, path in LAWS.items():
            out = os.path.join(a.workdir, f"{element}_{name}")
            stdout = run(a.runin, element, case, path, out)
            check_scale_separation(element, case, stdout, path)
            got[name] = summary(os.path.join(out, csv_name), laws[name], h_column)
            s = got[name]
            print(f"{element}, {name} law: mu peak {s['peak']:.4f} -> {s['end']:.4f} (t90 {s['t90']:.4g} s), "
                  f"Rq {s['rq0'] * 1e9:.1f} -> {s['rq1'] * 1e9:.1f} nm")
            if not s["end"] <= FALL * s["peak"]:
                fail(f"{element} ({name}): friction did not fall from its peak: {s['peak']:.4f} -> {s['end']:.4f}")
            if not s["rq1"] <= RQ_FALL * s["rq0"]:
                fail(f"{element} ({name}): Rq did not fall: {s['rq0']:.4g} -> {s['rq1']:.4g} m")
            ratio = archard_ratio(element, case, s["rows"], laws[name])
            print(f"  Archard's invariant V / (K integral W ds) = {ratio:.4f}")
            if not abs(ratio - 1.0) <= ARCHARD_TOLERANCE:
                fail(f"{element} ({name}): worn volume / (K integral W ds) = {ratio:.4f}, not within "
                     f"{ARCHARD_TOLERANCE} of 1")
        smooth, rough = got["smooth"], got["rough"]
        if not rough["peak"] > smooth["peak"] + seed_band:
            fail(f"{element}: the rougher surface's peak {rough['peak']:.4f} is not above the smoother one's "
                 f"{smooth['peak']:.4f} by more than the seed band {seed_band:.4f}")
        if not rough["t90"] > smooth["t90"]:
            fail(f"{element}: the rougher surface's run-in (t90 {rough['t90']:.4g} s) is not longer than the "
                 f"smoother one's ({smooth['t90']:.4g} s)")
    print("PASS")


if __name__ == "__main__":
    main()
