#!/usr/bin/env python3
"""LAMMPS-level verification of pair runin/asperity (run by ctest; stdlib only).

  verify_micro.py impact --lmp LMP --workdir DIR                     elastic: energy, Hertz contact time
  verify_micro.py impact --lmp LMP --workdir DIR --restitution E...  damped: rebound / impact speed = e
  verify_micro.py wear-budget --lmp LMP --workdir DIR [--mpiexec M --np N]
  verify_micro.py restart --lmp LMP --workdir DIR [--jump M [--jump-rate T --jump-max-depth D]]  bit for bit
                                                                     (--jump: with fix runin/wear/jump)

Decks: tests/lammps/decks/in.impact_pair, in.slider_verify, in.slider_verify_restart.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks  # noqa: E402

DECKS = os.path.join(SOURCE_DIR, "tests", "lammps", "decks")
COEFFS = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")


# With elastic-plastic Al summits (S_y 34 MPa) the deck's 0.02 N (35 MPa nominal, the yield stress itself)
# would push the slider through the layer; 2 mN keeps the summits within the fitted omega/omega_c range.
PLASTIC_LOAD = 2.0e-3


def run_lmp(args, deck, variables, log, np=1):
    normal = getattr(args, "normal", "hertz")
    variables = dict(variables, normal=normal)
    if getattr(args, "jump", 1.0) > 1.0:
        variables["jump"] = args.jump    # fix runin/wear/jump from the slide on (the decks' jump variables)
        if getattr(args, "jump_rate", 0.0) > 0.0:
            variables.update(jump_rate=args.jump_rate, jump_max_depth=args.jump_max_depth)
    if getattr(args, "caps", False):
        variables["caps"] = "yes"    # the same spheres as caps: atoms at their tops (pair_style caps)
    if normal == "elastic/plastic" and "load" not in variables:
        variables["load"] = PLASTIC_LOAD
    return thermo_blocks(run_lammps(args, os.path.join(DECKS, deck), variables, log, np))


# --- 2. head-on impact ---------------------------------------------------------------------------
def impact(args):
    """Two asperities collide head on. Elastic (e = 1): total energy at every step within 1e-6 of the
    initial kinetic energy, contact time within 1 % of Hertz. Damped: v_out / v_in = e within 1 %."""
    fresh_dir(args.workdir)
    r1, r2, rho1, rho2, e_star, v0 = 1.0e-6, 0.8e-6, 8960.0, 2700.0, 4.8e10, 1.0
    m1, m2 = (rho * 4.0 / 3.0 * math.pi * r ** 3 for rho, r in ((rho1, r1), (rho2, r2)))
    mass, r_star = m1 * m2 / (m1 + m2), r1 * r2 / (r1 + r2)
    overlap_max = (15.0 * mass * v0 ** 2 / (16.0 * e_star * math.sqrt(r_star))) ** 0.4
    integral = 0.4 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)    # int_0^1 dx / sqrt(1 - x^5/2)
    contact_time = 2.0 * integral * overlap_max / v0
    dt, gap = 1.0e-12, 1.0e-10    # 5441 steps per contact: velocity Verlet's energy error ~ (omega dt)^2
    variables = {"R1": r1, "R2": r2, "rho1": rho1, "rho2": rho2, "Estar": e_star, "v0": v0, "gap": gap, "dt": dt}
    ke0 = 0.5 * m2 * v0 ** 2
    for e in args.restitution or [1.0]:
        # a damped pair leaves the contact at e v0 from an overlap below delta_max
        nsteps = int((2.0 * gap / v0 + contact_time + overlap_max / (e * v0)) / dt)
        (rows,) = run_lmp(args, "in.impact_pair", dict(variables, e=e, nsteps=nsteps), f"log.e{e}")
        touching = [row for row in rows if row["c_fric[4]"] == 1.0]
        if not touching or rows[-1]["c_fric[4]"] != 0.0 or rows[0]["c_fric[4]"] != 0.0:
            fail(f"e = {e}: the asperities must approach, touch and separate within the run")
        if abs(rows[0]["KinEng"] - ke0) > 1e-12 * ke0:
            fail(f"e = {e}: initial kinetic energy {rows[0]['KinEng']!r}, expected 1/2 m2 v0^2 = {ke0!r}")
        rebound = rows[-1]["v_vrel"] / v0    # vz[2] - vz[1]: -v0 before, +e v0 after
        if e == 1.0:
            drift = max(abs(row["KinEng"] + row["PotEng"] - ke0) for row in rows) / ke0
            if not drift <= 1e-6:
                fail(f"energy not conserved through the elastic collision: max |E - E0| / E0 = {drift:.3e} "
                     f"(limit 1e-6)")
            duration = len(touching) * dt
            error = (duration - contact_time) / contact_time
            if not abs(error) <= 0.01:
                fail(f"contact time {duration:.6e} s vs Hertz {contact_time:.6e} s: {error:+.3e} (limit 1 %)")
            print(f"ok: elastic: max |E - E0| / E0 = {drift:.3e}, contact time {duration:.6e} s vs Hertz "
                  f"{contact_time:.6e} s ({error:+.2e}), rebound {rebound:.9f} v0")
        else:
            error = (rebound - e) / e
            if not abs(error) <= 0.01:
                fail(f"measured restitution {rebound:.6f} for input e = {e}: {error:+.3e} (limit 1 %)")
            print(f"ok: e = {e}: measured {rebound:.6f} ({error:+.2e} relative)")


# --- 4. wear budget on a multi-contact slider -------------------------------------------------------
def read_dump(path):
    """(columns, {id: [values as text]}) of a one-snapshot custom dump."""
    lines = open(path).read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    columns = lines[start].split()[2:]
    return columns, {int(line.split()[0]): line.split() for line in lines[start + 1:]}


def wear_budget(args):
    """Sum over atoms of the per-atom volume lost = compute runin/friction's cumulative wear (entry 5)
    = time integral of its per-step wear rate (entry 12, summed over contacts in the force loop)
    = body 1 + body 2 (entries 10, 11) = per-type sums of the dump; transfer 0.3 deposits 0.3 of it."""
    fresh_dir(args.workdir)
    blocks = run_lmp(args, "in.slider_verify", {"mode": "full", "coeffs": COEFFS}, "log.lammps", args.np)
    if len(blocks) != 3:
        fail(f"expected settle and two slide thermo tables, got {len(blocks)}")
    dt = 1.0e-10    # the deck's timestep
    # the first row of each run is its setup: forces re-evaluated, no wear added (rate 0)
    if any(block[0]["c_fric[12]"] != 0.0 for block in blocks):
        fail("a setup row reports a non-zero wear rate")
    rates = [row["c_fric[12]"] for block in blocks for row in block[1:]]
    integral = math.fsum(rate * dt for rate in rates)
    last = blocks[-1][-1]
    total = last["c_fric[5]"]
    columns, atoms = read_dump(os.path.join(args.workdir, "state.full.dump"))
    lost, gained, kind = (columns.index(c) for c in ("f_RUNIN_WEAR_STATE[1]", "f_RUNIN_WEAR_STATE[2]", "type"))
    per_atom = math.fsum(float(a[lost]) for a in atoms.values())
    per_type = [math.fsum(float(a[lost]) for a in atoms.values() if a[kind] == t) for t in ("1", "2")]
    deposited = math.fsum(float(a[gained]) for a in atoms.values())
    worn_atoms = sum(1 for a in atoms.values() if float(a[lost]) > 0.0)
    if total <= 0.0 or worn_atoms < 10 or sum(1 for r in rates if r > 0.0) < 100:
        fail(f"too little wear to test: total {total!r}, {worn_atoms} worn atoms")
    worst = 0.0
    for name, value in (("sum over atoms of the volume lost", per_atom),
                        ("time integral of the wear rate (entry 12)", integral),
                        ("body 1 + body 2 (entries 10 + 11)", last["c_fric[10]"] + last["c_fric[11]"]),
                        ("deposited / transfer fraction 0.3", deposited / 0.3)):
        error = abs(value - total) / total
        if not error <= 1e-12:
            fail(f"{name} = {value!r} vs compute runin/friction's cumulative wear {total!r}: {error:.3e} (limit 1e-12)")
        worst = max(worst, error)
    for body, (entry, value) in enumerate(zip(("c_fric[10]", "c_fric[11]"), per_type), 1):
        error = abs(last[entry] - value) / total
        if not error <= 1e-12:
            fail(f"body {body}: entry {entry} = {last[entry]!r} vs the dump's sum {value!r}: {error:.3e}")
        worst = max(worst, error)
    print(f"ok: {args.np} rank(s): wear {total:.6e} m^3 on {worn_atoms} atoms over {len(rates)} steps; "
          f"atoms, rate integral, bodies and transfer agree to {worst:.2e}")


# --- 8b. restart bit for bit -----------------------------------------------------------------------
def restart(args):
    """Stop the slide at nsplit with write_restart, continue with read_restart (pair_style re-specified or
    not): thermo rows (all 13 friction entries, every step) and the final x, v, omega, f and wear state
    must equal the reference, which runs the same two 'run' commands in one process, to the last bit."""
    fresh_dir(args.workdir)
    settle, split, total = 1000, 300, 1000    # the deck's nsettle, nsplit, nslide
    reference = run_lmp(args, "in.slider_verify", {"mode": "full", "coeffs": COEFFS}, "log.reference")
    run_lmp(args, "in.slider_verify", {"mode": "first", "coeffs": COEFFS}, "log.first")
    by_step = {int(row["Step"]): row for row in reference[2]}
    at_split = reference[1][-1]
    # the continuation must depend on contact history: sticking and slipping contacts carrying F_t (with
    # elastic-plastic summits every contact slips at this load, and each carries its plastic maximum instead)
    sticking_ok = 0.0 < at_split["c_fric[8]"] < 1.0 or getattr(args, "normal", "hertz") == "elastic/plastic"
    if not (at_split["c_fric[4]"] >= 10 and sticking_ok and at_split["c_fric[3]"] > 0.1):
        fail(f"split step {settle + split}: want >= 10 contacts, some sticking and some slipping, mu_eff > 0.1; "
             f"got {at_split}")
    _, before = read_dump(os.path.join(args.workdir, "state.split_full.dump"))
    for respecify in ("no", "yes"):
        (rows,) = run_lmp(args, "in.slider_verify_restart", {"respecify": respecify, "coeffs": COEFFS},
                          f"log.restart_{respecify}")
        if [int(r["Step"]) for r in rows] != sorted(by_step):
            fail("the restarted run does not cover the reference's steps")
        # setup row: no spring advance, so its tangential force is the restored history alone
        if rows[0]["c_fric[2]"] <= 0.0 or rows[0] != by_step[settle + split]:
            fail(f"respecify {respecify}: setup after read_restart {rows[0]} != reference {by_step[settle + split]}")
        for row in rows:
            if row != by_step[int(row["Step"])]:
                diff = {k: (row[k], by_step[int(row["Step"])][k]) for k in row if row[k] != by_step[int(row["Step"])][k]}
                fail(f"respecify {respecify}: step {int(row['Step'])} differs from the uninterrupted run: {diff}")
        columns, want = read_dump(os.path.join(args.workdir, "state.full.dump"))
        _, got = read_dump(os.path.join(args.workdir, "state.restarted.dump"))
        if got != want:
            bad = next(tag for tag in want if got.get(tag) != want[tag])
            fail(f"respecify {respecify}: final state of atom {bad} differs:\n{columns}\n{want[bad]}\n{got.get(bad)}")
        os.rename(os.path.join(args.workdir, "state.restarted.dump"),
                  os.path.join(args.workdir, f"state.restarted_{respecify}.dump"))
    if args.jump > 1.0:
        # the jump fix's global state (equivalent steps, jumps, last factor, the rate controller's depth) continues
        def jump_line(log):
            lines = [line for line in open(os.path.join(args.workdir, log)) if line.startswith("JUMP ")]
            if not lines:
                fail(f"{log}: no JUMP line (fix runin/wear/jump not defined?)")
            return lines[-1].split()[1:]
        want_jump = jump_line("log.reference")
        if float(want_jump[1]) < 2:
            fail(f"the reference made {want_jump[1]} jumps; the test needs jumps on both sides of the split")
        for respecify in ("no", "yes"):
            if jump_line(f"log.restart_{respecify}") != want_jump:
                fail(f"respecify {respecify}: fix runin/wear/jump state after the restart "
                     f"{jump_line(f'log.restart_{respecify}')} != uninterrupted {want_jump}")
    builds = [line for line in open(os.path.join(args.workdir, "log.restart_yes")) if "Neighbor list builds" in line]
    if not builds or int(builds[-1].split("=")[1]) < 1:
        fail(f"the continued run must rebuild the neighbour list (contact history re-matched): {builds}")
    # the continued stretch really moved and wore the asperities
    moved = sum(1 for tag in want if want[tag][2] != before[tag][2])
    wear_col = columns.index("f_RUNIN_WEAR_STATE[1]")
    worn = sum(1 for tag in want if want[tag][wear_col] != before[tag][wear_col])
    if moved == 0 or worn == 0:
        fail(f"the continued run changed {moved} positions and {worn} wear states")
    print(f"ok: split at step {settle + split} ({at_split['c_fric[4]']:.0f} contacts, stick fraction "
          f"{at_split['c_fric[8]']:.3f}, |F_t| {at_split['c_fric[2]']:.4e} N); {len(rows)} thermo rows x 13 "
          f"entries and {len(want)} atoms x {len(columns)} columns (x v omega f wear) identical to the last bit "
          f"after {total - split} steps, with and without re-specifying pair_style; {worn} atoms wore meanwhile")


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("impact", "wear-budget", "restart"):
        p = sub.add_parser(name)
        p.add_argument("--lmp", required=True)
        p.add_argument("--workdir", required=True)
        p.add_argument("--mpiexec", default="mpiexec")
        p.add_argument("--np", type=int, default=1)
        p.add_argument("--normal", default="hertz", choices=("hertz", "elastic/plastic"))
        if name == "impact":
            p.add_argument("--restitution", type=float, nargs="+")
        else:
            p.add_argument("--caps", action="store_true", help="the slider's spheres as caps (pair_style caps)")
        if name == "restart":
            p.add_argument("--jump", type=float, default=1.0, help="jump factor of fix runin/wear/jump (1: none)")
            p.add_argument("--jump-rate", type=float, default=0.0, help="with --jump: its rate tolerance (the "
                           "controller's state restarts too)")
            p.add_argument("--jump-max-depth", type=float, default=1.0, help="with --jump-rate: its max_depth")
    args = parser.parse_args()
    {"impact": impact, "wear-budget": wear_budget, "restart": restart}[args.command](args)


if __name__ == "__main__":
    main()
