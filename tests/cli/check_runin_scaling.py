#!/usr/bin/env python3
"""Run-in distance against pressure in a machine element on a law from the cell ("emergent run-in").

  check_runin_scaling.py --runin RUNIN --workdir DIR [--law LAW.json --pressures P1 P2 P3]

A flat-ended steel pin (uniform nominal pressure) on the shipped steel state law inputs/state_law_steel.json at
three grid pressures (0.632, 2 and 6.32 MPa). Run-in distance: the sliding distance at which the pin face's
roughness, Rq(p, h_mean) from the law, has fallen by 20 % from its start. Archard's estimate makes it
sigma H / (k p): asserted, the log-log slope over the three pressures within 20 % of -1, and Rq falls.
Printed, and asserted the same way with --assert-friction (the rough-on-rough law, whose friction runs in): the
friction run-in distance, where mu_eff has made 90 % of its fall from the peak (measured slope -0.962 on
inputs/state_law_steel_rough.json; -2.09 on the flat-cell law, whose friction does not run in).
"""
import argparse
import csv
import math
import os
import subprocess
import sys

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "tools"))
from state_law import StateLaw  # noqa: E402  (the C++ reader's interpolation rule)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402
LAW = os.path.join(SOURCE, "inputs", "state_law_steel.json")
RADIUS = 1.5e-3
PRESSURES = (632455.5320336759, 2.0e6, 6324555.320336758)
DROP = 0.8


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--law", default=LAW)
    ap.add_argument("--pressures", type=float, nargs=3, default=PRESSURES, help="three grid pressures [Pa]")
    ap.add_argument("--assert-friction", action="store_true",
                    help="also assert the friction run-in distance's slope (a law whose friction runs in)")
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    law = StateLaw(a.law)
    distances, friction_distances = [], []
    for p in a.pressures:
        if law.grid_index(p, 1e-9) is None:
            fail(f"{p} Pa is not a grid pressure of the law")
        load = p * math.pi * RADIUS ** 2
        case = os.path.join(a.workdir, f"pod_{p:.4g}.toml")
        with open(case, "w") as f:
            f.write(f'''title = "run-in scaling, flat pin at {p:.4g} Pa"
[pin]
mass = 0.001
track_radius = 0.05
normal_load = {load!r}
[loading]
drive = "speed"
sliding_speed = 0.1
ramp_time = 0.001
[friction]
model = "state_law"
law = "{a.law}"
[contact]
tip = "flat"
flat_radius = {RADIUS!r}
rings = 8
[run]
t_end = 0.06
output_interval = 5e-5
''')
        out = os.path.join(a.workdir, f"out_{p:.4g}")
        result = subprocess.run([a.runin, "pin-on-disk", case, "--output-dir", out, "--no-plot"],
                                capture_output=True, text=True)
        if result.returncode != 0:
            fail(f"pin-on-disk at {p:g} Pa: {result.stderr.strip()}")
        with open(os.path.join(out, "pin_on_disk.csv")) as f:
            rows = list(csv.DictReader(f))
        rq0 = law.value("rq", p, 0.0)
        s_runin = None
        for r0, r1 in zip(rows, rows[1:]):
            q0 = law.value("rq", p, float(r0["h_mean_m"]))
            q1 = law.value("rq", p, float(r1["h_mean_m"]))
            if q0 > DROP * rq0 >= q1:
                w = (q0 - DROP * rq0) / (q0 - q1)
                s0, s1 = float(r0["sliding_distance_m"]), float(r1["sliding_distance_m"])
                s_runin = s0 + w * (s1 - s0)
                break
        if s_runin is None:
            fail(f"at {p:g} Pa Rq did not fall by {100 * (1 - DROP):.0f} % within the run")
        distances.append(s_runin)
        mu = [float(r["mu_eff"]) for r in rows]
        sd = [float(r["sliding_distance_m"]) for r in rows]
        k_peak = max(range(len(mu)), key=lambda k: mu[k])
        level = mu[-1] + 0.1 * (mu[k_peak] - mu[-1])
        k = next((k for k in range(k_peak + 1, len(mu)) if mu[k] <= level), len(mu) - 1)
        s_mu = (sd[k - 1] + (sd[k] - sd[k - 1]) * (mu[k - 1] - level) / (mu[k - 1] - mu[k]) if mu[k - 1] > mu[k]
                else sd[k])
        friction_distances.append(s_mu)
        print(f"p = {p:.4g} Pa: Rq {rq0 * 1e9:.1f} nm falls by 20 % after s = {s_runin * 1e3:.4g} mm; mu_eff "
              f"{mu[k_peak]:.4f} -> {mu[-1]:.4f}, 90 % of its fall after s = {s_mu * 1e3:.4g} mm")
    x = [math.log(p) for p in a.pressures]
    y_mu = [math.log(s) for s in friction_distances]
    mx_, my_ = sum(x) / 3, sum(y_mu) / 3
    slope_mu = sum((a_ - mx_) * (b - my_) for a_, b in zip(x, y_mu)) / sum((a_ - mx_) ** 2 for a_ in x)
    print(f"log-log slope of the friction run-in distance against pressure: {slope_mu:.4f}"
          + (" (sigma H / (k p): -1, limit 20 %)" if a.assert_friction else " (not asserted)"))
    if a.assert_friction and abs(slope_mu + 1.0) > 0.2:
        fail(f"friction run-in slope {slope_mu:.4f} is not within 20 % of -1")
    y = [math.log(s) for s in distances]
    mx, my = sum(x) / 3, sum(y) / 3
    slope = sum((a_ - mx) * (b - my) for a_, b in zip(x, y)) / sum((a_ - mx) ** 2 for a_ in x)
    print(f"log-log slope of the run-in distance against pressure: {slope:.4f} (sigma H / (k p): -1, limit 20 %)")
    if abs(slope + 1.0) > 0.2:
        fail(f"slope {slope:.4f} is not within 20 % of -1")
    print("PASS")


if __name__ == "__main__":
    main()
