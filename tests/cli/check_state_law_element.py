#!/usr/bin/env python3
"""Checks a line-contact machine element run on a state law (doc/state_law_continuum.md).

CSV: the columns <prefix>mu_eff, <prefix>h_max_m and <prefix><counter column> exist for every --prefix (default: none);
h_max never decreases; the counter body's worn volume is --ratio times the rough body's (<prefix><wear column>,
the law's counterface/body rate ratio, integrated by the same quadrature); mu_eff (--mu-column) falls by at least
--min-drop (relative) over the run. --vtk FILE FIELD...: the VTK file carries those field names.
"""
import argparse
import csv
import sys
import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402


ap = argparse.ArgumentParser()
ap.add_argument("csv")
ap.add_argument("--prefix", action="append")
ap.add_argument("--wear-column", default="wear_volume_m3")
ap.add_argument("--counter-column", default="counterface_volume_m3")
ap.add_argument("--ratio", type=float)
ap.add_argument("--mu-column", default="mu_eff")
ap.add_argument("--min-drop", type=float, default=0.0)
ap.add_argument("--vtk", nargs="+", action="append", default=[])
a = ap.parse_args()
rows = list(csv.DictReader(open(a.csv)))
a.prefix = a.prefix or [""]
if len(rows) < 10:
    fail("too few rows")
for prefix in a.prefix:
    for name in ("mu_eff", "h_max_m", a.counter_column, a.wear_column):
        if prefix + name not in rows[0]:
            fail("column %s missing" % (prefix + name))
    for k in range(1, len(rows)):
        if float(rows[k][prefix + "h_max_m"]) < float(rows[k - 1][prefix + "h_max_m"]) * (1 - 1e-12):
            fail("%sh_max_m decreases at row %d" % (prefix, k))
    if a.ratio is not None:
        body, counter = float(rows[-1][prefix + a.wear_column]), float(rows[-1][prefix + a.counter_column])
        if not body > 0 or abs(counter / body - a.ratio) > 1e-6 * a.ratio:
            fail("%s: counter/body worn volume %s, expected %g" % (prefix, counter / body if body > 0 else "n/a", a.ratio))
mu0, mu1 = float(rows[0][a.mu_column]), float(rows[-1][a.mu_column])
print("%s: %.5g -> %.5g" % (a.mu_column, mu0, mu1))
if mu0 - mu1 < a.min_drop * mu0:
    fail("%s falls by less than %g: %g -> %g" % (a.mu_column, a.min_drop, mu0, mu1))
for spec in a.vtk:
    text = open(spec[0], errors="replace").read()
    for name in spec[1:]:
        if 'Name="%s"' % name not in text:
            fail("%s: field %s missing" % (spec[0], name))
print("check_state_law_element: ok")
