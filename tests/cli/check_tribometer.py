#!/usr/bin/env python3
"""Runs the tribometer case (inputs/pin_on_disk_tribometer.toml: flat AISI 1020 pin, 20 N, 0.5 m/s, 1 km, adaptive
wear steps) and checks its summary against its own CSV and the law (doc/state_law_continuum.md):

- the run slides 1 km (within the ramp's half-length) in less than the wall-time bound (10 s, the run without
  output, as the summary reports it);
- the run-in distance: steady mu = the mean of F/W over the last 10 % of sliding (each row's F/W weighted by the
  distance slid since the row before: F/W is held over it), the settle distance = the first row from which on F/W
  stays within 2 % of it; recomputed here and equal to the summary's (stdout and pin_on_disk_summary.csv);
- Archard's invariant: worn volume / (K W s) within 2 % of 1 for the pin and for the disk, K = the case's law's
  wear_rate (counterface_wear_rate) / p at its lowest grid pressure and h = 0; recomputed and equal to the summary's;
- the slow steps are the CSV's rows after the first;
- the law reaches the settled roughness at the pin's pressure, so the last column it holds beyond its last worn depth
  is the settled state, not a truncation: Rq(p, h) of the law (the reader's interpolation) changes over a window of
  sigma/10 of h by less than 1 % of its change over the first window from some depth inside the law on (the
  criterion of doc/rve_cell.md, "Mild wear to the settled depth"), and Rq along the pin's path, Rq(p, h_mean), is
  within 2 % of its end value from before the pin wears past the law's last depth (printed: that roughness run-in
  distance, the settled depth and where the pin reaches it, the law lookups beyond the last depth);
- check_state_law_pod.py on the output: mu_eff(s) and h(s) within 1 % of the law integrated directly along s at the
  uniform nominal pressure, F/W = the held mu_eff, disk/pin volume = 1, the three VTK frames.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from runin_common import SOURCE_DIR, fail, fresh_dir, run_or_fail  # noqa: E402
from state_law import StateLaw  # noqa: E402

CASE = os.path.join(SOURCE_DIR, "inputs", "pin_on_disk_tribometer.toml")
LOAD, SPEED, T_END, RAMP, FLAT_RADIUS = 20.0, 0.5, 2000.0, 0.05, 1.5e-3
WALL_BOUND = 10.0
SETTLE_TOLERANCE, TAIL = 0.02, 0.1
ARCHARD_TOLERANCE = 0.02


def run_in(s, mu):
    cut = s[-1] - TAIL * (s[-1] - s[0])
    weighted = length = 0.0
    for k in range(1, len(s)):
        lo = max(s[k - 1], cut)
        if s[k] > lo:
            weighted += mu[k] * (s[k] - lo)
            length += s[k] - lo
    steady = weighted / length
    settle = None
    for k in range(len(s) - 1, -1, -1):
        if abs(mu[k] - steady) > SETTLE_TOLERANCE * abs(steady):
            break
        settle = s[k]
    return steady, settle


def settled_depth(law, law_path, pressure):
    """The first h (a multiple of sigma/10) from which the law's Rq at this pressure changes over sigma/10 by less
    than 1 % of its change over the first sigma/10 (None: the law is too shallow or Rq still falls at its end)."""
    with open(law_path) as f:
        window = 0.1 * json.load(f)["surface"]["sigma"]
    edges = [k * window for k in range(int(law.h[-1] / window + 1e-9) + 1)]
    if len(edges) < 3:
        return None
    curve = [law.value("rq", pressure, e) for e in edges]
    first = abs(curve[1] - curve[0])
    return next((edges[k] for k in range(1, len(curve) - 1) if abs(curve[k + 1] - curve[k]) < 0.01 * first), None)


def distance_at_depth(s, h, depth):
    """The sliding distance at which the pin's mean worn depth reaches depth (linear between rows), or None."""
    for k in range(1, len(s)):
        if h[k] >= depth:
            return s[k - 1] + (s[k] - s[k - 1]) * (depth - h[k - 1]) / (h[k] - h[k - 1])
    return None


def close(a, b, rel=1e-9):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    fresh_dir(a.workdir)
    out = os.path.join(a.workdir, "out")
    stdout = run_or_fail([a.runin, "pin-on-disk", CASE, "--output-dir", out, "--no-plot"]).stdout
    print(stdout)
    rows = list(csv.DictReader(open(os.path.join(out, "pin_on_disk.csv"))))
    summary = list(csv.DictReader(open(os.path.join(out, "pin_on_disk_summary.csv"))))[0]
    s = [float(r["sliding_distance_m"]) for r in rows]
    mu = [float(r["mu"]) for r in rows]

    expected = SPEED * (T_END - RAMP / 2)
    if not close(s[-1], expected, 1e-12):
        fail("slid %.12g m, expected %.12g m (0.5 m/s for 2000 s after the 50 ms ramp)" % (s[-1], expected))
    wall = float(summary["wall_time_s"])
    m = re.search(r"wall time +(\S+) s", stdout)
    if not m:
        fail("no wall time line")
    if wall >= WALL_BOUND:
        fail("1 km took %g s (bound %g s)" % (wall, WALL_BOUND))

    steady, settle = run_in(s, mu)
    if settle is None or settle > 0.1 * s[-1]:
        fail("mu does not settle within 2 %% of %g in the first 10 %% of sliding" % steady)
    if not close(float(summary["steady_mu_last_10pc"]), steady) or not close(float(summary["settle_distance_m"]),
                                                                              settle):
        fail("summary run-in %s m, steady %s; recomputed %.12g m, %.12g" % (summary["settle_distance_m"],
                                                                          summary["steady_mu_last_10pc"], settle,
                                                                          steady))
    m = re.search(r"run-in +mu = F/W within 2 % of its steady value (\S+) \(mean over the last 10 % of sliding\) "
                  r"from s = (\S+) m", stdout)
    if not m or not close(float(m.group(1)), steady, 1e-5) or not close(float(m.group(2)), settle, 1e-5):
        fail("no run-in line matching %.6g m, steady %.6g" % (settle, steady))

    # the case's law (friction.law), as the summary names it
    m = re.search(r"^  state law +(\S+) \(p ", stdout, re.M)
    if not m:
        fail("no state law line")
    law_path = m.group(1)
    law = StateLaw(law_path)
    p0 = law.p[0]
    k_pin = law.value("wear_rate", p0, 0.0) / p0
    k_disk = law.value("counterface_wear_rate", p0, 0.0) / p0
    ratios = (float(rows[-1]["wear_volume_m3"]) / (k_pin * LOAD * s[-1]),
              float(rows[-1]["disk_wear_volume_m3"]) / (k_disk * LOAD * s[-1]))
    for name, ratio in zip(("pin", "disk"), ratios):
        reported = float(summary["archard_ratio_" + name])
        if not close(reported, ratio, 1e-6):
            fail("Archard ratio of the %s: summary %g, recomputed %g" % (name, reported, ratio))
        if abs(ratio - 1.0) > ARCHARD_TOLERANCE:
            fail("Archard ratio of the %s %g: not within 2 %% of 1" % (name, ratio))
    if not re.search(r"Archard +worn volume / \(K W s\): pin (\S+) .*disk (\S+) ", stdout):
        fail("no Archard line")

    steps = int(summary["slow_steps"])
    if steps != len(rows) - 1:
        fail("%d slow steps for %d rows" % (steps, len(rows)))
    m = re.search(r"wear steps +adaptive, tolerance 0.001: (\d+) slow steps", stdout)
    if not m or int(m.group(1)) != steps:
        fail("no wear-steps line with %d slow steps" % steps)

    pressure = LOAD / (math.pi * FLAT_RADIUS ** 2)
    # the roughness along the path and where the law's depth axis ends
    h = [float(r["h_mean_m"]) for r in rows]
    rq = [law.value("rq", pressure, x) for x in h]
    rq_settle = None
    for k in range(len(s) - 1, -1, -1):
        if abs(rq[k] - rq[-1]) > SETTLE_TOLERANCE * rq[-1]:
            break
        rq_settle = s[k]
    s_last = distance_at_depth(s, h, law.h[-1])
    depth = settled_depth(law, law_path, pressure)
    s_depth = None if depth is None else distance_at_depth(s, h, depth)
    m = re.search(r"law lookups +(\d+) lookups: (\d+) clamped below p = \S+ Pa, (\d+) above p = \S+ Pa, (\d+) beyond",
                  stdout)
    if not m:
        fail("no law lookups line")
    lookups, below, above, beyond = (int(x) for x in m.groups())
    print("law depth: last worn depth %.4g nm reached at s = %s m (%.4g %% of the sliding beyond it); lookups %d: "
          "%d (%.3g %%) beyond the last worn depth, %d (%.3g %%) below the lowest pressure, %d above"
          % (1e9 * law.h[-1], "%.4g" % s_last if s_last is not None else "-",
             100 * (s[-1] - s_last) / s[-1] if s_last is not None else 0.0, lookups, beyond, 100 * beyond / lookups,
             below, 100 * below / lookups, above))
    print("roughness: Rq(p, h_mean) %.4g -> %.4g nm, within 2 %% of its end from s = %.4g m; the law's Rq at %.4g Pa "
          "settled from h = %s nm (s = %s m)"
          % (1e9 * rq[0], 1e9 * rq[-1], rq_settle, pressure, "%.4g" % (1e9 * depth) if depth is not None else "-",
             "%.4g" % s_depth if s_depth is not None else "-"))
    if depth is None:
        fail("the law's Rq at %g Pa has not settled by its last worn depth %g m (change per sigma/10 not below 1 %% "
             "of the first): holding its last column beyond it truncates the roughness run-in" % (pressure, law.h[-1]))
    if s_last is not None and rq_settle > s_last:
        fail("Rq along the path settles at s = %g m, after the pin wears past the law's last depth (s = %g m)"
             % (rq_settle, s_last))

    check = subprocess.run([sys.executable, os.path.join(HERE, "check_state_law_pod.py"), out, "--law", law_path,
                            "--flat", repr(pressure), "--counterface-ratio", "1.0", "--vtk", "3",
                            "--min-distance", "999", "--no-expect-fall", "--min-mu-change", "0.004"], capture_output=True, text=True)
    print(check.stdout.strip())
    if check.returncode != 0:
        fail("check_state_law_pod.py: " + check.stdout.strip().splitlines()[-1])
    print("tribometer: 1 km in %.3g s, %d slow steps, settles within 2 %% of mu = %.5g at s = %.4g m; Archard pin "
          "%.5f, disk %.5f (mu_eff %.6g -> %.6g)" % (wall, steps, steady, settle, ratios[0], ratios[1], mu[0], mu[-1]))
    print("check_tribometer: ok")


if __name__ == "__main__":
    main()
