#!/usr/bin/env python3
"""Single asperity-pair tests of pair runin/asperity against closed forms (run by ctest; stdlib only).

  single_pair.py press --lmp LMP --workdir DIR [--worn V1 V2] [--mpiexec MPIEXEC --np N]
  single_pair.py slide --lmp LMP --workdir DIR [--archard plain|thesis] [--reshape yes|no] [--transfer F]
  single_pair.py shear --lmp LMP --workdir DIR [--restick V] [--friction coulomb|strength --tau TAU]

Closed forms: Hertz, Sneddon's flat punch + Hertz on truncated spheres, Archard V = k W s / H,
the Mindlin spring k_t = 8 G* a with the static -> kinetic Coulomb limit. See doc/worn_asperity_geometry.md.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, run_lammps, thermo_blocks, worn  # noqa: E402

DECKS = os.path.join(SOURCE_DIR, "tests", "lammps", "decks")
COEFFS = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")


def run_lmp(args, deck, variables, log="log.lammps"):
    return thermo_blocks(run_lammps(args, os.path.join(DECKS, deck), variables, log, np=getattr(args, "np", 1)))


def check(name, got, want, tolerance, scale=None):
    scale = abs(want) if scale is None else scale
    error = abs(got - want) / scale if scale > 0 else abs(got - want)
    if not error <= tolerance:
        fail(f"{name}: got {got!r}, closed form {want!r} (relative error {error:.3e} > {tolerance:g})")
    return error


# --- closed forms (run_deck.cap_height / worn: bisection, independent of the C++ kernels) ---
def sneddon(e_star, r_star, flat, overlap):
    """(F, a, U) of a truncated paraboloid (flat radius b) pressed by delta: flat punch + Hertz."""
    if overlap <= 0.0:
        return 0.0, 0.0, 0.0
    b = flat
    a2 = (b * b + math.sqrt(b ** 4 + 4.0 * r_star ** 2 * overlap ** 2)) / 2.0
    a = math.sqrt(a2)
    c = r_star * overlap / a
    force = 2.0 * e_star / (3.0 * r_star) * c * (2.0 * a2 + b * b)
    energy = 2.0 * e_star / (3.0 * r_star ** 2) * (0.8 * (a ** 5 - b ** 5) - b ** 4 * (a - b))
    return force, a, energy


def materials():
    """E*, G* and the hardnesses of the Al (type 1) / Cu (type 2) pair in potentials/CuAl.runin."""
    values = {}
    pair = None
    for line in open(COEFFS):
        words = line.split("#")[0].split()
        if words[:1] == ["material"]:
            values[words[1]] = tuple(float(w) for w in words[2:6])
        elif words[:1] == ["pair"]:
            pair = [float(w) for w in words[3:8]]
    (e1, n1, _, h1), (e2, n2, _, h2) = values["Al"], values["Cu"]
    g1, g2 = e1 / (2 * (1 + n1)), e2 / (2 * (1 + n2))
    e_star = 1.0 / ((1 - n1 * n1) / e1 + (1 - n2 * n2) / e2)
    g_star = 1.0 / ((2 - n1) / g1 + (2 - n2) / g2)
    restitution, mu_s, mu_k, d_c, k = pair
    return dict(e_star=e_star, g_star=g_star, h_al=h1, h_cu=h2, mu_s=mu_s, mu_k=mu_k, d_c=d_c, k=k)


def press(args):
    """F(delta), contact area and energy of one pair pressed step by step vs Hertz / Sneddon."""
    fresh_dir(args.workdir)
    r1, r2, e_star = 1.0e-6, 0.8e-6, 4.8e10
    v1, v2 = args.worn
    blocks = run_lmp(args, "in.single_pair_press", {"R1": r1, "R2": r2, "V1": v1, "V2": v2, "Estar": e_star})
    h1, b1 = worn(r1, v1, 0.0)
    h2, b2 = worn(r2, v2, 0.0)
    r_star = r1 * r2 / (r1 + r2)
    flat = min(b1, b2)
    worst, touching = 0.0, 0
    for block in blocks:
        row = block[-1]
        reach = (r1 + r2) - (h1 + h2)
        overlap = reach - row["v_gap"]
        force, a, energy = sneddon(e_star, r_star, flat, overlap)
        if force == 0.0:
            if row["c_fric[1]"] != 0.0 or row["c_fric[4]"] != 0.0:
                fail(f"force {row['c_fric[1]']!r} at gap {row['v_gap']!r}: the worn summits do not touch")
            continue
        touching += 1
        worst = max(worst, check("sum F_n", row["c_fric[1]"], force, 1e-10),
                    check("f_z of atom 2", row["v_fz2"], force, 1e-10),
                    check("contact area", row["c_fric[9]"], math.pi * a * a, 1e-10),
                    check("pair energy", row["PotEng"], energy, 1e-9))
    if touching < 5 or (v1 == 0.0 and touching != len(blocks)):
        fail(f"only {touching} of {len(blocks)} positions in contact")
    print(f"ok: {touching} positions in contact, flat b = {flat:.4e} m, drops {h1:.4e} + {h2:.4e} m, "
          f"worst relative error {worst:.3e}")


def read_dump(path):
    lines = open(path).read().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    columns = lines[start].split()[2:]
    return {int(float(line.split()[0])): dict(zip(columns, map(float, line.split()))) for line in lines[start + 1:]}


def slide(args):
    """Archard volume for a known slip, worn geometry, transfer bookkeeping and restart of one pair."""
    fresh_dir(args.workdir)
    r1 = r2 = 1.0e-6
    overlap, speed, nslide, dt = 5.0e-9, 2.0, 2000, 1.0e-10
    m = materials()
    blocks = run_lmp(args, "in.single_pair_slide",
                     {"R1": r1, "R2": r2, "overlap": overlap, "speed": speed, "nslide": nslide,
                      "archard": args.archard, "reshape": args.reshape, "transfer": args.transfer,
                      "coeffs": COEFFS})
    sliding, final = blocks[0], blocks[1][-1]
    last = sliding[-1]
    removed = last["c_fric[5]"]
    state = read_dump(os.path.join(args.workdir, "state.dump"))
    lost = [state[1]["f_RUNIN_WEAR_STATE[1]"], state[2]["f_RUNIN_WEAR_STATE[1]"]]
    gained = [state[1]["f_RUNIN_WEAR_STATE[2]"], state[2]["f_RUNIN_WEAR_STATE[2]"]]
    r_star = r1 * r2 / (r1 + r2)
    form = 3.0 if args.archard == "thesis" else 1.0
    notes = []
    if args.reshape == "no":
        # constant load: the Hertz force at the fixed overlap; slip = v N dt minus the final spring
        load, a, _ = sneddon(m["e_star"], r_star, 0.0, r1 + r2 - last["v_gap"])
        check("F_n while sliding", last["c_fric[1]"], load, 1e-10)
        spring = m["mu_k"] * load / (8.0 * m["g_star"] * a)
        slip = speed * nslide * dt - spring
        # per-body Archard: each body loses k W s / H_i (the thesis's form: / 3 H_i)
        archard = m["k"] * load * slip * (1.0 / m["h_al"] + 1.0 / m["h_cu"]) / form
        check("removed volume vs k W s (1/H_Al + 1/H_Cu)", removed, archard, 1e-10)
        notes.append(f"removed {removed:.6e} m^3 = k W s (1/H_Al + 1/H_Cu) / {form:g} = {archard:.6e}")
    # per-atom bookkeeping: k_i/H_i per body (equal k: the 1/H split) and transfer. (c_fric[5] IS the sum over atoms of the volume lost;
    # verify_micro.py wear-budget checks it against the per-contact wear rate on a multi-contact slider.)
    share_al = m["h_cu"] / (m["h_al"] + m["h_cu"])
    check("Al share of the removed volume", lost[0], share_al * removed, 1e-13)
    f = args.transfer
    check("volume gained by Cu (from Al)", gained[1], f * lost[0], 1e-14, scale=removed)
    check("volume gained by Al (from Cu)", gained[0], f * lost[1], 1e-14, scale=removed)
    deposited, debris = sum(gained), (1.0 - f) * removed
    check("removed = deposited + debris", deposited + debris, removed, 1e-14)
    # geometry: truncated sphere of the net removed volume
    geometry = []
    for atom, radius in ((1, r1), (2, r2)):
        h, a_w = worn(radius, state[atom]["f_RUNIN_WEAR_STATE[1]"], state[atom]["f_RUNIN_WEAR_STATE[2]"])
        check(f"wear depth of atom {atom}", state[atom]["f_RUNIN_WEAR_STATE[3]"], h, 1e-12, scale=max(abs(h), 1e-30))
        check(f"flat radius of atom {atom}", state[atom]["f_RUNIN_WEAR_STATE[4]"], a_w, 1e-12, scale=max(a_w, 1e-30))
        geometry.append((h, a_w))
    # force with the final geometry (setup of 'run 0', no wear added)
    if args.reshape == "yes":
        (h1, b1), (h2, b2) = geometry
        reach = (r1 + r2) - (h1 + h2)
        force, _, _ = sneddon(m["e_star"], r_star, min(b1, b2), reach - final["v_gap"])
    else:
        force, _, _ = sneddon(m["e_star"], r_star, 0.0, r1 + r2 - final["v_gap"])
    check("F_n with the worn geometry", final["c_fric[1]"], force, 1e-10)
    notes.append(f"F_n {final['c_fric[1]']:.6e} N with h = {geometry[0][0]:.3e}, {geometry[1][0]:.3e} m")
    # restart: settings, coefficients and per-atom state come back unchanged
    restarted = run_lmp(args, "in.single_pair_restart", {}, log="restart.lammps")[-1][-1]
    check("F_n after read_restart", restarted["c_fric[1]"], final["c_fric[1]"], 1e-15)
    check("wear volume after read_restart", restarted["c_fric[5]"], removed, 1e-15)
    again = read_dump(os.path.join(args.workdir, "restarted.dump"))
    if again != state:
        fail(f"per-atom wear state changed across write_restart/read_restart:\n{state}\n{again}")
    print("ok: " + "; ".join(notes))


def shear(args):
    """Stick, break-away at mu_s F_n, slip weakening over d_c, stop (re-stick) and restart, step by step."""
    fresh_dir(args.workdir)
    r1 = r2 = 1.0e-6
    overlap, e_star, g_star = 5.0e-9, 4.8e10, 1.9e10
    mu_s, mu_k, d_c, speed, dt = 0.6, 0.4, 5.0e-9, 1.0, 1.0e-10
    blocks = run_lmp(args, "in.single_pair_shear",
                     {"R1": r1, "R2": r2, "overlap": overlap, "Estar": e_star, "Gstar": g_star, "mu_s": mu_s,
                      "mu_k": mu_k, "d_c": d_c, "speed": speed, "restick": args.restick,
                      "friction": args.friction, "tau": args.tau})
    if len(blocks) != 3:
        fail(f"expected slide, stop and slide thermo tables, got {len(blocks)}")
    r_star = r1 * r2 / (r1 + r2)
    fn, a, _ = sneddon(e_star, r_star, 0.0, overlap)
    kt = 8.0 * g_star * a
    adhesion = ploughing = 0.0
    if args.friction == "strength":
        adhesion = args.tau * math.pi * a * a
        ploughing = 2.0 / math.pi * (overlap / a) * fn
        mu_k_eff = (adhesion + ploughing) / fn
        mu_s_eff = mu_k_eff + mu_s - mu_k
    else:
        mu_s_eff, mu_k_eff = mu_s, mu_k

    def limit(slip):
        if slip <= 0.0:
            return mu_s_eff * fn
        return (mu_k_eff + (mu_s_eff - mu_k_eff) * max(0.0, 1.0 - slip / d_c)) * fn

    spring, slip, worst, peaks = 0.0, 0.0, 0.0, []
    for block, velocity in zip(blocks, (speed, 0.0, speed)):
        peak = 0.0
        for index, row in enumerate(block):
            advance = index > 0    # the first row of each run is its setup: history read, not changed
            trial = spring + (velocity * dt if advance else 0.0)
            force = kt * trial
            slipping = force > limit(slip)
            increment = 0.0
            if slipping:
                force = limit(slip)
                increment = trial - force / kt
                trial = force / kt
            if advance:
                spring, slip = trial, slip + increment
                if args.restick > 0.0 and not slipping and velocity < args.restick:
                    slip = 0.0
            step = int(row["Step"])
            worst = max(worst, check(f"|F_t| at step {step}", row["c_fric[2]"], force, 1e-10, scale=fn))
            worst = max(worst, check(f"frictional power at step {step}", row["c_fric[13]"],
                                     force * increment / dt, 1e-10, scale=fn * speed))
            if row["c_fric[8]"] != (0.0 if slipping else 1.0):
                fail(f"stick fraction {row['c_fric[8]']} at step {step}, slipping = {slipping}")
            check("contact area", row["c_fric[9]"], math.pi * a * a, 1e-12)
            check("mu_adhesion", row["c_fric[6]"], adhesion / fn, 1e-10, scale=1.0)
            check("mu_ploughing", row["c_fric[7]"], ploughing / fn, 1e-10, scale=1.0)
            peak = max(peak, row["c_fric[2]"])
        peaks.append(peak)
    # the headline numbers, each also covered by the replay above
    first = blocks[0][1]["c_fric[2]"] / (speed * dt)
    check("initial tangential stiffness vs Mindlin 8 G* a", first, kt, 1e-10)
    check("break-away force vs mu_s F_n", peaks[0], mu_s_eff * fn, 1e-12)
    check("sliding force vs mu_k F_n", blocks[0][-1]["c_fric[2]"], mu_k_eff * fn, 1e-12)
    want_second_peak = mu_s_eff * fn if args.restick > 0.0 else mu_k_eff * fn
    check("break-away after the stop", peaks[2], want_second_peak, 1e-12)
    print(f"ok: k_t = {first:.6e} N/m (8 G* a = {kt:.6e}), peak {peaks[0] / fn:.6f} F_n, sliding "
          f"{blocks[0][-1]['c_fric[2]'] / fn:.6f} F_n, after stop {peaks[2] / fn:.6f} F_n; worst {worst:.2e}")


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("press", "slide", "shear"):
        p = sub.add_parser(name)
        p.add_argument("--lmp", required=True)
        p.add_argument("--workdir", required=True)
        if name == "press":
            p.add_argument("--worn", nargs=2, type=float, default=(0.0, 0.0))
            p.add_argument("--mpiexec", default="mpiexec")
            p.add_argument("--np", type=int, default=1)
        elif name == "slide":
            p.add_argument("--archard", choices=("plain", "thesis"), default="plain")
            p.add_argument("--reshape", choices=("yes", "no"), default="no")
            p.add_argument("--transfer", type=float, default=0.0)
        else:
            p.add_argument("--restick", type=float, default=0.0)
            p.add_argument("--friction", choices=("coulomb", "strength"), default="coulomb")
            p.add_argument("--tau", type=float, default=0.0)
    args = parser.parse_args()
    {"press": press, "slide": slide, "shear": shear}[args.command](args)


if __name__ == "__main__":
    main()
