#!/usr/bin/env python3
"""The thesis's mu0 sweep from physical interface states (doc/validation.md, "The mu0 sweep from interface states").

Runs the three shipped cases inputs/pin_on_disk_mu0_{oxidised,dry_low,boundary}.toml (one pin-on-disk on the dry
steel law, the interface state a [film] that is neither removed nor regrown) and asserts, on their CSVs:
- the oxidised run (the law's own state) is the film-free steel case tests/data/state_law/steel/
  pin_on_disk_state_law.toml, friction force identical at every sample;
- mu0 (mu at t = 0) of each run is the oxidised run's times Tabor's T(f) / T(f_base) (1e-9), and the oxidised run's
  is Tabor's at the calibrated m = 0.8921 (Marks' 0.57) within 1 % (the tilt of the cell's contact normals);
- claim 2, peak: each higher-state run's peak friction force >= 1.2 x the next lower's (the thesis's margin);
- claim 2, time to equilibrium: does NOT hold: t_eq (tests/cli/thesis_claims.py) is the same for the three runs
  (one output interval) and is the speed ramp's settling (<= ramp + 2 intervals): the state scales the friction
  and leaves the run-in as the law's;
- claim 3: does NOT hold: start / steady is the same for the three runs (1e-6, the scaling is uniform) and below
  the thesis's 1.2; it is the law's own run-in (peak / steady of mu_body at the pin's pressure);
- the clean state (m = 1) is refused, exit 2 (junction growth without bound);
- the boundary case on the law built at the boundary state with boundary wear (--law
  inputs/state_law_steel_boundary.json, k = 1e-6): its mu0 within 20 % of the rescaled boundary run's (printed).

  check_mu0_states.py --runin RUNIN --workdir DIR
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
from runin_common import SOURCE_DIR, fail, fresh_dir, run_or_fail  # noqa: E402
from thesis_claims import check_claims, curve_stats  # noqa: E402

ALPHA, F_BASE = 12.0, 0.8921
# name, f of the state, the thesis's mu0 it stands beside
STATES = [("oxidised", 0.8921, 0.95), ("dry_low", 0.7, 0.55), ("boundary", 0.1, 0.15)]
RAMP, INTERVAL = 0.05, 0.002
PEAK_MARGIN, START_MARGIN = 0.2, 0.2
PLAIN = os.path.join(SOURCE_DIR, "tests", "data", "state_law", "steel", "pin_on_disk_state_law.toml")
BOUNDARY_LAW = os.path.join(SOURCE_DIR, "inputs", "state_law_steel_boundary.json")


def tabor(f):
    return f / math.sqrt(ALPHA * (1.0 - f * f))


def case(name):
    return os.path.join(SOURCE_DIR, "inputs", f"pin_on_disk_mu0_{name}.toml")


def run(runin, name, out, extra=()):
    run_or_fail([runin, "pin-on-disk", case(name), "--output-dir", out, "--no-plot", *extra], cwd=SOURCE_DIR)
    with open(os.path.join(out, "pin_on_disk.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    curve = ([r["t_s"] for r in rows], [r["friction_force_N"] for r in rows], [r["speed_m_s"] for r in rows])
    return rows, curve


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runin", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    work = args.workdir
    fresh_dir(work)

    runs = {}
    for name, f, thesis in STATES:
        rows, curve = run(args.runin, name, os.path.join(work, name))
        runs[name] = (f, thesis, rows, curve, curve_stats(*curve))
    mu0_ox = runs["oxidised"][2][0]["mu"]
    for name, (f, thesis, rows, curve, s) in runs.items():
        mu0 = rows[0]["mu"]
        expect = mu0_ox * tabor(f) / tabor(F_BASE)
        print(f"state {name}: m {f:g}, mu0 {mu0:.6g} (Tabor {tabor(f):.6g}; thesis {thesis:g}), mu end "
              f"{rows[-1]['mu']:.6g}, peak {s['peak']:.6g} N, start / steady {s['start'] / s['steady']:.6g}, "
              f"t_eq {s['t_eq']} s")
        if not abs(mu0 - expect) <= 1e-9 * expect:
            fail(f"{name}: mu0 {mu0!r} is not the oxidised run's x T({f}) / T({F_BASE}) = {expect!r} (1e-9)")
    # the film at the law's own state is the law: the film-free steel case, sample for sample
    plain = os.path.join(work, "film_free")
    run_or_fail([args.runin, "pin-on-disk", PLAIN, "--output-dir", plain, "--no-plot"], cwd=SOURCE_DIR)
    with open(os.path.join(plain, "pin_on_disk.csv")) as f:
        plain_force = [float(r["friction_force_N"]) for r in csv.DictReader(f)]
    if plain_force != runs["oxidised"][3][1]:
        fail("oxidised: the friction force differs from the film-free case's " + PLAIN)
    if not abs(mu0_ox / tabor(F_BASE) - 1.0) <= 0.01:
        fail(f"oxidised: mu0 {mu0_ox} not within 1 % of Tabor's {tabor(F_BASE)} at the calibrated m")

    curves = {runs[name][1]: runs[name][3] for name, _, _ in STATES}
    problems = check_claims(curves, PEAK_MARGIN, 0.1, START_MARGIN)
    print("thesis_claims.py --claims 0.2 0.1 0.2 reports:" + "".join("\n  " + p for p in problems))
    stats = [runs[name][4] for name, _, _ in STATES]
    for (hi_name, _, _), (lo_name, _, _), hi, lo in zip(STATES, STATES[1:], stats, stats[1:]):
        print(f"claim 2, peak: {hi_name} / {lo_name} = {hi['peak'] / lo['peak']:.6g}")
        if not hi["peak"] >= (1 + PEAK_MARGIN) * lo["peak"]:
            fail(f"claim 2: peak {hi['peak']} ({hi_name}) not >= {1 + PEAK_MARGIN} x {lo['peak']} ({lo_name})")
    t_eq = [s["t_eq"] for s in stats]
    if None in t_eq or max(t_eq) - min(t_eq) > INTERVAL * (1 + 1e-9) or max(t_eq) > RAMP + 2 * INTERVAL:
        fail(f"claim 2, time: expected the same t_eq for the three states at the ramp's settling, got {t_eq}")
    ratios = [s["start"] / s["steady"] for s in stats]
    if max(ratios) - min(ratios) > 1e-6 * ratios[0] or not ratios[0] < 1 + START_MARGIN:
        fail(f"claim 3: expected one start / steady below {1 + START_MARGIN} for the three states, got {ratios}")
    print(f"claim 2, time: not shown: t_eq {t_eq[0]:g} s for all three (the {RAMP:g} s speed ramp's settling)")
    print(f"claim 3: not shown: start / steady {ratios[0]:.6g} for all three (< {1 + START_MARGIN:g})")

    # the clean state: Tabor's junction grows without bound at m = 1
    clean = os.path.join(work, "clean.toml")
    with open(case("oxidised")) as f:
        text = f.read()
    with open(clean, "w") as f:
        f.write(text.replace('interface = "oxidised"', 'interface = "clean"'))
    done = subprocess.run([args.runin, "pin-on-disk", clean, "--output-dir", os.path.join(work, "clean"),
                           "--no-plot"], cwd=SOURCE_DIR, capture_output=True, text=True)
    err = done.stderr.strip().splitlines()
    if done.returncode != 2 or len(err) != 1 or "key 'film.interface'" not in err[0] or "m = 1 " not in err[0]:
        fail(f"clean: expected one error line on film.interface and exit 2, got {done.returncode}: {done.stderr!r}")
    print(f"state clean: m 1, refused: {err[0]}")

    # the boundary state as built (junctions at m = 0.1 with boundary wear, k = 1e-6) against the rescale
    rows, _ = run(args.runin, "boundary", os.path.join(work, "boundary_law"), ("--law", BOUNDARY_LAW))
    built, scaled = rows[0]["mu"], runs["boundary"][2][0]["mu"]
    wear_ratio = rows[-1]["wear_volume_m3"] / runs["boundary"][2][-1]["wear_volume_m3"]
    print(f"boundary law as built: mu0 {built:.6g}, mu end {rows[-1]['mu']:.6g}; rescaled / built {scaled / built:.6g}; "
          f"pin wear built / rescaled {wear_ratio:.6g}")
    if not abs(scaled / built - 1.0) <= 0.2:
        fail(f"boundary: the rescaled mu0 {scaled} is not within 20 % of the built law's {built}")
    print("ok: mu0 sweep from interface states")


if __name__ == "__main__":
    main()
