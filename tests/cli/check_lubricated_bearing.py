#!/usr/bin/python3
"""Runs the lubricated mode of `runin journal-bearing` on a case and checks its outputs against its summary.

usage: check_lubricated_bearing.py RUNIN CASE OUTDIR [--stribeck [--stribeck-flag]] [--png] [--frames N]

Checks: exit 0; lubricated.csv (and stribeck.csv, PNGs, the VTK series of N frames with the film fields) exist;
the summary's numbers (initial lambda, peak film and asperity pressure, end state, Stribeck minimum) are those
of the CSV to their printed digits; the run starts in mixed lubrication (1 <= lambda <= 2.5) and ends with the
film carrying all but < 1e-4 of the load.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys


def fail(message):
    print("check_lubricated_bearing: FAIL: " + message)
    sys.exit(1)


def close(printed, value, digits=4):
    """printed (a %.{digits}g string) agrees with value to its printed digits"""
    p = float(printed)
    if value == 0.0:
        return p == 0.0
    return abs(p - value) <= 0.5 * 1.001 * 10 ** (math.floor(math.log10(abs(value))) - digits + 1)


def read(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runin")
    parser.add_argument("case")
    parser.add_argument("outdir")
    parser.add_argument("--stribeck", action="store_true")
    parser.add_argument("--png", action="store_true")
    parser.add_argument("--frames", type=int, default=0)
    parser.add_argument("--stribeck-flag", action="store_true", help="pass --stribeck to runin (no [stribeck] table)")
    a = parser.parse_args()
    shutil.rmtree(a.outdir, ignore_errors=True)
    cmd = [a.runin, "journal-bearing", a.case, "--output-dir", a.outdir] + ([] if a.png else ["--no-plot"]) + (
        ["--stribeck"] if a.stribeck_flag else [])
    run = subprocess.run(cmd, capture_output=True, text=True)
    print(run.stdout)
    print(run.stderr, file=sys.stderr)
    if run.returncode != 0:
        fail("exit code %d" % run.returncode)
    out = run.stdout
    rows = read(os.path.join(a.outdir, "lubricated.csv"))
    if len(rows) < 10:
        fail("lubricated.csv has %d rows" % len(rows))
    first, last = rows[0], rows[-1]
    m = re.search(r"regime +initial lambda (\S+) \((\w[\w ]*)\), peak film pressure (\S+) MPa, peak asperity "
                  r"pressure (\S+) MPa", out)
    if not m:
        fail("no regime line")
    if not close(m.group(1), first["lambda"]):
        fail("initial lambda %s vs CSV %g" % (m.group(1), first["lambda"]))
    if not 1.0 <= first["lambda"] <= 2.5 or m.group(2) != "mixed":
        fail("the run does not start in mixed lubrication: lambda %g (%s)" % (first["lambda"], m.group(2)))
    if not close(m.group(3), 1e-6 * max(r["peak_film_pressure_Pa"] for r in rows)):
        fail("peak film pressure %s vs CSV" % m.group(3))
    if not close(m.group(4), 1e-6 * max(r["peak_asperity_pressure_Pa"] for r in rows)):
        fail("peak asperity pressure %s vs CSV" % m.group(4))
    m = re.search(r"end +t = (\S+) s, s = (\S+) m: eps (\S+), attitude (\S+) rad, h_min (\S+) um, lambda (\S+) "
                  r"\([\w ]+\), asperity share (\S+), mu (\S+) ", out)
    if not m:
        fail("no end line")
    for printed, key, scale, digits in [(1, "t_s", 1, 6), (2, "distance_m", 1, 6), (3, "eccentricity", 1, 5),
                                        (5, "h_min_m", 1e6, 4), (6, "lambda", 1, 4), (7, "asperity_share", 1, 4),
                                        (8, "mu", 1, 5)]:
        if not close(m.group(printed), scale * last[key], digits):
            fail("end %s: summary %s vs CSV %g" % (key, m.group(printed), scale * last[key]))
    if not last["asperity_share"] < 1e-4:
        fail("the film does not take over: asperity share %g at the end" % last["asperity_share"])
    if not last["mu"] < 0.5 * first["mu"]:
        fail("no run-in: mu %g -> %g" % (first["mu"], last["mu"]))
    m = re.search(r"wear +bore: max (\S+) nm, mean (\S+) nm, volume (\S+) mm\^3", out)
    if not m or not close(m.group(1), 1e9 * last["h_max_m"]) or not close(m.group(3), 1e9 * last["worn_volume_m3"], 6):
        fail("wear line vs CSV")
    wanted = ["lubricated.csv"]
    if a.stribeck:
        wanted.append("stribeck.csv")
        pts = read(os.path.join(a.outdir, "stribeck.csv"))
        best = min(pts, key=lambda r: r["mu"])
        m = re.search(r"Stribeck +(\d+) speeds .*friction minimum mu (\S+) at lambda (\S+),", out)
        if not m or int(m.group(1)) != len(pts) or not close(m.group(2), best["mu"], 5) or not close(m.group(3), best["lambda"]):
            fail("Stribeck line vs stribeck.csv")
        if not (pts[0]["asperity_share"] > 0.9 and pts[-1]["asperity_share"] < 1e-6):
            fail("the sweep does not span boundary to full film")
    if a.png:
        wanted += ["lubricated.png"] + (["stribeck.png"] if a.stribeck else [])
    for name in wanted:
        if not os.path.getsize(os.path.join(a.outdir, name)) > 0:
            fail("missing " + name)
    if a.frames:
        pvd = os.path.join(a.outdir, "vtk", "bore_film.pvd")
        text = open(pvd).read()
        files = re.findall(r'file="([^"]+)"', text)
        if len(files) != a.frames:
            fail("%d VTK frames, expected %d" % (len(files), a.frames))
        vts = open(os.path.join(a.outdir, "vtk", files[-1]), errors="replace").read()
        for field in ["film_thickness", "pressure", "fill_fraction", "worn_depth", "asperity_pressure"]:
            if 'Name="%s"' % field not in vts:
                fail("VTK frame lacks " + field)
    print("check_lubricated_bearing: OK (%d samples, lambda %.4g -> %.4g, mu %.5g -> %.5g)"
          % (len(rows), first["lambda"], last["lambda"], first["mu"], last["mu"]))


if __name__ == "__main__":
    main()
