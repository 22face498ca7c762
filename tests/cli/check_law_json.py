#!/usr/bin/python3
"""Checks the law fitted to tests/data/fric_ave_time.txt, which was generated from
mu = 0.4 + 0.3 exp(-(s - 1e-7)/3e-7) (+ ripple of amplitude 0.002) after a peak of 0.7 at 1e-7 m."""
import json
import sys

law = json.load(open(sys.argv[1]))
fit = law["fit"]
checks = {
    "format": law["format"] == "runin-friction-law",
    "columns": law["source"]["distance_column"] == "v_slide" and law["source"]["mu_column"] == "c_fric[3]",
    "units": law["units"]["distance"] == "m" and law["units"]["distance_in_m"] == 1.0,
    "table kept from s = 0": len(law["table"]["distance"]) == 201 and law["table"]["mu"][0] == 0.0,
    "s_peak": abs(fit["s_peak"] - 1e-7) < 1e-15,
    "mu_0": abs(fit["mu_0"] - 0.7) < 0.005,
    "mu_ss": abs(fit["mu_ss"] - 0.4) < 0.002,
    "s0": abs(fit["s0"] / 3e-7 - 1) < 0.02,
    "rms_residual": 0.0005 < fit["rms_residual"] < 0.002,  # the ripple is rms 0.0014
}
failed = [name for name, ok in checks.items() if not ok]
print("fit:", {k: fit[k] for k in ("mu_0", "mu_ss", "s0", "rms_residual")}, "failed:", failed)
sys.exit(1 if failed else 0)
