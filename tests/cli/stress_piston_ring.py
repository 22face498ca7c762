#!/usr/bin/python3
"""Stress sweep of `runin piston-ring` (stdlib only).

usage: stress_piston_ring.py RUNIN BASE_CASE.toml WORKDIR

Runs the base (crank, gas) case shortened to 10 revolutions and the ramp variant with
mu0 in {0, 0.5, 1, 2}, the loads (ring tension and gas) x1 and x1000 and the Archard k in
{1e-8, 1e-4, 1e-1}. Each run must either succeed with a finite CSV (|F| <= mu_s W in stick,
wear volume >= 0, ring wear depth below the ring's radial thickness) or stop with exit code 1
and a one-line "runin: error: ..." message (the cases are valid input, so exit code 2 is a
failure). Physical sense: frictionless sliding at x1000 gas load with k = 0.1 wears more than
the 10 mm thick ring (53 mm without the limit), so WORN_THROUGH must stop with
"ring worn through at t = ...".
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

from case_text import drop_section, edit


WORN_THROUGH = {"crank_mu0_load1000_k0.1"}


def main():
    runin, base_path, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    base = open(base_path).read()
    base = edit(base, "run", "t_end", "0.5")
    base = drop_section(base, "sweep")
    base = edit(base, "output", "vtk_times", "[0.0, 0.5]")
    thickness = float(re.search(r"^thickness\s*=\s*([^\s#]+)", base, re.M).group(1))
    failures, runs = [], 0
    for motion in ("crank", "ramp"):
        for mu0 in (0.0, 0.5, 1.0, 2.0):
            for load in (1.0, 1000.0):
                for k in (1e-8, 1e-4, 1e-1):
                    text = edit(base, "friction", "mu_static", repr(mu0))
                    text = edit(text, "friction", "mu_kinetic", repr(0.7 * mu0))
                    text = edit(text, "ring", "elastic_pressure", repr(0.2e6 * load))
                    text = edit(text, "wear", "k", repr(k))
                    if motion == "ramp":
                        text = drop_section(text, "gas")
                        text = edit(text, "kinematics", "motion", '"ramp"')
                        text = text.replace("crank_speed_rpm = 1200.0", "ramp_time = 2.0")
                    else:
                        pressures = re.search(r"^pressure = \[([^\]]*)\]", text, re.M).group(1)
                        scaled = ", ".join(repr(float(p) * load) for p in pressures.split(","))
                        text = re.sub(r"^pressure = \[[^\]]*\]", f"pressure = [{scaled}]", text, flags=re.M)
                    name = f"{motion}_mu{mu0:g}_load{load:g}_k{k:g}"
                    case = os.path.join(work, name + ".toml")
                    with open(case, "w") as f:
                        f.write(text)
                    out = os.path.join(work, name)
                    shutil.rmtree(out, ignore_errors=True)  # a stopped run keeps an earlier run's output
                    runs += 1
                    p = subprocess.run([runin, "piston-ring", case, "--output-dir", out, "--no-plot"],
                                       capture_output=True, text=True, timeout=300)
                    if p.returncode == 0:
                        with open(os.path.join(out, "piston_ring.csv"), newline="") as f:
                            rows = [[float(x) for x in r] for r in list(csv.reader(f))[1:]]
                        if not rows or not all(math.isfinite(x) for r in rows for x in r):
                            failures.append(f"{name}: non-finite output")
                        elif any(r[12] == 0 and abs(r[7]) > mu0 * r[9] * (1 + 1e-6) + 1e-9 for r in rows):
                            failures.append(f"{name}: stick force above mu_s W")
                        elif rows[-1][15] < 0.0:
                            failures.append(f"{name}: negative wear volume")
                        with open(os.path.join(out, "piston_ring_face.csv"), newline="") as f:
                            depth = max(float(r["wear_depth_m"]) for r in csv.DictReader(f))
                        if depth > thickness:
                            failures.append(f"{name}: ring wear depth {depth:.3g} m exceeds its thickness {thickness} m")
                        if name in WORN_THROUGH:
                            failures.append(f"{name}: finished, expected 'ring worn through' (depth {depth:.3g} m)")
                        print(f"{name}: ok, {len(rows)} rows, wear {rows[-1][15]:.3g} m^3, ring depth {depth:.3g} m")
                    else:
                        lines = p.stderr.strip().splitlines()
                        # Every case is valid input: only a numerical stop (exit 1) with a clear message is allowed.
                        if p.returncode != 1 or len(lines) != 1 or not lines[0].startswith("runin: error: "):
                            failures.append(f"{name}: exit {p.returncode}, stderr {p.stderr!r}")
                        elif name in WORN_THROUGH and not lines[0].startswith("runin: error: ring worn through at t = "):
                            failures.append(f"{name}: expected 'ring worn through', got {lines[0]!r}")
                        if os.path.exists(out):
                            failures.append(f"{name}: output left behind by a stopped run")
                        print(f"{name}: stopped (exit {p.returncode}): {p.stderr.strip()}")
    for f in failures:
        print("stress_piston_ring:", f, file=sys.stderr)
    print(f"{runs} runs, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
