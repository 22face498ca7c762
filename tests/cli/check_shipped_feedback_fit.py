#!/usr/bin/env python3
"""The shipped fit inputs/feedback_fitted_piston_ring.toml is the thesis's ch. 3 model fitted to the lubricated piston
ring's run-in as the code runs it now: run inputs/piston_ring_lubricated.toml, fit it with `runin fit-feedback`, and
compare every fitted constant with the shipped file (relative 1e-6); then `runin feedback` runs the shipped file and
its mu(t) must meet the ring's cycle-mean mu(t) within 5 % (the fitted model reproduces the element's friction).

  check_shipped_feedback_fit.py --runin RUNIN --workdir DIR
"""
import argparse
import csv
import os
import sys
import tomllib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import SOURCE_DIR, fail, fresh_dir, run_or_fail  # noqa: E402

SHIPPED = os.path.join(SOURCE_DIR, "inputs", "feedback_fitted_piston_ring.toml")
CASE = os.path.join(SOURCE_DIR, "inputs", "piston_ring_lubricated.toml")
KEYS = (("model", "C1"), ("model", "C2"), ("model", "K1"), ("model", "K2"), ("run", "R0"), ("fit", "R_star"))


def run(command):
    return run_or_fail(command).stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    fresh_dir(a.workdir)
    ring = os.path.join(a.workdir, "ring")
    run([a.runin, "piston-ring", CASE, "--output-dir", ring, "--no-plot"])
    fitted = os.path.join(a.workdir, "fit", "fit.toml")
    run([a.runin, "fit-feedback", os.path.join(ring, "lubricated.csv"), "--t-column", "time_s", "--mu-column", "mu",
         "--r-column", "R_m", "--r-scale", "1e6", "--kind", "lubricated", "--output", fitted, "--no-plot"])
    with open(SHIPPED, "rb") as f:
        shipped = tomllib.load(f)
    with open(fitted, "rb") as f:
        fresh = tomllib.load(f)
    for table, key in KEYS:
        s, n = shipped[table][key], fresh[table][key]
        print(f"{table}.{key}: shipped {s:.10g}, refit {n:.10g}")
        if abs(n / s - 1.0) > 1e-6:
            fail(f"{table}.{key}: the shipped fit {s:.10g} is not the fit of the ring as it runs now ({n:.10g}); "
                 "regenerate inputs/feedback_fitted_piston_ring.toml (doc/validation.md)")
    out = os.path.join(a.workdir, "feedback")
    run([a.runin, "feedback", SHIPPED, "--output-dir", out, "--no-plot"])
    with open(os.path.join(ring, "lubricated.csv")) as f:
        data = [(float(r["time_s"]), float(r["mu"])) for r in csv.DictReader(f)]
    with open(os.path.join(out, "feedback.csv")) as f:
        rows = list(csv.DictReader(f))
    t_model = [float(r["t"]) for r in rows]
    mu_model = [float(r["mu"]) for r in rows]
    worst = 0.0
    for t, mu in data:
        k = min(range(len(t_model)), key=lambda i: abs(t_model[i] - t))
        if abs(t_model[k] - t) > 1e-9 * max(1.0, t) + 0.5 * (t_model[1] - t_model[0]):
            fail(f"feedback.csv has no sample near t = {t}")
        worst = max(worst, abs(mu_model[k] / mu - 1.0))
    print(f"runin feedback on the shipped fit: mu(t) within {worst:.4f} of the ring's cycle-mean mu (limit 0.05)")
    if not worst <= 0.05:
        fail(f"the fitted model misses the ring's mu(t) by {worst:.4f} > 0.05")
    print("PASS")


if __name__ == "__main__":
    main()
