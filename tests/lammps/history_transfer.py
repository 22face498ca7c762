#!/usr/bin/env python3
"""Reverse history transfer: tests/lammps/decks/in.history_transfer run with neighbor bins that move the
contact between the two atoms mid-pass and with bins that never do. The pair must change its holding atom in
the first run (else the test proves nothing), and the forces on atom 2 must agree with the second run to 1e-12
of their largest value: a transfer_history that does not turn or carry the spring (or is never called, as an
override of a signature the library no longer has) breaks that.

usage: history_transfer.py LMP WORKDIR   (LMP may carry arguments, e.g. "lmp -in plugin_load.in")"""
import os
import re
import shutil
import subprocess
import sys

lmp, work = sys.argv[1], sys.argv[2]
deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks", "in.history_transfer")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def run(binsize):
    """Thermo rows (step, force on atom 2) and the atoms that held the contact (the local dump)."""
    out = subprocess.run(lmp.split() + ["-in", deck, "-var", "binsize", binsize, "-log", "none", "-echo", "none"],
                         cwd=work, capture_output=True, text=True, check=True).stdout
    rows = [l.split() for l in out.splitlines() if re.match(r"^\s*\d+\s+-?\d", l) and len(l.split()) == 4]
    lines = open(os.path.join(work, "holder.local")).read().splitlines()
    holders = {int(float(lines[k + 1].split()[-1])) for k, l in enumerate(lines) if l.startswith("ITEM: ENTRIES")
               and k + 1 < len(lines) and not lines[k + 1].startswith("ITEM")}
    return [[float(v) for v in r] for r in rows], holders


(moved, holders), (fixed, _) = run("4.0e-7"), run("0.0")
if holders != {1, 2}:
    sys.exit(f"FAIL: the contact was held by atoms {sorted(holders)} only; the bins did not move it")
scale = max(abs(v) for r in fixed for v in r[1:])
worst = max(abs(a - b) for ra, rb in zip(moved, fixed) for a, b in zip(ra[1:], rb[1:]))
if len(moved) != len(fixed) or not scale > 0 or worst > 1e-12 * scale:
    sys.exit(f"FAIL: forces differ by {worst:.3e} N (largest force {scale:.3e} N) when the contact changes atom")
print(f"ok: the contact moved between atoms 1 and 2; {len(moved)} rows, forces agree to {worst / scale:.2e} "
      f"of {scale:.3e} N")
