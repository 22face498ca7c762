#!/usr/bin/env python3
"""tools/sweep_micro_law.py on the journal bearing with the micro law: every run completes, the values span a
decade (e ends at the file's 0.5, its upper bound being 1), the two keys share the base run, and rerunning one
row's element case on its kept law reproduces the row. Standard library only.

  check_sweep_micro.py --lmp LMP_RUNIN --runin RUNIN --workdir DIR
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

HERE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--runin", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    out = os.path.join(args.workdir, "sweep")
    case = os.path.join(HERE, "inputs", "journal_bearing_micro.toml")
    result = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "tools", "sweep_micro_law.py"), "--lmp", args.lmp,
                             "--runin", args.runin, "--element", "journal-bearing", "--case", case,
                             "--output-dir", out, "--no-plot"], capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"exit {result.returncode}:\n{result.stdout[-1500:]}{result.stderr[-1500:]}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    if [r["key"] for r in rows] != ["d_c"] * 3 + ["e"] * 3 or any(r["status"] != "ok" for r in rows):
        fail(f"rows {[(r['key'], r['status']) for r in rows]}")
    expected = {"d_c": [10 ** -0.5, 1.0, 10 ** 0.5], "e": [0.1, 10 ** -0.5, 1.0]}
    for key, factors in expected.items():
        mine = [r for r in rows if r["key"] == key]
        for r, factor in zip(mine, factors):
            if not math.isclose(float(r["factor"]), factor, rel_tol=1e-11):
                fail(f"{key}: factor {r['factor']}, expected {factor}")
    base = [r for r in rows if float(r["factor"]) == 1.0]
    if len(base) != 2 or base[0]["case"] != base[1]["case"] or base[0]["peak_friction_force_N"] != base[1]["peak_friction_force_N"]:
        fail("the keys do not share one base run")
    if len({r["peak_friction_force_N"] for r in rows if r["key"] == "d_c"}) != 3:
        fail("d_c does not change the peak friction force")
    # a row reruns from what the sweep kept: the element on the row's own law
    row = rows[0]
    run_dir = os.path.join(out, row["case"])
    direct = os.path.join(args.workdir, "direct")
    subprocess.run([args.runin, "journal-bearing", case, "--law", os.path.join(run_dir, "law.json"), "--output-dir",
                    direct, "--no-plot"], check=True, capture_output=True)
    with open(os.path.join(direct, "journal_bearing_summary.csv"), newline="") as f:
        summary = next(csv.DictReader(f))
    for name, value in summary.items():
        if row[name] != value:
            fail(f"{row['case']}: {name} = {value} in a direct run, {row[name]} in the sweep")
    print("ok: " + "; ".join(f"{r['key']} x {float(r['factor']):.3g}: peak {float(r['peak_friction_force_N']):.4g} N, "
                             f"break-away {float(r['breakaway_time_s']):.4g} s" for r in rows))


if __name__ == "__main__":
    main()
