#!/usr/bin/python3
"""Round trip of `runin fit-feedback` through `runin feedback` (stdlib only).

usage: check_feedback_fit.py RUNIN OUTDIR

Data from the exact solution R^2 = R*^2 + (R0^2 - R*^2) exp(-2 A K1 t), mu = C1 R + C2/R with the constants
of inputs/feedback_lubricated.toml (R0 = 6 above R*, t in minutes from t = 10 min, R in metres: fitted with
--t-scale 60 --r-scale 1e6, written as TOML) and inputs/feedback_dry.toml (R0 = 0.5 below R*, t and R in
the model's units, written as JSON, --no-plot). Checks: the fitted constants (A K1, B K2, C1, C2, R0) to 1e-6, the
[fit] provenance (source name, its SHA-256, columns), the comparison CSV and PNG; then `runin feedback` on the
fitted file reproduces the data's mu(t) and R(t) to 1e-6 relative at every data time. Last, R = 6 exp(-t/2000)
(towards 0, no equilibrium) is refused: exit 2, one line naming the status, nothing written. And an element's
output: inputs/pin_on_disk_feedback.toml's CSV fitted over the sliding distance (--drop-repeated-t: it stands still
while the pin sticks) gives back the case's C1, C2, A K1, B K2 and R0 to 1e-5.
"""
import csv
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys
import tomllib

from output_checks import close, finish, leftover_problems, png_problems

CASES = {
    # name: (C1, C2, K1, K2, A, B, R0, t_end, dt, kind)
    "lubricated": (0.02, 0.08, 1e-3, 4e-3, 1.0, 1.0, 6.0, 8000.0, 40.0, "lubricated"),
    "dry": (0.05, 0.2, 2e-3, 2e-3, 1.0, 2.0, 0.5, 5000.0, 25.0, "dry"),
}


def exact(c, t):
    C1, C2, K1, K2, A, B, R0 = c[:7]
    rs2 = B * K2 / (A * K1)
    R = math.sqrt(rs2 + (R0 * R0 - rs2) * math.exp(-2.0 * A * K1 * t))
    return R, C1 * R + C2 / R


def run(args):
    return subprocess.run(args, capture_output=True, text=True)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def round_trip(runin, out, name, problems):
    c = CASES[name]
    C1, C2, K1, K2, A, B, R0, t_end, dt, kind = c
    lub = name == "lubricated"
    directory = os.path.join(out, name)
    os.makedirs(directory)
    data = os.path.join(directory, f"{name}_runin.csv")
    n = int(round(t_end / dt)) + 1
    truth = []
    with open(data, "w") as f:
        f.write("# exact solution of the ch. 3 feedback model\n")
        f.write("time_min,mu_body,Ra_m,phase\n" if lub else "t,mu,R,phase\n")
        for i in range(n):
            t = dt * i
            R, mu = exact(c, t)
            truth.append((t, R, mu))
            if lub:
                f.write(f"{10.0 + t / 60.0!r},{mu!r},{R * 1e-6!r},run-in\n")
            else:
                f.write(f"{t!r},{mu!r},{R!r},run-in\n")
    case = os.path.join(directory, "fitted.toml" if lub else "fitted.json")
    columns = ["time_min", "mu_body", "Ra_m"] if lub else ["t", "mu", "R"]
    args = [runin, "fit-feedback", data, "--t-column", columns[0], "--mu-column", columns[1], "--r-column",
            columns[2], "--output", case, "--kind", kind]
    if lub:
        args += ["--t-scale", "60", "--r-scale", "1e6"]
    else:
        args += ["--no-plot"]  # one plot is enough (matplotlib's start-up dominates the test's time)
    r = run(args)
    if r.returncode != 0:
        problems.append(f"{name}: fit-feedback exit {r.returncode}: {r.stderr.strip()}")
        return
    with open(case, "rb") as f:
        doc = tomllib.load(f) if lub else json.load(f)
    m, fit = doc["model"], doc["fit"]
    expected = {"C1": C1, "C2": C2, "K1": A * K1, "K2": B * K2, "A": 1.0, "B": 1.0}
    for key, value in expected.items():
        if not close(m[key], value, 1e-6):
            problems.append(f"{name}: model.{key} = {m[key]!r}, expected {value!r}")
    if m["kind"] != kind:
        problems.append(f"{name}: model.kind = {m['kind']}")
    for key, value in {"R0": R0, "t_end": t_end, "output_interval": dt}.items():
        if not close(doc["run"][key], value, 1e-6):
            problems.append(f"{name}: run.{key} = {doc['run'][key]!r}, expected {value!r}")
    with open(data, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    want = {"source": os.path.basename(data), "source_sha256": sha, "t_column": columns[0],
            "mu_column": columns[1], "r_column": columns[2], "status": "converged", "points": n}
    for key, value in want.items():
        if fit.get(key) != value:
            problems.append(f"{name}: fit.{key} = {fit.get(key)!r}, expected {value!r}")
    if not close(fit["R_star"], math.sqrt(B * K2 / (A * K1)), 1e-6) or fit["mu_max_rel_error"] > 1e-8:
        problems.append(f"{name}: fit.R_star {fit['R_star']}, mu_max_rel_error {fit['mu_max_rel_error']}")
    stem = os.path.splitext(os.path.basename(case))[0]
    comparison = read_rows(os.path.join(directory, f"{stem}_comparison.csv"))
    if len(comparison) != n or max(abs(float(row["mu_rel_error"])) for row in comparison) > 1e-8:
        problems.append(f"{name}: comparison CSV: {len(comparison)} rows or mu error above 1e-8")
    if lub:
        problems += png_problems(directory, [f"{stem}_comparison.png"])
    elif os.path.exists(os.path.join(directory, f"{stem}_comparison.png")):
        problems.append(f"{name}: --no-plot wrote a PNG")
    problems += leftover_problems(directory)

    # `runin feedback` takes the fitted file unchanged and reproduces the data.
    run_dir = os.path.join(directory, "run")
    r = run([runin, "feedback", case, "--output-dir", run_dir, "--no-plot"])
    if r.returncode != 0:
        problems.append(f"{name}: feedback on the fitted file exit {r.returncode}: {r.stderr.strip()}")
        return
    if "fitted from" not in r.stdout or os.path.basename(data) not in r.stdout:
        problems.append(f"{name}: runin feedback does not name the fit's source")
    rows = read_rows(os.path.join(run_dir, "feedback.csv"))
    if len(rows) != n:
        problems.append(f"{name}: runin feedback wrote {len(rows)} rows, the data have {n}")
        return
    worst_mu = worst_R = worst_t = 0.0
    for row, (t, R, mu) in zip(rows, truth):
        worst_t = max(worst_t, abs(float(row["t"]) - t))
        worst_R = max(worst_R, abs(float(row["R"]) - R) / R)
        worst_mu = max(worst_mu, abs(float(row["mu"]) - mu) / mu)
    if worst_mu > 1e-6 or worst_R > 1e-6 or worst_t > 1e-9 * t_end:
        problems.append(f"{name}: runin feedback vs data: mu {worst_mu:.3g}, R {worst_R:.3g}, t {worst_t:.3g}")
    print(f"{name}: fitted file through runin feedback: max relative error mu {worst_mu:.3g}, R {worst_R:.3g}")


def no_equilibrium(runin, out, problems):
    directory = os.path.join(out, "decay")
    os.makedirs(directory)
    data = os.path.join(directory, "decay.csv")
    with open(data, "w") as f:
        f.write("t,mu,R\n")
        for i in range(101):
            t = 80.0 * i
            R = 6.0 * math.exp(-t / 2000.0)
            f.write(f"{t!r},{0.02 * R + 0.08 / R!r},{R!r}\n")
    case = os.path.join(directory, "out", "fitted.toml")
    r = run([runin, "fit-feedback", data, "--t-column", "t", "--mu-column", "mu", "--r-column", "R", "--output", case])
    lines = r.stderr.strip().splitlines()
    if r.returncode != 2 or len(lines) != 1 or "not fitted (no equilibrium roughness)" not in lines[0]:
        problems.append(f"decay towards 0: exit {r.returncode}, stderr {r.stderr.strip()!r}")
    if os.path.exists(os.path.join(directory, "out")):
        problems.append("decay towards 0: output written")


def pin_on_disk(runin, out, problems):
    """An element's output: the pin-on-disk feedback case (dR/ds, the pin sticks at times) fitted over the sliding
    distance in m recovers the case's constants."""
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    case_path = os.path.join(source, "inputs", "pin_on_disk_feedback.toml")
    with open(case_path, "rb") as f:
        f_case = tomllib.load(f)["friction"]
    directory = os.path.join(out, "pin_on_disk")
    r = run([runin, "pin-on-disk", case_path, "--output-dir", directory, "--no-plot"])
    if r.returncode != 0:
        problems.append(f"pin-on-disk exit {r.returncode}: {r.stderr.strip()}")
        return
    data = os.path.join(directory, "pin_on_disk.csv")
    fitted = os.path.join(directory, "fit", "fitted.toml")
    args = [runin, "fit-feedback", data, "--t-column", "sliding_distance_m", "--mu-column", "mu_law", "--r-column",
            "roughness", "--kind", "dry", "--output", fitted, "--no-plot"]
    r = run(args)  # the distance stands still while the pin sticks
    if r.returncode != 2 or "--drop-repeated-t keeps the first" not in r.stderr:
        problems.append(f"pin-on-disk without --drop-repeated-t: exit {r.returncode}, {r.stderr.strip()!r}")
    r = run(args + ["--drop-repeated-t"])
    if r.returncode != 0:
        problems.append(f"pin-on-disk fit exit {r.returncode}: {r.stderr.strip()}")
        return
    with open(fitted, "rb") as f:
        doc = tomllib.load(f)
    expected = {"C1": f_case["C1"], "C2": f_case["C2"], "K1": f_case["A"] * f_case["K1"],
                "K2": f_case["B"] * f_case["K2"]}
    worst = max(abs(doc["model"][k] - v) / v for k, v in expected.items())
    worst = max(worst, abs(doc["run"]["R0"] - f_case["R0"]) / f_case["R0"])
    if worst > 1e-5 or doc["fit"]["dropped_repeated_t"] < 1:
        problems.append(f"pin-on-disk: fitted constants off by {worst:.3g} relative, or no rows dropped")
    print(f"pin-on-disk over the sliding distance: constants within {worst:.3g} relative, "
          f"{doc['fit']['dropped_repeated_t']} rows at a repeated distance dropped")


def main():
    runin, out = sys.argv[1], sys.argv[2]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    problems = []
    for name in CASES:
        round_trip(runin, out, name, problems)
    no_equilibrium(runin, out, problems)
    pin_on_disk(runin, out, problems)
    finish("check_feedback_fit", problems, "fit-feedback round trip: " + ("FAILED" if problems else "ok"))


if __name__ == "__main__":
    main()
