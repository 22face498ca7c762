#!/usr/bin/python3
"""Stress sweep of `runin journal-bearing` (stdlib only; ctest label stress).

usage: stress_journal_bearing.py RUNIN BASE_CASE.toml WORKDIR

From the long run-in case (inputs/journal_bearing_runin.toml, 20 s, 512 nodes) shortened to 5 s:
mu0 in {0, 2} (mu_kinetic = 0.8 mu0), load x1 and x1000, Archard k 1e-8 and 1e-1, near-zero
clearance (1 nm), each at x1 and x1000 load. Each run must finish with a finite CSV (exit 0) or
stop with exit 1 and one line "runin: error: ...". A crash, a NaN, exit 2 (the cases are valid
input) or a run past the timeout fails the sweep.
Work cap: k = 0.1 over the full 20 s needs about 2.3e5 wear updates (contact re-solves; it ran
282 s before the cap), so it must stop at once; so must k = 0.1 over 5 s (4.4e4 updates, 44 s) with the "exceed the cap" message.
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

from case_text import edit
import time


def cases(base):
    short = edit(edit(base, "run", "t_end", "5.0"), "run", "frame_times", "[0.0, 5.0]")
    load = float(re.search(r"^load\s*=\s*([^\s#]+)", base, re.M).group(1))
    for factor in (1.0, 1000.0):
        scaled = edit(short, "bearing", "load", repr(load * factor))
        for mu0 in (0.0, 2.0):
            text = edit(edit(scaled, "friction", "mu_static", repr(mu0)), "friction", "mu_kinetic", repr(0.8 * mu0))
            yield f"mu0_{mu0:g}_load{factor:g}", text, None
        for k in (1e-8, 1e-1):
            # k = 0.1 slips (x1 load) over ~0.09 m in 2e-6 m wear steps: above the default cap.
            stop = "exceed the cap of" if k == 1e-1 and factor == 1.0 else None
            yield f"k_{k:g}_load{factor:g}", edit(scaled, "wear", "coefficient", repr(k)), stop
        yield f"clearance_1nm_load{factor:g}", edit(scaled, "bearing", "clearance", "1e-9"), None
    yield "k_0.1_full_run", edit(base, "wear", "coefficient", "0.1"), "exceed the cap of"


def main():
    runin, base_path, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    base = open(base_path).read()
    failures = []
    for name, text, expected_stop in cases(base):
        case = os.path.join(work, name + ".toml")
        with open(case, "w") as f:
            f.write(text)
        out = os.path.join(work, name)
        shutil.rmtree(out, ignore_errors=True)  # a stopped run keeps an earlier run's output
        start = time.monotonic()
        try:
            p = subprocess.run([runin, "journal-bearing", case, "--output-dir", out, "--no-plot"],
                               capture_output=True, text=True, timeout=120)
        except subprocess.TimeoutExpired:
            failures.append(f"{name}: timed out (120 s)")
            continue
        seconds = time.monotonic() - start
        lines = p.stderr.strip().splitlines()
        if p.returncode == 0:
            with open(os.path.join(out, "journal_bearing.csv"), newline="") as f:
                rows = list(csv.DictReader(f))
            if not rows or not all(math.isfinite(float(v)) for r in rows for v in r.values()):
                failures.append(f"{name}: non-finite output")
            if expected_stop:
                failures.append(f"{name}: finished, expected a stop with '{expected_stop}'")
            print(f"{name:24s} ok in {seconds:.1f} s: {len(rows)} rows, wear {float(rows[-1]['wear_volume_m3']):.3g} m^3, "
                  f"mu {float(rows[-1]['mu']):.3g}")
        else:
            if p.returncode != 1 or len(lines) != 1 or not lines[0].startswith("runin: error: "):
                failures.append(f"{name}: exit {p.returncode}, stderr {p.stderr!r}")
            elif expected_stop and expected_stop not in lines[0]:
                failures.append(f"{name}: expected '{expected_stop}', got {lines[0]!r}")
            if os.path.exists(out):
                failures.append(f"{name}: output left behind by a stopped run")
            print(f"{name:24s} stopped in {seconds:.1f} s (exit {p.returncode}): {p.stderr.strip()}")
    for f in failures:
        print("stress_journal_bearing:", f, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
