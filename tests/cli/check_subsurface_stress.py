#!/usr/bin/env python3
"""Subsurface stress in the pin-on-disk summary (doc/subsurface_stress.md).

usage: check_subsurface_stress.py RUNIN SOURCE_DIR WORKDIR

Runs inputs/pin_on_disk.toml (Cu pin on Al disk, Hertz p0 = 260 MPa, mu = 0.95) and checks the summary:
the start is Hamilton's closed form, the end the influence tier; the frictionless disk peak is 0.59-0.63 p0
(0.62 p0 at nu = 0.3, slightly less at the disk's nu = 0.33); the Al disk (S_y = 34 MPa) gets a WARNING
line at start and end; subsurface.pvd indexes two subsurface_*.vts frames when VTK is built.
"""
import os
import re
import subprocess
import sys


def main():
    runin, source, work = sys.argv[1:4]
    out = os.path.join(work, "out")
    p = subprocess.run([runin, "pin-on-disk", os.path.join(source, "inputs", "pin_on_disk.toml"), "--output-dir", out,
                        "--no-plot"], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"check_subsurface_stress: exit {p.returncode}: {p.stderr}")
    text = p.stdout
    failures = []
    start = re.search(r"subsurface stress start .*Hamilton.*p0 = ([0-9.e+-]+) Pa", text)
    end = re.search(r"subsurface stress end .*influence functions", text)
    if not start or not end:
        sys.exit("check_subsurface_stress: no start/end subsurface stress lines in\n" + text)
    p0 = float(start.group(1))
    if abs(p0 / 2.60e8 - 1.0) > 0.01:
        failures.append(f"Hertz p0 = {p0} Pa, expected 2.60e8 (thesis set-up)")
    free = re.search(r"frictionless: disk peak von Mises ([0-9.e+-]+) Pa", text)
    if not free or not 0.59 <= float(free.group(1)) / p0 <= 0.63:
        failures.append(f"frictionless disk peak / p0 not in [0.59, 0.63]: {free.group(1) if free else None}")
    disk = re.findall(r"disk \(Al\)\s+peak von Mises ([0-9.e+-]+) Pa.*S_y = ([0-9.e+-]+) Pa: (\w+)", text)
    if len(disk) != 2 or any(v != "YIELDS" or float(a) <= float(s) for a, s, v in disk):
        failures.append(f"disk lines: {disk}")
    warnings = [l for l in text.splitlines() if l.strip().startswith("WARNING: the disk (Al) yields")]
    if len(warnings) != 2:
        failures.append(f"expected 2 disk WARNING lines, got {len(warnings)}")
    if "subsurface.pvd" in text:
        pvd = open(os.path.join(out, "subsurface.pvd")).read()
        frames = re.findall(r'file="(subsurface_\d+\.vts)"', pvd)
        if len(frames) != 2 or not all(os.path.getsize(os.path.join(out, f)) > 0 for f in frames):
            failures.append(f"subsurface.pvd frames: {frames}")
    for f in failures:
        print("check_subsurface_stress:", f, file=sys.stderr)
    print(text)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
