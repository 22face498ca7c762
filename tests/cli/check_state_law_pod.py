#!/usr/bin/env python3
"""Checks a pin-on-disk run on a state law (doc/state_law_continuum.md).

--flat P: flat punch at the uniform nominal pressure P: mu_eff(s) and h(s) reproduce the law integrated directly
          along s (dh/ds = wear_rate(P, h), RK4 on the law's own interpolation: linear in h, power law in p) within 1 %.
--cell-curve (with --flat P on a grid pressure of the law): mu_eff at the cell's own sliding distances (the law's
          sliding_distance column at P) equals the cell's mu_body there within 1 %: the cell's mu(s) reproduced.
Always:   the friction force of each slip row is the mu_eff held over the interval before it (operator splitting,
          F = sum_i mu_i p_i A_i = mu_eff W; plus alpha V W with --alpha); h and the worn volumes never decrease; the disk's worn volume is
          the law's counterface/body ratio (--counterface-ratio) of the pin's.
--vtk N:  N pin_face_*.vts frames carrying the h_m and mu fields.
"""
import argparse
import bisect
import csv
import glob
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from state_law import StateLaw  # noqa: E402  (the C++ reader's interpolation rule)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
    ap.add_argument("--law", required=True)
    ap.add_argument("--flat", type=float)
    ap.add_argument("--counterface-ratio", type=float)
    ap.add_argument("--vtk", type=int)
    ap.add_argument("--cell-curve", action="store_true")
    ap.add_argument("--no-expect-fall", dest="expect_fall", action="store_false",
                    help="do not require mu_eff to fall (laws from the cell)")
    ap.add_argument("--min-distance", type=float, default=0.0)
    ap.add_argument("--min-mu-change", type=float, default=0.1,
                    help="relative change of mu_eff that shows the run exercises the law (the dry junction law "
                         "barely moves: 0.5 %%)")
    ap.add_argument("--alpha", type=float, default=0.0, help="the case's speed term: F/W = mu_eff + alpha V")
    a = ap.parse_args()
    rows = list(csv.DictReader(open(os.path.join(a.out_dir, "pin_on_disk.csv"))))
    if len(rows) < 10:
        fail("too few rows")
    for key in ("mu_eff", "h_mean_m", "h_max_m"):
        if key not in rows[0]:
            fail("column %s missing" % key)
    law = StateLaw(a.law)
    s = [float(r["sliding_distance_m"]) for r in rows]
    if s[-1] < a.min_distance:
        fail("slid %g m < %g m" % (s[-1], a.min_distance))
    for k in range(1, len(rows)):
        for key in ("h_max_m", "wear_volume_m3", "disk_wear_volume_m3"):  # h_mean: new edge rings join at h = 0
            if float(rows[k][key]) < float(rows[k - 1][key]) * (1 - 1e-12):
                fail("%s decreases at row %d" % (key, k))
        if rows[k]["state_slip"] == "1" and rows[k - 1]["state_slip"] == "1":
            held = float(rows[k - 1]["mu_eff"])
            mu = float(rows[k]["mu"]) - a.alpha * float(rows[k]["speed_m_s"])
            if abs(mu - held) > 1e-9 * max(abs(held), 1e-12):
                fail("row %d: F/W = %.12g but the held mu_eff is %.12g" % (k, mu, held))
    if a.counterface_ratio is not None:
        pin, disk = float(rows[-1]["wear_volume_m3"]), float(rows[-1]["disk_wear_volume_m3"])
        if pin <= 0 or abs(disk / pin - a.counterface_ratio) > 1e-6 * a.counterface_ratio:
            fail("disk/pin worn volume %g, expected %g" % (disk / pin if pin > 0 else float("nan"), a.counterface_ratio))
    if a.flat:
        p = a.flat
        # Reference: RK4 on dh/ds = w(p, h) from 0 to each row's s, 1e-4 of the run per step at most.
        h, s_ref = 0.0, 0.0
        worst_mu = worst_h = 0.0
        step = s[-1] / 20000
        for k, target in enumerate(s):
            while s_ref < target:
                ds = min(step, target - s_ref)
                k1 = law.value("wear_rate", p, h)
                k2 = law.value("wear_rate", p, h + 0.5 * ds * k1)
                k3 = law.value("wear_rate", p, h + 0.5 * ds * k2)
                k4 = law.value("wear_rate", p, h + ds * k3)
                h += ds / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
                s_ref += ds
            mu_ref = law.value("mu_body", p, h)
            mu = float(rows[k]["mu_eff"])
            worst_mu = max(worst_mu, abs(mu - mu_ref) / mu_ref)
            if h > 0:
                worst_h = max(worst_h, abs(float(rows[k]["h_mean_m"]) - h) / h)
            pm = float(rows[k]["mean_pressure_Pa"])
            if abs(pm - p) > 1e-9 * p:
                fail("row %d: mean pressure %g, expected the uniform %g" % (k, pm, p))
        mu0, mu1 = float(rows[0]["mu_eff"]), float(rows[-1]["mu_eff"])
        print("flat punch p = %g Pa: mu_eff %.5g -> %.5g over %.4g m, h %.4g m; worst relative error mu %.3g, h %.3g"
              % (p, mu0, mu1, s[-1], h, worst_mu, worst_h))
        # the synthetic law runs in (mu falls); a law from the cell need not (doc/rve_cell.md): only that mu moved
        if a.expect_fall and mu0 - mu1 < 0.1 * mu0:
            fail("no run-in: mu_eff %g -> %g" % (mu0, mu1))
        if abs(mu1 - mu0) < a.min_mu_change * mu0:
            fail("mu_eff did not evolve: %g -> %g (the run is too short to test the state law)" % (mu0, mu1))
        if worst_mu > 0.01 or worst_h > 0.01:
            fail("flat punch departs from the law by more than 1 %")
        if a.cell_curve:
            i = law.grid_index(p)
            if i is None:
                fail("--cell-curve needs P on the law's pressure grid")
            mu_col = [float(r["mu_eff"]) for r in rows]
            worst, compared = 0.0, 0
            for s_cell, mu_cell in zip(law.grid("sliding_distance")[i], law.grid("mu_body")[i]):
                if s_cell <= 0 or s_cell > s[-1]:
                    continue
                k = bisect.bisect_left(s, s_cell)
                f = (s_cell - s[k - 1]) / (s[k] - s[k - 1])
                mu = mu_col[k - 1] + f * (mu_col[k] - mu_col[k - 1])
                worst = max(worst, abs(mu - mu_cell) / mu_cell)
                compared += 1
            print("cell curve at p = %g Pa: %d points of the law's (sliding_distance, mu_body), worst relative error %.3g"
                  % (law.p[i], compared, worst))
            if compared < 5 or worst > 0.01:
                fail("the cell's mu(s) is not reproduced within 1 %")
    if a.vtk is not None:
        frames = sorted(glob.glob(os.path.join(a.out_dir, "pin_face_*.vts")))
        if len(frames) != a.vtk:
            fail("%d VTK frames, expected %d" % (len(frames), a.vtk))
        for f in frames:
            text = open(f, errors="replace").read()
            for name in ("h_m", "mu", "pressure_Pa"):
                if 'Name="%s"' % name not in text:
                    fail("%s: field %s missing" % (f, name))
    print("check_state_law_pod: ok")


if __name__ == "__main__":
    main()
