#!/usr/bin/env python3
"""Checks of the contact-model features of the RunIn LAMMPS styles (run by ctest; standard library only).

  contact_model_checks.py slider-mu-body --lmp LMP --workdir DIR [--mpiexec MPIEXEC --np N]
  contact_model_checks.py wall-mu-body --lmp LMP --workdir DIR [--mpiexec MPIEXEC --np N]
  contact_model_checks.py single --lmp LMP --workdir DIR [--mu-s MU --mu-k MU]
  contact_model_checks.py mixing --lmp LMP --workdir DIR
  contact_model_checks.py restart-error --lmp LMP --workdir DIR --write DECK --read DECK --pattern REGEX
                          --control NAME=VALUE

slider-mu-body: inputs/in.rough_slider (short run). At every thermo row of the sliding run,
  compute runin/friction's mu_body (entry 16, the global-frame reaction on 'body slider' along
  'slide x' over its load) equals the drive's and the press's view of the same body,
  |f_drive[1]| / |f_press[3]| (fix setforce / fix aveforce report the summed force before they
  change it), to 1e-10; entries 14 and 15 equal |f_drive[1]| and |f_press[3]|; the friction opposes
  the sliding (f_drive[1] < 0) once the slide has started. mu_eff (entry 3, each contact in its own
  frame) is printed next to mu_body, not asserted.
flat wall: inputs/in.runin_wall (short run) with 'body wall': on a flat counterface every contact
  normal is z, so mu_body (16) equals mu_eff (3) and the load (15) equals |f_wall[3]|, to 1e-10.
single: pair runin/asperity single() through compute pair/local on one tilted, damped, sheared pair
  (tests/lammps/decks/in.contact_single): the normal part (fx fy fz) plus the tangential part
  (p1 p2 p3) is the per-atom force on atom i to 1e-12 of |F|, at every step (stick, break-away,
  slip weakening, kinetic sliding, stop, reversal; both sticking and sliding steps required);
  p4 = a = sqrt(R* delta) and p5 = delta from the positions; |normal| and |tangential| equal
  compute runin/friction's entries 1 and 2.
mixing: tests/lammps/decks/in.contact_mixing: pair_coeff 1 1 (Al) and 2 2 (Cu) from the materials of
  potentials/CuAl.runin, 1 2 unset: the 1-2 Hertz force equals 4/3 E*_12 sqrt(R*) delta^3/2 with
  1/E*_12 = (1-nu1^2)/E1 + (1-nu2^2)/E2 to 1e-12, and the first sticking tangential step equals
  8 G*_12 a v dt with 1/G*_12 = (2-nu1)/G1 + (2-nu2)/G2 to 1e-12.
restart-error: a restart written by the --write deck and read by the --read deck whose sub-models differ
  must stop with exactly one ERROR line matching REGEX, without a crash; the same --read deck with
  -var NAME VALUE (--control: the restart's own models) must run. Two lmp_runin runs in one directory,
  since 'clear' inside one deck drops the RunIn styles of lmp_runin.
"""
import argparse
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, mpi_env, run_lammps, single_error, thermo_blocks  # noqa: E402

DECKS = os.path.join(SOURCE_DIR, "tests", "lammps", "decks")
COEFFS = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")


def relative(got, want, scale=None):
    scale = abs(want) if scale is None else abs(scale)
    return abs(got - want) / scale if scale > 0.0 else abs(got - want)


def check(name, got, want, tolerance, scale=None):
    error = relative(got, want, scale)
    if not error <= tolerance:
        fail(f"{name}: got {got!r}, want {want!r} (relative error {error:.3e} > {tolerance:g})")
    return error


def finite_rows(rows):
    for row in rows:
        for name, value in row.items():
            if not math.isfinite(value):
                fail(f"non-finite {name} at step {row['Step']:.0f}")


# --- 1. mu_body of the rough slider --------------------------------------------------------------
def slider_mu_body(args):
    fresh_dir(args.workdir)
    log = run_lammps(args, os.path.join(SOURCE_DIR, "inputs", "in.rough_slider"),
                     {"coeffs": COEFFS, "nsettle": 1000, "nslide": 2000, "thermo_every": 250}, np=args.np)
    blocks = thermo_blocks(log)
    if len(blocks) != 2:
        fail(f"expected the settle and slide thermo tables, found {len(blocks)}")
    sliding = blocks[1]
    finite_rows(sliding)
    if len(sliding) < 5:
        fail(f"only {len(sliding)} sliding rows")
    worst = 0.0
    print(f"{'step':>6} {'mu_eff [3]':>12} {'mu_body [16]':>13} {'-f_drive/f_press':>17} {'[16]-[3]':>10} "
          f"{'load [15]':>11} {'contacts':>8}")
    for index, row in enumerate(sliding):
        step = int(row["Step"])
        drive, press = row["f_drive[1]"], row["f_press[3]"]
        if not press > 0.0:
            fail(f"step {step}: no load on the slider (f_press[3] = {press!r})")
        if index > 0 and not drive < 0.0:
            fail(f"step {step}: the friction on the slider does not oppose the sliding (f_drive[1] = {drive!r})")
        want = abs(drive) / abs(press)
        worst = max(worst, check(f"step {step}: mu_body c_fric[16] vs |f_drive[1]| / |f_press[3]|",
                                 row["c_fric[16]"], want, 1e-10),
                    check(f"step {step}: friction on the body c_fric[14] vs |f_drive[1]|", row["c_fric[14]"],
                          abs(drive), 1e-10),
                    check(f"step {step}: load on the body c_fric[15] vs |f_press[3]|", row["c_fric[15]"],
                          abs(press), 1e-10))
        print(f"{step:>6} {row['c_fric[3]']:>12.6f} {row['c_fric[16]']:>13.6f} {-drive / press:>17.6f} "
              f"{row['c_fric[16]'] - row['c_fric[3]']:>+10.5f} {row['c_fric[15]']:>11.4e} {row['c_fric[4]']:>8.0f}")
    if not max(row["c_fric[16]"] for row in sliding) > 0.1:
        fail("mu_body never exceeds 0.1 while sliding: the slider is not sliding against friction")
    gap = [row["c_fric[16]"] - row["c_fric[3]"] for row in sliding[1:]]
    print(f"ok: {len(sliding)} sliding rows on {args.np} rank(s): mu_body = |f_drive[1]| / |f_press[3]| to "
          f"{worst:.2e}; mu_body - mu_eff from {min(gap):+.4f} to {max(gap):+.4f} after the first row (mu_eff = "
          f"|sum F_t| / sum F_n with each contact's F_t and F_n in its own, tilted frame; mu_body = x over z of the "
          f"global reaction on the slider, where tilted normal forces add to x and tangential forces to z)")


# --- 2. mu_body on a flat wall ------------------------------------------------------------------
def wall_mu_body(args):
    fresh_dir(args.workdir)
    # inputs/in.runin_wall with entries 14 and 15 after its last thermo column and every digit printed
    text = open(os.path.join(SOURCE_DIR, "inputs", "in.runin_wall")).read()
    edits = [("body wall\n", "body wall\n"),
             ("c_rough[4] c_fric[16]\n", "c_rough[4] c_fric[16] c_fric[14] c_fric[15]\n"),
             ("thermo_modify   format float %.10g", "thermo_modify   format float %.17g")]
    for old, new in edits:
        if text.count(old) != 1:
            fail(f"inputs/in.runin_wall: expected one {old.strip()!r} (compute fric ... body wall, thermo_style "
                 f"ending in c_fric[16], float format %.10g)")
        text = text.replace(old, new)
    deck = os.path.join(args.workdir, "in.runin_wall_body")
    with open(deck, "w") as out:
        out.write(text)
    log = run_lammps(args, deck, {"nload": 2000, "nslide": 1000, "thermo_every": 100, "out": "runin.dat"},
                     np=args.np)
    blocks = thermo_blocks(log)
    if len(blocks) != 2:
        fail(f"expected the load and slide thermo tables, found {len(blocks)}")
    rows = blocks[0] + blocks[1]
    finite_rows(rows)
    touching = [row for row in rows if row["c_fric[4]"] > 0]
    sliding = [row for row in blocks[1][1:] if row["c_fric[4]"] > 0]
    # the deck's kinetic level is about 0.03 (elastic-plastic steel summits, tau_s 20 MPa)
    if len(touching) < 5 or len(sliding) < 5 or not max(row["c_fric[3]"] for row in sliding) > 0.01:
        fail(f"the wall must touch and slide: {len(touching)} rows with contacts, {len(sliding)} sliding")
    worst = 0.0
    for row in rows:
        step = int(row["Step"])
        worst = max(worst, check(f"step {step}: mu_body c_fric[16] vs mu_eff c_fric[3]", row["c_fric[16]"],
                                 row["c_fric[3]"], 1e-10),
                    check(f"step {step}: load on the wall c_fric[15] vs |f_wall[3]|", row["c_fric[15]"],
                          abs(row["f_wall[3]"]), 1e-10))
    # the ave/time file got mu_body as its last column
    lines = open(os.path.join(args.workdir, "runin.dat")).read().splitlines()
    header = lines[1].lstrip("#").split()
    if header[-1] != "c_fric[16]":
        fail(f"runin.dat: last column is {header[-1]!r}, expected c_fric[16]")
    last = sliding[-1]
    print(f"ok: {len(rows)} rows ({len(touching)} in contact) on {args.np} rank(s): mu_body = mu_eff and load = |f_wall[3]| to "
          f"{worst:.2e}; at step {last['Step']:.0f}: mu = {last['c_fric[16]']:.6f}, load {last['c_fric[15]']:.6f} N, "
          f"{last['c_fric[4]']:.0f} contacts")


# --- 3. single() through compute pair/local -----------------------------------------------------
def single(args):
    fresh_dir(args.workdir)
    r1, r2 = 1.0e-6, 0.8e-6
    log = run_lammps(args, os.path.join(DECKS, "in.contact_single"),
                     {"R1": r1, "R2": r2, "mu_s": args.mu_s, "mu_k": args.mu_k})
    blocks = thermo_blocks(log)
    if len(blocks) != 3:
        fail(f"expected the shear, stop and reverse thermo tables, found {len(blocks)}")
    r_star = r1 * r2 / (r1 + r2)
    worst, states, mismatches = 0.0, {"stick": [], "slide": []}, []
    for block in blocks:
        for row in block:
            step = int(row["Step"])
            if row["c_red[9]"] <= 0.0 or row["c_fric[4]"] != 1.0:
                fail(f"step {step}: the pair must be in contact (pair/local dist {row['c_red[9]']!r}, "
                     f"contacts {row['c_fric[4]']!r})")
            i, j = int(row["c_redi[1]"]), int(row["c_redi[2]"])
            if {i, j} != {1, 2}:
                fail(f"step {step}: property/local lists the pair as {i} {j}")
            normal = [row[f"c_red[{k}]"] for k in (1, 2, 3)]
            tangential = [row[f"c_red[{k}]"] for k in (4, 5, 6)]
            force = [row[f"v_f{axis}{i}"] for axis in "xyz"]
            scale = math.sqrt(sum(f * f for f in force))
            error = max(relative(normal[k] + tangential[k], force[k], scale) for k in range(3))
            worst = max(worst, error)
            state = "stick" if row["c_fric[8]"] == 1.0 else "slide"
            if not error <= 1e-12:
                mismatches.append((step, state, error, [n + t for n, t in zip(normal, tangential)], force,
                                   math.sqrt(sum(t * t for t in tangential)) / row["c_fric[2]"] - 1.0))
            # the normal part pushes i away from j: along x_i - x_j
            sign = 1.0 if i == 1 else -1.0
            towards_i = [-sign * row[f"v_d{axis}"] for axis in "xyz"]
            if not sum(n * d for n, d in zip(normal, towards_i)) > 0.0:
                fail(f"step {step}: the normal part {normal} of pair/local does not push atom {i} away from the other")
            distance = math.sqrt(sum(row[f"v_d{axis}"] ** 2 for axis in "xyz"))
            overlap = r1 + r2 - distance
            check(f"step {step}: p5 vs the overlap R1 + R2 - r", row["c_red[8]"], overlap, 1e-9)
            check(f"step {step}: p4 vs the contact radius sqrt(R* delta)", row["c_red[7]"],
                  math.sqrt(r_star * row["c_red[8]"]), 1e-12)
            check(f"step {step}: dist", row["c_red[9]"], distance, 1e-12)
            check(f"step {step}: |normal part| vs compute runin/friction [1]", math.sqrt(sum(n * n for n in normal)),
                  row["c_fric[1]"], 1e-12)
            if not mismatches or mismatches[-1][0] != step:
                check(f"step {step}: |tangential part| vs compute runin/friction [2]",
                      math.sqrt(sum(t * t for t in tangential)), row["c_fric[2]"], 1e-12, scale=row["c_fric[1]"])
            if abs(sum(t * n for t, n in zip(tangential, normal))) > 1e-12 * scale * scale:
                fail(f"step {step}: the tangential part {tangential} is not normal to {normal}")
            states[state].append(step)
    for state, steps in states.items():
        if not steps:
            fail(f"no {state} step among the compared rows")
    if mismatches:
        step, state, error, got, want, _ = mismatches[0]
        fail(f"the force on atom i from pair/local (fx + p1, fy + p2, fz + p3) differs from the per-atom force "
             f"by more than 1e-12 of |F| at {len(mismatches)} of {sum(map(len, states.values()))} steps "
             f"({', '.join(f'{s} ({t}, {e:.2e}, |p1 p2 p3| / c_fric[2] - 1 = {r:+.2e})' for s, t, e, _, _, r in mismatches[:3])}"
             f"{', ...' if len(mismatches) > 3 else ''}; last {mismatches[-1][0]}); first: step {step} ({state}): "
             f"pair/local {got}, per-atom {want}, relative error {error:.3e}")
    print(f"ok: {sum(map(len, states.values()))} steps (sticking: {len(states['stick'])}, e.g. {states['stick'][-1]}; "
          f"sliding: {len(states['slide'])}, e.g. {states['slide'][-1]}): pair/local force on atom i = per-atom "
          f"force to {worst:.2e}, p4 = sqrt(R* delta), p5 = delta")


# --- 4. mixing of an unset type pair ------------------------------------------------------------
def materials():
    values = {}
    for line in open(COEFFS):
        words = line.split("#")[0].split()
        if words[:1] == ["material"]:
            values[words[1]] = dict(zip(("E", "nu", "rho", "H"), map(float, words[2:6])))
    return values


def mixing(args):
    fresh_dir(args.workdir)
    m = materials()
    al, cu = m["Al"], m["Cu"]
    for mat in (al, cu):
        mat["G"] = mat["E"] / (2.0 * (1.0 + mat["nu"]))
    # like pairs: two bodies of the same material
    estar11 = al["E"] / (2.0 * (1.0 - al["nu"] ** 2))
    estar22 = cu["E"] / (2.0 * (1.0 - cu["nu"] ** 2))
    gstar11 = al["G"] / (2.0 * (2.0 - al["nu"]))
    gstar22 = cu["G"] / (2.0 * (2.0 - cu["nu"]))
    # the unlike pair from the materials directly
    estar12 = 1.0 / ((1.0 - al["nu"] ** 2) / al["E"] + (1.0 - cu["nu"] ** 2) / cu["E"])
    gstar12 = 1.0 / ((2.0 - al["nu"]) / al["G"] + (2.0 - cu["nu"]) / cu["G"])
    r1, r2, speed, dt = 1.0e-6, 0.8e-6, 0.5, 1.0e-10
    blocks = thermo_blocks(run_lammps(args, os.path.join(DECKS, "in.contact_mixing"),
                                      {"R1": r1, "R2": r2, "Estar11": repr(estar11), "Gstar11": repr(gstar11),
                                       "Estar22": repr(estar22), "Gstar22": repr(gstar22), "H1": al["H"],
                                       "H2": cu["H"], "speed": speed}))
    if len(blocks) != 7:
        fail(f"expected 6 pressed positions and the shear run, found {len(blocks)} thermo tables")
    r_star = r1 * r2 / (r1 + r2)
    worst = 0.0
    for block in blocks[:6]:
        row = block[-1]
        overlap = r1 + r2 - row["v_gap"]
        hertz = 4.0 / 3.0 * estar12 * math.sqrt(r_star) * overlap ** 1.5
        worst = max(worst, check(f"overlap {overlap:.3e} m: sum F_n vs Hertz with E*_12", row["c_fric[1]"], hertz, 1e-12),
                    check(f"overlap {overlap:.3e} m: f_z of atom 2 vs Hertz with E*_12", row["v_fz2"], hertz, 1e-12))
    # the like-pair values must not be what the unlike pair uses
    for name, value in (("E*_11", estar11), ("E*_22", estar22)):
        if relative(estar12, value) < 1e-3:
            fail(f"E*_12 = {estar12!r} is too close to {name} = {value!r} to tell mixing from a copy")
    shear = blocks[6]
    overlap = r1 + r2 - shear[0]["v_gap"]
    a = math.sqrt(r_star * overlap)
    first = shear[1]
    if first["c_fric[8]"] != 1.0:
        fail("the first shear step must stick")
    tangential = check("first shear step: |F_t| vs 8 G*_12 a v dt", first["c_fric[2]"],
                       8.0 * gstar12 * a * speed * dt, 1e-12)
    print(f"ok: E*_11 = {estar11:.6e}, E*_22 = {estar22:.6e} Pa -> E*_12 = {estar12:.6e} Pa: Hertz force at 6 "
          f"overlaps to {worst:.2e}; G*_12 = {gstar12:.6e} Pa: first tangential step to {tangential:.2e}")


# --- 5. restart written with other sub-models ---------------------------------------------------
def restart_error(args):
    fresh_dir(args.workdir)
    run_lammps(args, os.path.join(SOURCE_DIR, args.write), log="write.lammps")
    read = os.path.join(SOURCE_DIR, args.read)
    name, value = args.control.split("=", 1)
    control = run_lammps(args, read, {name: value}, log="control.lammps")
    if any(line.startswith("ERROR") for line in control.splitlines()) or "Loop time" not in control:
        fail(f"the control run (-var {name} {value}: the restart's own models) did not run cleanly")
    result = subprocess.run([args.lmp, "-in", read, "-log", "none"], cwd=args.workdir, env=mpi_env(),
                            capture_output=True, text=True, timeout=60)
    error = single_error(result, args.pattern, "the deck with other sub-models than the restart's was accepted")
    print(f"ok: control (-var {name} {value}) runs; " + error)


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("slider-mu-body", "wall-mu-body", "single", "mixing", "restart-error"):
        p = sub.add_parser(name)
        p.add_argument("--lmp", required=True)
        p.add_argument("--workdir", required=True)
        p.add_argument("--mpiexec", default="mpiexec")
        p.add_argument("--np", type=int, default=1)
        if name == "single":
            p.add_argument("--mu-s", type=float, default=0.6)
            p.add_argument("--mu-k", type=float, default=0.4)
        if name == "restart-error":
            for option in ("--write", "--read", "--pattern", "--control"):
                p.add_argument(option, required=True)
    args = parser.parse_args()
    args.workdir = os.path.abspath(args.workdir)
    {"slider-mu-body": slider_mu_body, "wall-mu-body": wall_mu_body, "single": single,
     "mixing": mixing, "restart-error": restart_error}[args.command](args)


if __name__ == "__main__":
    main()
