#!/usr/bin/env python3
"""The rough-on-rough homogenisation cell inputs/in.rve_rough (run by ctest; stdlib only).

  rve_rough.py physics --lmp LMP --workdir DIR [--nside 24] [--depth 5e-9]
  rve_rough.py ranks --lmp LMP --workdir DIR [--mpiexec MPIEXEC] [--nside 16] [--depth 5e-9]

physics: Steel1020 on Steel1020 (R 100 um, sigma 0.2 um per body), physical wear (accel 1), at 5 and 20 MPa.
Asserted (doc/rve_cell.md, "rough on rough"):
  - the contacts carry the load at the end of loading (sum F_n within 2 % of p A);
  - the real area is proportional to the load early in the run-in: after loading W / A_r at 5 and 20 MPa within 10 % of
    each other, in the Bowden-Tabor band 0.5-1.2 H; while sliding, A_r/A at 20 MPa over A_r/A at 5 MPa (means
    over h in [depth/5, depth]) within 25 % of the pressure ratio 4 (on the flat counterface of in.rve_wall it
    is ~1: the worn flats conform to the wall; here it falls to ~2 by h = 20 nm, doc/rve_cell.md);
  - the rough body's Rq falls while it wears (Rq at h = depth below 0.95 x Rq at the start of sliding);
  - the worn volume is Archard's: h + h_cf = 2 k p s / H to 1e-3;
  - the complete output file exists only after the run (out.part renamed at the end).
ranks: the cell at 1 and 2 MPI ranks, every output value to 1e-9 relative.
bins: the deck's settings for speed (doc/homogenise.md, "Speed") change no bit of the output, at 20 MPa: its
  neighbour bins, a sixth of the list cutoff 2R + skin, against LAMMPS's own (half the cutoff), with the same
  neighbour count and list builds; and its load per summit, a number, against the equal-style variable
  -v_load/count(slider) that fix aveforce evaluated every step before.
caps: the summits as caps (pair_style runin/asperity caps, the deck's -var caps yes) against whole spheres, at
  20 MPa: the same contacts after loading, every output value within 1e-4 relative, a ghost shell at least 5 times
  smaller and no longer list, and caps at 1 and 2 ranks within 1e-4. Not to the bit: the centres are computed, so
  the overlaps differ in the last bits, and a plastic contact at its largest interference switches between its
  loading and its unloading stiffness (which set the damping) on such a bit; whole spheres agree across ranks to
  1e-12 only because their centres, 2R apart in z, fix which atom of a pair owns it.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, numeric_table, run_lammps, run_lammps_two_at_a_time  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "inputs", "in.rve_rough")
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
K, H = 7.0e-3, 1.19e9           # Steel1020 on Steel1020 (potentials/Steel1020.runin)
COLUMNS = ("step", "s", "h", "h_cf", "mu", "rq", "rsk", "af", "mu_adh", "mu_plough", "contacts")
LOADED = re.compile(r"^REGIME loaded.*?W = (\S+) N \(load (\S+) N\), W/A_r = (\S+) Pa", re.M)


def run_cell(args, pressure, name, np=1, nside=None):
    out = f"{name}.dat"
    log = run_lammps(args, DECK, {"material": MATERIAL, "pressure": pressure, "accel": 1.0,
                                  "nside": nside or args.nside, "depth": args.depth, "seed": 11,
                                  "nout": 500, "out": out}, log=f"log.{name}", np=np)
    path = os.path.join(args.workdir, out)
    if not os.path.exists(path) or os.path.exists(path + ".part"):
        fail(f"{name}: the output was not renamed from {out}.part to {out} at the end of the run")
    rows = [dict(zip(COLUMNS, r)) for r in numeric_table(path)]
    match = LOADED.search(log)
    if not match:
        fail(f"{name}: no 'REGIME loaded' line in the log")
    w, load, p_real = (float(x) for x in match.groups())
    return rows, w, load, p_real


def physics(args):
    fresh_dir(args.workdir)
    cells = {}
    for pressure in (5.0e6, 2.0e7):
        rows, w, load, p_real = run_cell(args, pressure, f"p{pressure:g}")
        if abs(w / load - 1.0) > 0.02:
            fail(f"p = {pressure:g} Pa: the contacts carry {w:.4g} N of the load {load:.4g} N after loading")
        if not 0.5 * H <= p_real <= 1.2 * H:
            fail(f"p = {pressure:g} Pa: W / A_r = {p_real:.4g} Pa after loading, outside 0.5-1.2 H")
        last, first = rows[-1], rows[1]
        if last["h"] < args.depth:
            fail(f"p = {pressure:g} Pa: the cell stopped at h = {last['h']:g} m before {args.depth:g} m")
        archard = 2.0 * K * pressure * last["s"] / H
        if abs((last["h"] + last["h_cf"]) / archard - 1.0) > 1e-3:
            fail(f"p = {pressure:g} Pa: h + h_cf = {last['h'] + last['h_cf']:.6g} m, Archard {archard:.6g} m")
        if not last["rq"] < 0.95 * first["rq"]:
            fail(f"p = {pressure:g} Pa: Rq {first['rq']:.4g} -> {last['rq']:.4g} m does not fall by 5 %")
        band = [r["af"] for r in rows[1:] if r["h"] >= args.depth / 5]
        cells[pressure] = sum(band) / len(band)
        print(f"p = {pressure:g} Pa: W = {w:.4g} N of {load:.4g} N, W/A_r = {p_real:.4g} Pa after loading; "
              f"sliding s = {last['s']:.4g} m to h = {last['h']:.4g} m: Archard ratio "
              f"{(last['h'] + last['h_cf']) / archard:.6f}, Rq {first['rq']:.4g} -> {last['rq']:.4g} m, "
              f"mean A_r/A {cells[pressure]:.5f}, mu_body {last['mu']:.4f}")
    ratio = cells[2.0e7] / cells[5.0e6]
    print(f"A_r/A(20 MPa) / A_r/A(5 MPa) = {ratio:.3f} (load ratio 4)")
    if not 3.0 <= ratio <= 5.0:
        fail(f"the real area is not proportional to the load: A_r/A ratio {ratio:.3f} for a load ratio of 4")
    print("PASS")


def ranks(args):
    fresh_dir(args.workdir)
    one = run_cell(args, 2.0e7, "np1")[0]
    two = run_cell(args, 2.0e7, "np2", np=2)[0]
    if len(one) != len(two):
        fail(f"1 rank wrote {len(one)} rows, 2 ranks {len(two)}")
    worst = 0.0
    for a, b in zip(one, two):
        for key in COLUMNS:
            worst = max(worst, abs(a[key] - b[key]) / max(abs(a[key]), 1e-300))
    print(f"{len(one)} rows, largest relative difference between 1 and 2 ranks {worst:.3g}")
    if worst > 1e-9:
        fail(f"the cell depends on the number of ranks: relative difference {worst:.3g} > 1e-9")
    print("PASS")


def bins(args):
    fresh_dir(args.workdir)
    radius, skin = 1.0e-4, 4.0e-6  # the deck's R and skin
    cutoff = 2.0 * radius + skin
    with open(DECK) as f:
        text = f.read()
    line = re.search(r"^fix +press slider aveforce NULL NULL (\S+)$", text, re.M)
    if not line or not line.group(1).startswith("$("):
        fail(f"the deck's fix press does not take the load per summit as a number: {line and line.group(0)}")
    variable_deck = os.path.join(args.workdir, "in.rve_rough_variable")
    with open(variable_deck, "w") as f:
        f.write(text.replace(line.group(0), "variable        per_asperity equal -v_load/count(slider)\n"
                                            "fix             press slider aveforce NULL NULL v_per_asperity"))
    extras = {"deck": {}, "lammps": {"binsize": cutoff / 2.0}}
    common = {"material": MATERIAL, "pressure": 2.0e7, "accel": 1.0, "nside": args.nside, "depth": args.depth,
              "seed": 11, "nout": 100}
    run_lammps_two_at_a_time(args, DECK, [(name, {**common, "out": f"{name}.dat", **extra})
                                          for name, extra in extras.items()])
    run_lammps_two_at_a_time(args, variable_deck, [("variable", {**common, "out": "variable.dat"})])
    runs = {}
    for name in list(extras) + ["variable"]:
        with open(os.path.join(args.workdir, f"log.{name}")) as f:
            runs[name] = f.read()
    sizes = {name: re.findall(r"binsize = (\S+), bins", log) for name, log in runs.items()}
    if not sizes["deck"] or any(abs(float(s) / (cutoff / 6.0) - 1.0) > 1e-9 for s in sizes["deck"]):
        fail(f"the deck's neighbour bins are {sizes['deck']}, not (2R + skin) / 6 = {cutoff / 6.0:g} m")
    with open(os.path.join(args.workdir, "deck.dat"), "rb") as f:
        deck_out = f.read()
    with open(os.path.join(args.workdir, "lammps.dat"), "rb") as f:
        lammps_out = f.read()
    if deck_out != lammps_out:
        fail("the output with the deck's bins differs from the output with LAMMPS's bins")
    with open(os.path.join(args.workdir, "variable.dat"), "rb") as f:
        if f.read() != deck_out:
            fail("the output with the load per summit as a number differs from the one with its variable")
    counts = {name: re.findall(r"^(?:Total # of neighbors|Neighbor list builds) = (\d+)", log, re.M)
              for name, log in runs.items()}
    if counts["deck"] != counts["lammps"] or not counts["deck"]:
        fail(f"neighbour counts and list builds differ: {counts}")
    print(f"bins {sizes['deck'][0]} m (deck) and {sizes['lammps'][0]} m (LAMMPS's), fix press with a number and with "
          f"its variable: {len(deck_out)} bytes of output identical; neighbours and list builds {counts['deck']}")
    print("PASS")


def caps(args):
    fresh_dir(args.workdir)
    common = {"material": MATERIAL, "pressure": 2.0e7, "accel": 1.0, "nside": args.nside, "depth": args.depth,
              "seed": 11, "nout": 100}
    run_lammps_two_at_a_time(args, DECK, [("spheres", {**common, "out": "spheres.dat", "caps": "no"}),
                                          ("caps", {**common, "out": "caps.dat", "caps": "yes"})])
    run_lammps(args, DECK, {**common, "out": "caps_np2.dat", "caps": "yes"}, log="log.caps_np2", np=2)
    tables = {name: numeric_table(os.path.join(args.workdir, f"{name}.dat")) for name in ("spheres", "caps", "caps_np2")}

    def worst(a, b):
        if len(a) != len(b):
            fail(f"{len(a)} rows against {len(b)}")
        return max(abs(x - y) / max(abs(x), abs(y), 1e-300) for ra, rb in zip(a, b) for x, y in zip(ra, rb))

    spheres_caps, ranks_caps = worst(tables["spheres"], tables["caps"]), worst(tables["caps"], tables["caps_np2"])
    logs = {}
    for name in ("spheres", "caps"):
        with open(os.path.join(args.workdir, f"log.{name}")) as f:
            logs[name] = f.read()
    neighbours = {n: int(re.findall(r"^Total # of neighbors = (\d+)", log, re.M)[-1]) for n, log in logs.items()}
    ghosts = {n: float(re.findall(r"^Nghost:\s+(\S+)", log, re.M)[-1]) for n, log in logs.items()}
    print(f"{len(tables['caps'])} rows: caps against spheres {spheres_caps:.3g}, caps at 1 and 2 ranks "
          f"{ranks_caps:.3g} (largest relative difference); neighbours {neighbours['spheres']} -> {neighbours['caps']}, "
          f"ghosts {ghosts['spheres']:g} -> {ghosts['caps']:g}")
    loaded = [tables[name][0] for name in ("spheres", "caps")]
    if loaded[0][-1] != loaded[1][-1] or worst([loaded[0]], [loaded[1]]) > 1e-9:
        fail(f"after loading caps and whole spheres differ: {loaded}")
    if spheres_caps > 1e-4:
        fail(f"caps and whole spheres differ by {spheres_caps:.3g} > 1e-4")
    if ranks_caps > 1e-4:
        fail(f"caps depend on the number of ranks: {ranks_caps:.3g} > 1e-4")
    if not (neighbours["caps"] <= neighbours["spheres"] and ghosts["caps"] * 5 <= ghosts["spheres"]):
        fail(f"caps do not shrink the ghost shell five-fold without a longer list: {neighbours}, {ghosts}")
    print("PASS")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["physics", "ranks", "bins", "caps"])
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--nside", type=int, default=None)
    parser.add_argument("--depth", type=float, default=5.0e-9)
    args = parser.parse_args()
    args.workdir = os.path.abspath(args.workdir)
    args.nside = args.nside or {"physics": 24, "ranks": 16, "bins": 12, "caps": 12}[args.mode]
    {"physics": physics, "ranks": ranks, "bins": bins, "caps": caps}[args.mode](args)


if __name__ == "__main__":
    main()
