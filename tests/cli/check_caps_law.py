#!/usr/bin/env python3
"""A state law built with summits as caps (surface.caps) against the same case's law built with whole spheres.

  check_caps_law.py --law LAW --reference REFERENCE
  check_caps_law.py --runin RUNIN --case CASE --workdir DIR --reference REFERENCE   # builds LAW first (cold)

Caps are the same spheres with computed centres (doc/pair_runin_asperity.rst, "Caps"): the samples differ from whole
spheres by round-off grown over the run, not by physics. Asserted: the same grid (pressures, depths, seeds), and at
every grid point every field's seed mean within the reference's seed band (its highest less its lowest seed), or,
where the band is empty (h = 0), within 1e-9. Printed per field: the largest and RMS relative difference and the
largest difference in units of the band (doc/homogenise.md, "Summits as caps").
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail, run_or_fail  # noqa: E402


def compare(law, reference):
    for key in ("pressure", "worn_depth"):
        if law[key] != reference[key]:
            fail(f"the grids differ in {key}: {law[key]} against {reference[key]}")
    if law["samples"]["seeds"] != reference["samples"]["seeds"]:
        fail(f"the seeds differ: {law['samples']['seeds']} against {reference['samples']['seeds']}")
    if not law.get("surface", {}).get("caps"):
        fail("the law was not built with caps (its surface has no caps = true)")
    for name, field in reference["fields"].items():
        if not isinstance(field, dict) or "mean" not in field:
            continue
        other = law["fields"][name]
        worst = rms = worst_band = 0.0
        count = 0
        for i, row in enumerate(field["mean"]):
            for j, ref in enumerate(row):
                got = other["mean"][i][j]
                band = field["high"][i][j] - field["low"][i][j] if "high" in field else 0.0
                diff = abs(got - ref)
                rel = diff / max(abs(ref), 1e-300)
                worst, rms, count = max(worst, rel), rms + rel * rel, count + 1
                if band > 0.0:
                    worst_band = max(worst_band, diff / band)
                    if diff > band:
                        fail(f"{name} at p = {law['pressure'][i]:.4g} Pa, h = {law['worn_depth'][j]:.4g} m: {got:.6g} "
                             f"against {ref:.6g}, outside the reference's seed band {band:.3g}")
                elif rel > 1e-9:
                    fail(f"{name} at p = {law['pressure'][i]:.4g} Pa, h = {law['worn_depth'][j]:.4g} m: {got:.9g} "
                         f"against {ref:.9g} where the seeds agree")
        print(f"{name}: largest relative difference {worst:.2g}, RMS {math.sqrt(rms / count):.2g}, largest / seed band "
              f"{worst_band:.2g}")
    print("PASS")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--law")
    parser.add_argument("--reference", required=True)
    parser.add_argument("--runin")
    parser.add_argument("--case")
    parser.add_argument("--workdir")
    args = parser.parse_args()
    law_path = args.law
    if not law_path:
        if not (args.runin and args.case and args.workdir):
            fail("give --law, or --runin, --case and --workdir to build it")
        os.makedirs(args.workdir, exist_ok=True)
        law_path = os.path.join(args.workdir, "law.json")
        command = [args.runin, "homogenise", args.case, "--output", law_path, "--cache-dir",
                   os.path.join(args.workdir, "cache"), "--np", "2"]
        run_or_fail(command)
    with open(law_path) as f:
        law = json.load(f)
    with open(args.reference) as f:
        reference = json.load(f)
    compare(law, reference)


if __name__ == "__main__":
    main()
