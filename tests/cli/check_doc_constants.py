#!/usr/bin/env python3
"""Doc constants that drifted from the code once: the steady-state band of doc/pin_on_disk.md is
PinOnDiskSummary::steady_tolerance, and its table's steady time is what `runin pin-on-disk` prints for the
shipped case.

usage: check_doc_constants.py RUNIN SOURCE_DIR WORKDIR"""
import os
import re
import subprocess
import sys

runin, source, work = sys.argv[1:4]
header = open(os.path.join(source, "src/continuum/pin_on_disk.h")).read()
tolerance = float(re.search(r"steady_tolerance = ([0-9.eE+-]+);", header).group(1))
doc = open(os.path.join(source, "doc/pin_on_disk.md")).read()
bands = {float(b) for b in re.findall(r"speed stay within ([0-9.]+) % of their final values", doc)}
if bands != {100.0 * tolerance}:
    sys.exit(f"FAIL: doc/pin_on_disk.md gives the steady band as {sorted(bands)} %, the code uses {100 * tolerance} %")
printed = subprocess.run([runin, "pin-on-disk", os.path.join(source, "inputs/pin_on_disk.toml"), "--output-dir",
                          work, "--no-plot"], capture_output=True, text=True, check=True).stdout
steady = re.search(r"steady state\s+([0-9.]+) s", printed).group(1)
documented = re.search(r"\| steady state \| from ([0-9.]+) s", doc).group(1)
if steady != documented:
    sys.exit(f"FAIL: doc/pin_on_disk.md's table says steady from {documented} s, the program prints {steady} s")
print(f"ok: band {100 * tolerance} % and steady time {steady} s agree with the code")
