#!/usr/bin/env python3
"""A surface film in an element (doc/surface_films.md, "In an element"): the tribometer pin on the pipeline's dry
steel law with [film], two of Blau's run-in shapes by the film's inputs alone.

- rise (the shipped inputs/pin_on_disk_film.toml): covered start (coverage 1) by a film at the boundary state
  (m = 0.1), worn off (s_r = 0.05 m), not regrown. Checked: F/W at s = 0 is the law's mu(p, 0) times Tabor's
  T(f_film) / T(f_base); F/W never falls and ends steady (last 10 % of sliding within 2 %) at the bare law's level
  (within 1 %), at least 10 x the start; past the law's last worn depth (phi constant) ln theta falls with s at
  -phi / s_r, phi = the law's contact_fraction there (1e-6); Archard's invariant for the pin within 2 %.
- peak (the same case with two films, as in the cell's peak): the pin's wiped off within mm (s_r 2 mm, not regrown),
  the disk's growing from a bare start (counterface_coverage 0, s_r 0.05 m, k_g 0.05 /s; a track point is under the
  pin a / (4 r) of the time). Checked: the end contact coverage is half the disk's steady state
  k_g / (k_g + duty phi v / s_r) (1e-3, the pin's is 0); the peak of F/W at least 1.5 x the start and the end;
  the end steady (last 10 % within 2 %).
- fall (the same case, coverage 0, growth_rate 0.5 /s): bare start, a film that grows faster than sliding removes it.
  Checked: F/W at s = 0 is the bare law's; the coverage only rises, F/W within [end, start] (2 %); the end coverage is the steady state
  k_g / (k_g + phi v / s_r) (1e-3) and F/W there is the law's times T(f(theta*)) / T(f_base) (1e-3); end/start <= 0.7.

- journal bearing (inputs/journal_bearing_state_law.toml, 4 s, with the rise film on the bore, s_r = 20 um): the
  first mu_eff is the film-free run's times T(f_film) / T(f_base) (1e-9: the same node pressures at t = 0), the
  coverage of both halves only falls, to below 1e-3, and the end mu_eff is the film-free run's within 1 %.

- piston ring (tests/data/state_law/steel/piston_ring_state_law.toml: the two-ring pack on the steel law, with the
  rise film on the ring faces, s_r = 0.2 mm): each ring's first mu_eff is the film-free run's times
  T(f_film) / T(f_base) (1e-9), its face coverage falls below 0.05 and its mu_eff rises at least 10 x.

  check_film_element.py --runin RUNIN --workdir DIR
"""
import argparse
import csv
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from runin_common import SOURCE_DIR, fail, fresh_dir, run_or_fail  # noqa: E402
from state_law import StateLaw  # noqa: E402

CASE = os.path.join(SOURCE_DIR, "inputs", "pin_on_disk_film.toml")
JB_CASE = os.path.join(SOURCE_DIR, "inputs", "journal_bearing_state_law.toml")


def rise_film(removal_distance):
    """The rise inputs as a [film] table appended to an element's case."""
    return ("\n[film]\ncoverage = 1.0\ninterface = \"boundary\"\n"
            f"removal_distance = {removal_distance!r}\ngrowth_rate = 0.0\n")
LAW = os.path.join(SOURCE_DIR, "inputs", "state_law_steel_mild.json")
P = 20.0 / (math.pi * 1.5e-3 ** 2)
SPEED, S_R, F_FILM, F_BASE, ALPHA = 0.5, 0.05, 0.1, 0.8921, 12.0
GROWTH = 0.5
PEAK_S_R, DISK_S_R, DISK_GROWTH, DUTY = 0.002, 0.05, 0.05, 1.5e-3 / (4 * 0.02)


def tabor(f):
    return f / math.sqrt(ALPHA * (1.0 - f * f))


def factor(theta):
    return tabor(theta * F_FILM + (1.0 - theta) * F_BASE) / tabor(F_BASE)


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def run(runin, case, out):
    text = run_or_fail([runin, "pin-on-disk", case, "--output-dir", out, "--no-plot"], cwd=SOURCE_DIR).stdout
    return text, rows(os.path.join(out, "pin_on_disk.csv"))


def shape(r, sign, name):
    """The coverage moves one way only (first-order kinetics); F/W (which also follows the law's own small change
    with h) stays between its start and its end within 2 %: no peak, no dip."""
    theta = [x["film_coverage"] for x in r]
    for a, b in zip(theta, theta[1:]):
        if -sign * (b - a) < -1e-12:
            fail(f"{name}: the film coverage is not monotone ({a:.9g} -> {b:.9g})")
    mu = [x["mu"] for x in r]
    lo, hi = min(mu[0], mu[-1]), max(mu[0], mu[-1])
    if min(mu) < 0.98 * lo or max(mu) > 1.02 * hi:
        fail(f"{name}: F/W leaves [start, end] by more than 2 % ({min(mu):.6g} .. {max(mu):.6g}, "
             f"start {mu[0]:.6g}, end {mu[-1]:.6g})")


def close(a, b, rel, what):
    if abs(a - b) > rel * abs(b):
        fail(f"{what}: {a:.9g} against {b:.9g} (relative {abs(a - b) / abs(b):.3g} > {rel:g})")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runin", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    fresh_dir(a.workdir)
    law = StateLaw(LAW)
    depth = law.h[-1]
    mu0 = law.value("mu_body", P, 0.0)

    text, r = run(a.runin, CASE, os.path.join(a.workdir, "rise"))
    mu = [x["mu"] for x in r]
    close(mu[0], mu0 * factor(1.0), 1e-9, "rise: F/W at s = 0 against the law's mu x T(f_film) / T(f_base)")
    shape(r, +1, "rise")
    s = [x["sliding_distance_m"] for x in r]
    tail = [m for m, d in zip(mu, s) if d >= 0.9 * s[-1]]
    if max(tail) - min(tail) > 0.02 * tail[-1]:
        fail(f"rise: not steady over the last 10 % of sliding ({min(tail):.6g} .. {max(tail):.6g})")
    close(mu[-1], law.value("mu_body", P, r[-1]["h_mean_m"]), 0.01, "rise: end F/W against the bare law")
    if mu[-1] < 10.0 * mu[0]:
        fail(f"rise: end/start {mu[-1] / mu[0]:.3g} < 10")
    phi = law.value("contact_fraction", P, depth)
    deep = [x for x in r if x["h_mean_m"] > depth and 1e-250 < x["film_coverage"] < 0.5]
    if len(deep) < 3:
        fail("rise: fewer than 3 rows past the law's last worn depth with a coverage left")
    slope = (math.log(deep[-1]["film_coverage"]) - math.log(deep[0]["film_coverage"])) / (
        deep[-1]["sliding_distance_m"] - deep[0]["sliding_distance_m"])
    close(slope, -phi / S_R, 1e-6, "rise: d ln(theta) / ds past the law's depth against -phi / s_r")
    m = re.search(r"Archard\s+worn volume / \(K W s\): pin ([0-9.]+)", text)
    if not m or abs(float(m.group(1)) - 1.0) > 0.02:
        fail("rise: Archard's invariant for the pin not within 2 % (" + (m.group(1) if m else "no line") + ")")
    settle = re.search(r"run-in\s+mu = F/W within 2 % of its steady value \S+ \(mean over the last 10 % of sliding\) "
                       r"from s = (\S+) m", text)
    if not settle:
        fail("rise: no run-in line in the summary")
    print(f"ok: rise: run-in s = {settle.group(1)} m")
    print(f"ok: rise: F/W {mu[0]:.6g} -> {mu[-1]:.6g} ({mu[-1] / mu[0]:.3g} x), d ln(theta)/ds {slope:.6g} "
          f"= -phi/s_r {-phi / S_R:.6g} (phi {phi:.6g}), Archard pin {m.group(1)}")

    with open(CASE) as f:
        case = f.read()
    fall_case = os.path.join(a.workdir, "fall.toml")
    case = case.replace("coverage = 1.0 ", "coverage = 0.0 ").replace("growth_rate = 0.0 ", f"growth_rate = {GROWTH} ")
    case = case.replace('law = "inputs/', f'law = "{SOURCE_DIR}/inputs/')
    with open(fall_case, "w") as f:
        f.write(case)
    _, r = run(a.runin, fall_case, os.path.join(a.workdir, "fall"))
    mu = [x["mu"] for x in r]
    close(mu[0], mu0, 1e-9, "fall: F/W at s = 0 against the bare law")
    shape(r, -1, "fall")
    steady = GROWTH / (GROWTH + phi * SPEED / S_R)
    if abs(r[-1]["film_coverage"] - steady) > 1e-3:
        fail(f"fall: end coverage {r[-1]['film_coverage']:.6g} against the steady state {steady:.6g}")
    close(mu[-1], law.value("mu_body", P, r[-1]["h_mean_m"]) * factor(steady), 1e-3,
          "fall: end F/W against the law at the steady coverage")
    if mu[-1] > 0.7 * mu[0]:
        fail(f"fall: end/start {mu[-1] / mu[0]:.3g} > 0.7")
    print(f"ok: fall: F/W {mu[0]:.6g} -> {mu[-1]:.6g} ({mu[-1] / mu[0]:.3g} x), end coverage "
          f"{r[-1]['film_coverage']:.6g} (steady state {steady:.6g})")
    peak_case = os.path.join(a.workdir, "peak.toml")
    with open(CASE) as f:
        case = f.read()
    case = case.replace("removal_distance = 0.05 ", f"removal_distance = {PEAK_S_R} ")
    case = case.replace("growth_rate = 0.0 ", f"counterface_coverage = 0.0\ncounterface_removal_distance = {DISK_S_R}\n"
                        f"counterface_growth_rate = {DISK_GROWTH}\ngrowth_rate = 0.0 ")
    case = case.replace('law = "inputs/', f'law = "{SOURCE_DIR}/inputs/')
    with open(peak_case, "w") as f:
        f.write(case)
    _, r = run(a.runin, peak_case, os.path.join(a.workdir, "peak"))
    mu = [x["mu"] for x in r]
    disk = DISK_GROWTH / (DISK_GROWTH + DUTY * phi * SPEED / DISK_S_R)
    if abs(r[-1]["film_coverage"] - 0.5 * disk) > 1e-3:
        fail(f"peak: end contact coverage {r[-1]['film_coverage']:.6g} against half the disk's steady state "
             f"{0.5 * disk:.6g}")
    top = max(mu)
    at = r[mu.index(top)]["sliding_distance_m"]
    s = [x["sliding_distance_m"] for x in r]
    tail = [m for m, d in zip(mu, s) if d >= 0.9 * s[-1]]
    if not (top >= 1.5 * mu[0] and top >= 1.5 * mu[-1]) or max(tail) - min(tail) > 0.02 * tail[-1]:
        fail(f"peak: F/W {mu[0]:.4g}, peak {top:.4g} at s = {at:.3g} m, end {mu[-1]:.4g} (last 10 % "
             f"{min(tail):.4g} .. {max(tail):.4g}): not a peak then a steady fall")
    print(f"ok: peak: F/W {mu[0]:.6g}, peak {top:.6g} at s = {at:.4g} m, end {mu[-1]:.6g} (peak / end "
          f"{top / mu[-1]:.3g} x); end contact coverage {r[-1]['film_coverage']:.6g} (half the disk's steady state "
          f"{disk:.6g}, under the pin {DUTY:.6g} of the time)")

    journal_bearing(a)
    piston_ring(a)


def piston_ring(a):
    case = os.path.join(SOURCE_DIR, "tests", "data", "state_law", "steel", "piston_ring_state_law.toml")

    def ring(case_file, out):
        run_or_fail([a.runin, "piston-ring", case_file, "--output-dir", out, "--no-plot"], cwd=SOURCE_DIR)
        return {k: rows(os.path.join(out, f"piston_ring_{k}.csv")) for k in ("A", "B")}
    bare = ring(case, os.path.join(a.workdir, "pr_bare"))
    with open(case) as f:
        text = f.read().replace('"inputs/', f'"{SOURCE_DIR}/inputs/').replace('"potentials/', f'"{SOURCE_DIR}/potentials/')
    film_case = os.path.join(a.workdir, "pr_film.toml")
    with open(film_case, "w") as f:
        f.write(text + rise_film(2e-4))
    film = ring(film_case, os.path.join(a.workdir, "pr_film"))
    for k in ("A", "B"):
        r, b = film[k], bare[k]
        close(r[0]["mu_eff"], b[0]["mu_eff"] * factor(1.0), 1e-9, f"piston ring {k}: first mu_eff against the bare "
              "run's x T(f_film) / T(f_base)")
        theta = [x["film_coverage"] for x in r]
        # load-weighted over cells whose load moves with the crank: each cell's coverage falls, their mean need not
        if theta[-1] > 0.05:
            fail(f"piston ring {k}: the face coverage {theta[0]:.4g} -> {theta[-1]:.4g} does not fall below 0.05")
        if r[-1]["mu_eff"] < 10.0 * r[0]["mu_eff"]:
            fail(f"piston ring {k}: mu_eff {r[0]['mu_eff']:.4g} -> {r[-1]['mu_eff']:.4g} rises less than 10 x")
        print(f"ok: piston ring {k}: mu_eff {r[0]['mu_eff']:.6g} -> {r[-1]['mu_eff']:.6g} (bare {b[0]['mu_eff']:.6g} "
              f"-> {b[-1]['mu_eff']:.6g}); face coverage {theta[-1]:.4g} at the end")


def journal_bearing(a):
    def jb(case, out):
        run_or_fail([a.runin, "journal-bearing", case, "--output-dir", out, "--no-plot"], cwd=SOURCE_DIR)
        return rows(os.path.join(out, "journal_bearing.csv"))
    bare = jb(JB_CASE, os.path.join(a.workdir, "jb_bare"))
    with open(JB_CASE) as f:
        case = f.read().replace('law = "inputs/', f'law = "{SOURCE_DIR}/inputs/') + rise_film(2e-5)
    film_case = os.path.join(a.workdir, "jb_film.toml")
    with open(film_case, "w") as f:
        f.write(case)
    r = jb(film_case, os.path.join(a.workdir, "jb_film"))
    close(r[0]["mu_eff"], bare[0]["mu_eff"] * factor(1.0), 1e-9, "journal bearing: first mu_eff against the bare run's x "
          "T(f_film) / T(f_base)")
    for half in ("lower", "upper"):
        theta = [x[f"{half}_film_coverage"] for x in r]
        if any(b > a_ + 1e-12 for a_, b in zip(theta, theta[1:])) or theta[-1] > 1e-3:
            fail(f"journal bearing: the {half} half's coverage {theta[0]:.4g} -> {theta[-1]:.4g} does not fall below 1e-3")
    close(r[-1]["mu_eff"], bare[-1]["mu_eff"], 0.01, "journal bearing: end mu_eff against the bare run")
    print(f"ok: journal bearing: mu_eff {r[0]['mu_eff']:.6g} -> {r[-1]['mu_eff']:.6g} (bare {bare[0]['mu_eff']:.6g} -> "
          f"{bare[-1]['mu_eff']:.6g}); coverage lower {r[-1]['lower_film_coverage']:.3g}, upper "
          f"{r[-1]['upper_film_coverage']:.3g} at the end")


if __name__ == "__main__":
    main()
