#!/usr/bin/env python3
"""runin sweep: runs the study twice (it must rerun identically), checks its table (every key at `--points`
values, log-spaced over `--span` around the case's own value, which is the middle row and the base case's
numbers), and reruns each row's case file directly with the element's command: the six key numbers must equal
the row's. Standard library only.

  check_sweep.py --runin BIN --element journal-bearing --case CASE --workdir DIR [--key K ...] [--span 10]
                 [--points 3] [--expect-keys K ...]
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

NUMBERS = ["peak_friction_force_N", "peak_time_s", "breakaway_time_s", "steady_time_s", "steady_mu", "wear_volume_m3"]
PREFIX = {"pin-on-disk": "pin_on_disk", "journal-bearing": "journal_bearing", "piston-ring": "piston_ring"}


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{' '.join(command)} exited with {result.returncode}:\n{result.stdout[-1500:]}{result.stderr[-1500:]}")
    return result.stdout


def expect_failures(args):
    out = os.path.join(args.workdir, "a")
    command = [args.runin, "sweep", args.element, args.case, "--output-dir", out, "--no-plot", "--span",
               repr(args.span), "--points", str(args.points)] + [x for key in args.key for x in ("--key", key)]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 1 or not result.stderr.startswith(f"runin: error: sweep: {args.expect_failed} of "):
        fail(f"exit {result.returncode} with {args.expect_failed} failing run(s) expected (1, one error line):\n"
             f"{result.stderr}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    failed = [r for r in rows if r["status"].startswith("failed: runin: error: ")]
    good = [r for r in rows if r["status"] == "ok" and all(r[n] != "" for n in ("peak_friction_force_N", "steady_mu"))]
    if len(failed) != args.expect_failed or len(failed) + len(good) != len(rows):
        fail(f"{len(failed)} failed and {len(good)} complete rows of {len(rows)}, expected {args.expect_failed} failed")
    if any(r[n] != "" for r in failed for n in NUMBERS):
        fail("a failed row holds numbers")
    print(f"ok: exit 1, {len(failed)} failed run(s) named in the table, {len(good)} other rows kept: "
          + "; ".join(r["status"][:90] for r in failed))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runin", required=True)
    parser.add_argument("--element", required=True, choices=sorted(PREFIX))
    parser.add_argument("--case", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--key", action="append", default=[])
    parser.add_argument("--span", type=float, default=10.0)
    parser.add_argument("--points", type=int, default=3)
    parser.add_argument("--expect-keys", nargs="+", help="the keys the table must hold, in order")
    parser.add_argument("--plot", action="store_true", help="the first run also draws sweep_tornado.png")
    parser.add_argument("--expect-failed", type=int, default=0,
                        help="runs that must fail: the sweep exits 1, keeps the other rows and names each failure")
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    if args.expect_failed:
        return expect_failures(args)
    tables = []
    for name in ("a", "b"):
        out = os.path.join(args.workdir, name)
        command = [args.runin, "sweep", args.element, args.case, "--output-dir", out,
                   "--span", repr(args.span), "--points", str(args.points)]
        if not (args.plot and name == "a"):
            command.append("--no-plot")
        for key in args.key:
            command += ["--key", key]
        run(command)
        with open(os.path.join(out, "sweep.csv")) as f:
            tables.append(f.read())
    if tables[0] != tables[1]:
        fail("two runs of the same sweep wrote different tables")
    out = os.path.join(args.workdir, "a")
    if args.plot:
        with open(os.path.join(out, "sweep_tornado.png"), "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                fail("sweep_tornado.png is not a PNG")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    keys = list(dict.fromkeys(r["key"] for r in rows))
    if args.expect_keys and keys != args.expect_keys:
        fail(f"keys {keys}, expected {args.expect_keys}")
    factors = [args.span ** (i / (args.points - 1) - 0.5) for i in range(args.points)]
    base_numbers = None
    for key in keys:
        mine = [r for r in rows if r["key"] == key]
        if len(mine) != args.points:
            fail(f"{key}: {len(mine)} rows, expected {args.points}")
        middle = mine[args.points // 2]
        base_value = float(middle["value"])
        for r, factor in zip(mine, factors):
            if r["status"] != "ok":
                fail(f"{key} x {factor:g}: {r['status']}")
            if not math.isclose(float(r["factor"]), factor, rel_tol=1e-11):
                fail(f"{key}: factor {r['factor']}, expected {factor!r}")
            if not math.isclose(float(r["value"]), base_value * factor, rel_tol=1e-11):
                fail(f"{key}: value {r['value']} != {base_value} x {factor}")
        numbers = [middle[n] for n in NUMBERS]
        if base_numbers is None:
            base_numbers = numbers
        elif numbers != base_numbers:
            fail(f"{key}: the middle row {numbers} is not the base case {base_numbers}")
    # every row is a direct run of its case file
    checked = set()
    for r in rows:
        if r["case"] in checked:
            continue
        checked.add(r["case"])
        direct = os.path.join(args.workdir, "direct", str(len(checked)))
        run([args.runin, args.element, os.path.join(out, r["case"]), "--output-dir", direct, "--no-plot"])
        with open(os.path.join(direct, PREFIX[args.element] + "_summary.csv"), newline="") as f:
            summary = next(csv.DictReader(f))
        for n in NUMBERS:
            if summary[n] != r[n]:
                fail(f"{r['case']}: {n} = {summary[n]!r} in a direct run, {r[n]!r} in the sweep")
    print(f"ok: {len(keys)} keys x {args.points} values, identical on a rerun; {len(checked)} case files rerun "
          f"directly give the same six numbers")


if __name__ == "__main__":
    main()
