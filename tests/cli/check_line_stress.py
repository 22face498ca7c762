#!/usr/bin/env python3
"""Subsurface stress of the line contacts in the summary (doc/subsurface_stress.md).

usage: check_line_stress.py RUNIN SOURCE_DIR WORKDIR journal-bearing|piston-ring

Runs the thesis case (inputs/journal_bearing.toml: two Steel1020 bearing halves; inputs/piston_ring.toml: grey
cast iron rings A and B) three times and checks the summary and the VTK series:
  1. as shipped: per contact a start line from McEwen's closed form with the Hertz p0 and an end line from the
     influence tier; both bodies elastic against S_y (steel: 350 MPa from the file; grey iron: 195 MPa from the
     file, its 0.1 % compressive proof stress); peak / p0 at the start (mu = 0.95, on the surface) in [1.70, 1.78]
     (McEwen: 1.744 at nu = 0.29, 1.766 at 0.27); no WARNING; vtk/subsurface*.pvd with 2 frames per contact;
  2. with the material file replaced by one whose S_y = 1 MPa: every body yields at the start -> WARNING lines;
  3. without the material keys: "S_y unknown".
"""
import os
import re
import subprocess
import sys

CASES = {
    "journal-bearing": dict(case="journal_bearing.toml", contacts=["lower half", "upper half"],
                            bodies=["bearing", "shaft"], keys=["materials", "bearing_material", "shaft_material"],
                            name="Steel1020", hertz_p0=[1.476e6, 1.476e6], sy=3.5e8, tabor=False,
                            pvd=["subsurface.pvd", "subsurface_upper.pvd"], hint="contact.materials"),
    "piston-ring": dict(case="piston_ring.toml", contacts=["ring A face", "ring B face"],
                        bodies=["liner", "ring"], keys=["materials", "ring_material", "liner_material"],
                        name="GreyCastIron", hertz_p0=[1.904e6, 1.649e6], sy=1.95e8, tabor=False,
                        pvd=["subsurface.pvd", "subsurface_B.pvd"], hint="material.materials"),
}
NUM = r"([0-9.e+-]+)"


def run(runin, element, case, out):
    p = subprocess.run([runin, element, case, "--output-dir", out, "--no-plot"], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"check_line_stress: {case}: exit {p.returncode}: {p.stderr}")
    return p.stdout


def body_lines(text, contact, when):
    m = re.search(rf"subsurface stress {contact} {when} .*\n((?:    .*\n)+)", text)
    return m.group(1).splitlines() if m else []


def main():
    runin, source, work, element = sys.argv[1:5]
    c = CASES[element]
    case = os.path.join(source, "inputs", c["case"])
    os.makedirs(work, exist_ok=True)
    failures = []

    # 1. as shipped
    out = os.path.join(work, "shipped")
    text = run(runin, element, case, out)
    for k, contact in enumerate(c["contacts"]):
        start = re.search(rf"subsurface stress {contact} start .*McEwen.*p0 = {NUM} Pa, b = {NUM} m, mu = {NUM}", text)
        end = re.search(rf"subsurface stress {contact} end .*influence functions.*p0 = {NUM} Pa", text)
        if not start or not end:
            failures.append(f"{contact}: no start (McEwen) / end (influence) lines")
            continue
        p0 = float(start.group(1))
        if abs(p0 / c["hertz_p0"][k] - 1.0) > 0.01:
            failures.append(f"{contact}: Hertz p0 = {p0}, expected {c['hertz_p0'][k]}")
        for when in ("start", "end"):
            lines = body_lines(text, contact, when)
            for body in c["bodies"]:
                line = next((l for l in lines if l.strip().startswith(f"{body} ({c['name']})")), None)
                m = line and re.search(rf"peak von Mises {NUM} Pa.*S_y = {NUM} Pa(.*): (\w+) \(peak / S_y", line)
                if not m:
                    failures.append(f"{contact} {when}: no verdict line for {body} in {lines}")
                    continue
                peak, sy, note, verdict = float(m.group(1)), float(m.group(2)), m.group(3), m.group(4)
                if abs(sy / c["sy"] - 1.0) > 1e-3 or ("Tabor" in note) != c["tabor"] or verdict != "elastic":
                    failures.append(f"{contact} {when} {body}: S_y = {sy}{note}: {verdict}")
                if when == "start" and not 1.70 <= peak / p0 <= 1.78:
                    failures.append(f"{contact} start {body}: peak / p0 = {peak / p0:.4f} not in [1.70, 1.78]")
    if "WARNING" in text:
        failures.append("WARNING in the shipped case (every body is elastic)")
    if "subsurface.pvd" in text:
        for pvd in c["pvd"]:
            path = os.path.join(out, "vtk", pvd)
            frames = re.findall(r'file="([^"]+\.vts)"', open(path).read()) if os.path.exists(path) else []
            if len(frames) != 2 or not all(os.path.getsize(os.path.join(out, "vtk", f)) > 0 for f in frames):
                failures.append(f"{pvd}: frames {frames}")

    # 2. a material file with S_y = 1 MPa: WARNING lines at the start for both bodies of every contact
    weak = os.path.join(work, "weak.runin")
    with open(weak, "w") as f:
        f.write(f"material {c['name']}  66.0e9  0.27  7150.0  1.53e9  1.0e6\n")
    text_case = open(case).read()
    weak_case = os.path.join(work, "weak.toml")
    with open(weak_case, "w") as f:
        f.write(re.sub(r'materials = "[^"]+"', f'materials = "{weak}"', text_case))
    text = run(runin, element, weak_case, os.path.join(work, "weak"))
    warnings = [l for l in text.splitlines() if l.strip().startswith("WARNING:") and "yields below the" in l]
    starts = [w for w in warnings if "at the start of the run" in w]
    if len(starts) != 2 * len(c["contacts"]):
        failures.append(f"S_y = 1 MPa: {len(starts)} start WARNING lines, expected {2 * len(c['contacts'])}")

    # 3. no material keys: S_y unknown
    bare_case = os.path.join(work, "bare.toml")
    with open(bare_case, "w") as f:
        f.write("".join(l for l in text_case.splitlines(True)
                        if not any(l.strip().startswith(k + " ") for k in c["keys"])))
    text = run(runin, element, bare_case, os.path.join(work, "bare"))
    unknown = text.count(f"S_y unknown (set {c['hint']})")
    if unknown != 4 * len(c["contacts"]):
        failures.append(f"no materials: {unknown} 'S_y unknown' lines, expected {4 * len(c['contacts'])}")

    for f in failures:
        print("check_line_stress:", f, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
