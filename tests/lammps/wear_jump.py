#!/usr/bin/env python3
"""Cycle jumping of asperity wear (fix runin/wear/jump) on the rough-on-rough cell inputs/in.rve_rough (ctest).

  wear_jump.py archard     --lmp LMP --workdir DIR
  wear_jump.py ranks       --lmp LMP --workdir DIR [--mpiexec MPIEXEC]
  wear_jump.py convergence --lmp LMP --workdir DIR
  wear_jump.py max_change  --lmp LMP --workdir DIR
  wear_jump.py deep        --lmp LMP --workdir DIR [--max-change Z] [--rate T] [--depth H]
  wear_jump.py settled     --law LAW.json    (no LAMMPS: where a built law's Rq and mu_body settle, per pressure)

Steel1020 on Steel1020 (R 100 um, sigma 0.2 um per body) at 5 MPa, Archard k lowered to mild wear through the
pair's wear_scale (k = 7e-3 x accel). Asserted (doc/fix_runin_wear_jump.rst):
archard: k = 1e-5, 12^2 summits, to h = 1 nm: the sliding the jumps stand for is counted (equivalent distance
  > 20 x the distance run) and the worn volume of both bodies is Archard's at the equivalent distance,
  h + h_cf = 2 k p s / H within 1e-3; each jump adds at most max_depth to h + h_cf.
ranks: the same cell at 16^2 summits, 1 and 2 MPI ranks, every output value within 1e-9 relative (--controls: with
  the jump controlled by the state, max_change 8 nm and rate 2 %).
max_change: k = 1e-5, 12^2 summits, to h = 1 nm, the mean-depth cap max_depth 10 nm (it would move the summits in
  contact by hundreds of nm in one jump) and the state tolerance max_change 8 nm: no jump changes a summit's height by
  more than max_change, jumps are reduced to it with a WARNING naming it, and the worn volume stays Archard's at the
  equivalent distance (1e-3).
deep (study, ~15 min on 2 cores): the deep law's cell (inputs/homogenise_steel_mild_deep.toml: 24^2 summits at
  5 MPa, junction at the oxidised state, k = 1e-5) to h = 200 nm, seeds 11 and 12, with the jump controlled by the
  state (max_change Z and rate T) and with both halved: the seed means of mu_body and Rq on the law's depth grid
  (0, then 16 points geometric from 0.03 nm) differ by < 3 % RMS; Rq settles within the depth (its change over
  sigma / 10 of h below 1 % of the first sigma / 10's); mu_body (no run-in: Tabor's junction value from the first
  contacts) changes by < 1 % of its value per sigma / 10 past the first; worn depths Archard's to 1 %.
convergence (study, ~10 min): 24^2 summits to h = 5 nm, 2 seeds: halving max_depth (0.05 -> 0.025 nm), and k = 1e-6
  against 1e-5 (the mild-wear limit), change the seed means of mu_body(h) and Rq(h) by < 3 % RMS over h = 1-5 nm;
  worn depths Archard's to 1 %. The severe k = 7e-3 without jumps is printed beside them (not asserted).
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, numeric_table, run_lammps, run_lammps_two_at_a_time  # noqa: E402

DECK = os.path.join(SOURCE_DIR, "inputs", "in.rve_rough")
MATERIAL = os.path.join(SOURCE_DIR, "potentials", "Steel1020.runin")
K, H = 7.0e-3, 1.19e9           # Steel1020 on Steel1020 (potentials/Steel1020.runin)
PRESSURE = 5.0e6
COLUMNS = ("step", "s", "h", "h_cf", "mu", "rq", "rsk", "af", "mu_adh", "mu_plough", "contacts")


def cell_variables(k, nside, depth, max_depth, seed=11, out="cell.dat"):
    return {"material": MATERIAL, "pressure": PRESSURE, "accel": k / K, "nside": nside, "depth": depth,
            "seed": seed, "nout": 500, "nslide": 3000000, "jump": 1e12, "jump_every": 1000,
            "jump_max_depth": max_depth, "out": out}


def rows_of(args, out):
    path = os.path.join(args.workdir, out)
    if not os.path.exists(path):
        fail(f"{out}: no output (renamed from {out}.part at the end of the run)")
    return [dict(zip(COLUMNS, r)) for r in numeric_table(path)]


def archard(args):
    fresh_dir(args.workdir)
    k, max_depth = 1.0e-5, 1.0e-10
    log = run_lammps(args, DECK, cell_variables(k, 12, 1.0e-9, max_depth), log="log.cell")
    rows = rows_of(args, "cell.dat")
    last = rows[-1]
    run_steps = last["step"] - rows[0]["step"]
    run_distance = run_steps * 2.0e-8 * 1.0    # dt x speed of the deck
    if not last["s"] > 20.0 * run_distance:
        fail(f"equivalent sliding {last['s']:.4g} m is not > 20 x the {run_distance:.4g} m run: no jumps counted")
    archard_depth = 2.0 * k * PRESSURE * last["s"] / H
    ratio = (last["h"] + last["h_cf"]) / archard_depth
    if abs(ratio - 1.0) > 1e-3:
        fail(f"h + h_cf = {last['h'] + last['h_cf']:.6g} m, Archard at the equivalent distance {archard_depth:.6g} m "
             f"(ratio {ratio:.6f})")
    steps = [b["h"] + b["h_cf"] - a["h"] - a["h_cf"] for a, b in zip(rows, rows[1:])]
    per_row = 500 // 1000 + 1    # rows every 500 steps, jumps every 1000: at most one jump between rows
    if max(steps) > per_row * max_depth * 1.01:
        fail(f"h + h_cf grew by {max(steps):.4g} m between two rows, more than one jump of max_depth {max_depth:g} m")
    if "reduced from M" not in log:
        fail("no jump was reduced to max_depth: the test does not reach the tolerance")
    print(f"k = {k:g}: ran {run_distance:.4g} m, equivalent {last['s']:.6g} m ({last['s'] / run_distance:.0f}x); "
          f"h + h_cf = {last['h'] + last['h_cf']:.6g} m = {ratio:.6f} x Archard; largest step per row "
          f"{max(steps):.4g} m (max_depth {max_depth:g} m)")
    print("PASS")


def ranks(args):
    fresh_dir(args.workdir)
    runs = []
    for np in (1, 2):
        variables = cell_variables(1.0e-5, 16, 1.0e-9, 1.0e-10, out=f"np{np}.dat")
        if args.controls:    # the deep law's jump control: bisection on the largest summit change, rate on Rq
            variables.update(jump_max_change=8.0e-9, jump_rate=0.02)
        run_lammps(args, DECK, variables, log=f"log.np{np}", np=np)
        runs.append(rows_of(args, f"np{np}.dat"))
    one, two = runs
    if len(one) != len(two):
        fail(f"1 rank wrote {len(one)} rows, 2 ranks {len(two)}")
    worst = max(abs(a[key] - b[key]) / max(abs(a[key]), 1e-300) for a, b in zip(one, two) for key in COLUMNS)
    print(f"{len(one)} rows with jumps, largest relative difference between 1 and 2 ranks {worst:.3g}")
    if worst > 1e-9:
        fail(f"the jumped cell depends on the number of ranks: relative difference {worst:.3g} > 1e-9")
    print("PASS")


def max_change(args):
    """fix runin/wear/jump ... max_change Z bounds each jump by the largest change of one summit's height."""
    fresh_dir(args.workdir)
    k, max_depth, bound = 1.0e-5, 1.0e-8, 8.0e-9
    # the deck with the fix's largest per-summit change of the last jump (vector entry 5) as an extra column
    with open(DECK) as f:
        text = f.read()
    record = "v_mu_adh v_mu_plough v_contacts format"
    if record not in text:
        fail(f"{DECK}: the output line '{record}' was not found: update this test's copy of the deck")
    deck = os.path.join(args.workdir, "in.rve_rough_change")
    with open(deck, "w") as f:
        f.write(text.replace(record, "v_mu_adh v_mu_plough v_contacts f_jump[5] format"))
    variables = cell_variables(k, 12, 1.0e-9, max_depth)
    variables["jump_max_change"] = bound
    log = run_lammps(args, deck, variables, log="log.cell")
    path = os.path.join(args.workdir, "cell.dat")
    if not os.path.exists(path):
        fail("cell.dat: no output")
    rows = [dict(zip(COLUMNS + ("change",), r)) for r in numeric_table(path)]
    largest = max(r["change"] for r in rows)
    if largest > bound * (1.0 + 1e-9):
        fail(f"a jump changed a summit's height by {largest:.6g} m > max_change {bound:g} m")
    unbounded = [float(x) for x in re.findall(r"a summit's height would change by (\S+), the jump is kept within "
                                               r"max_change", log)]
    if not unbounded or max(unbounded) <= bound:
        fail("no jump was reduced to max_change (WARNING naming it): the test does not reach the tolerance")
    last = rows[-1]
    ratio = (last["h"] + last["h_cf"]) / (2.0 * k * PRESSURE * last["s"] / H)
    if abs(ratio - 1.0) > 1e-3:
        fail(f"h + h_cf = {last['h'] + last['h_cf']:.6g} m is {ratio:.6f} x Archard at the equivalent distance")
    print(f"largest change of a summit per jump {largest:.6g} m (max_change {bound:g} m; unbounded up to "
          f"{max(unbounded):.4g} m); h + h_cf = {ratio:.6f} x Archard at s = {last['s']:.5g} m")
    print("PASS")


def binned(rows, column, edges):
    """Means of `column` over rows with h in each [edge, next edge)."""
    out = []
    for a, b in zip(edges, edges[1:]):
        values = [r[column] for r in rows if a <= r["h"] < b]
        if not values:
            fail(f"no rows with h in [{a:g}, {b:g}) m")
        out.append(sum(values) / len(values))
    return out


def rms_relative(reference, other):
    """RMS over the bins of (other - reference) / reference."""
    return math.sqrt(sum(((y - x) / x) ** 2 for x, y in zip(reference, other)) / len(reference))


def run_all(args, cells):
    """Runs the cells two at a time (2 cores); returns {name: rows}."""
    run_lammps_two_at_a_time(args, DECK, list(cells.items()))
    return {name: rows_of(args, variables["out"]) for name, variables in cells.items()}


def convergence(args):
    """Seed means of mu_body(h) and Rq(h) in 0.5 nm bins of h = 1-5 nm for: k = 1e-5 at max_depth 0.05 nm (the
    deck's default) and 0.025 nm, k = 1e-6 at 0.05 nm, and the severe k = 7e-3 of the file without jumps."""
    fresh_dir(args.workdir)
    depth, seeds = 5.0e-9, (11, 12)
    setups = {"k1e-5": (1.0e-5, 5.0e-11), "k1e-5_half": (1.0e-5, 2.5e-11), "k1e-6": (1.0e-6, 5.0e-11),
              "severe": (K, None)}
    cells = {}
    for name, (k, max_depth) in setups.items():
        for seed in seeds:
            variables = cell_variables(k, 24, depth, max_depth or 1.0, seed=seed, out=f"{name}_s{seed}.dat")
            if max_depth is None:
                variables["jump"] = 1
            cells[f"{name}_s{seed}"] = variables
    runs = run_all(args, cells)
    for name, rows in runs.items():
        k = setups[name.rsplit("_s", 1)[0]][0]
        last = rows[-1]
        ratio = (last["h"] + last["h_cf"]) / (2.0 * k * PRESSURE * last["s"] / H)
        print(f"{name}: s = {last['s']:.5g} m to h = {last['h']:.4g} m, worn depth {ratio:.5f} x Archard k p s / H")
        if abs(ratio - 1.0) > 0.01:
            fail(f"{name}: worn depth {ratio:.5f} x Archard's k p s / H")
    edges = [1.0e-9 + i * 0.5e-9 for i in range(9)]
    means = {}
    for name in setups:
        for column in ("mu", "rq"):
            per_seed = [binned(runs[f"{name}_s{seed}"], column, edges) for seed in seeds]
            means[name, column] = [sum(v) / len(v) for v in zip(*per_seed)]
    print("h [nm] | " + " | ".join(f"{name} mu_body, Rq [nm]" for name in setups))
    for i, edge in enumerate(edges[:-1]):
        print(f"{1e9 * edge:.1f}-{1e9 * edges[i + 1]:.1f} | " +
              " | ".join(f"{means[name, 'mu'][i]:.4f}, {1e9 * means[name, 'rq'][i]:.1f}" for name in setups))
    failures = []
    for other, label in (("k1e-5_half", "max_depth halved"), ("k1e-6", "k = 1e-6")):
        for column in ("mu", "rq"):
            rms = rms_relative(means["k1e-5", column], means[other, column])
            print(f"{label}: {column}(h) RMS difference {100 * rms:.2f} % over h = 1-5 nm")
            if rms > 0.03:
                failures.append(f"{label}: {column}(h) differs by {100 * rms:.2f} % RMS > 3 %")
    for column in ("mu", "rq"):
        rms = rms_relative(means["k1e-5", column], means["severe", column])
        print(f"severe k = 7e-3 against k = 1e-5: {column}(h) RMS difference {100 * rms:.1f} % over h = 1-5 nm")
    if failures:
        fail("; ".join(failures))
    print("PASS")


def law_grid(depth, points=16, first=3.0e-11):
    """The deep law's depth grid: 0, then `points` depths geometric from `first` to `depth`."""
    return [0.0] + [first * (depth / first) ** (i / (points - 1)) for i in range(points)]


def on_grid(rows, column, grid):
    """Rq linear in h between rows; mu_body the mean of the rows between the neighbouring grid depths (sliding rows
    only; linear in h as Rq where a jump left none there), close to how runin homogenise resamples a sample."""
    rows = [r for r in rows if r["s"] > 0.0]
    out = []
    for i, h in enumerate(grid):
        low = grid[i - 1] if i > 0 else 0.0
        high = grid[i + 1] if i + 1 < len(grid) else h
        values = [r[column] for r in rows if low <= r["h"] <= high]
        if column == "rq" or not values:    # mu_body without rows there (a jump over it): linear as Rq
            above = next(j for j, r in enumerate(rows) if r["h"] >= h)
            if above == 0:
                out.append(rows[0][column])
                continue
            a, b = rows[above - 1], rows[above]
            out.append(a[column] + (b[column] - a[column]) * (h - a["h"]) / (b["h"] - a["h"]))
        else:
            out.append(sum(values) / len(values))
    return out


def window_curve(rows, column, edges):
    """Rq linear in h at each edge; mu_body the mean of the sliding rows within half a window of it."""
    if column == "rq":
        return on_grid(rows, "rq", edges)
    half = 0.5 * (edges[1] - edges[0])
    out = []
    for e in edges:
        values = [r[column] for r in rows if r["s"] > 0.0 and abs(r["h"] - e) <= half]
        if not values:
            fail(f"no rows with h within {half:g} m of {e:g} m")
        out.append(sum(values) / len(values))
    return out


def settled_depth(rows_per_seed, column, window):
    """The first h (a multiple of window) from which the seed-mean column changes over one window by less than 1 % of
    its change over the first window; None if it does not within the rows."""
    top = min(rows[-1]["h"] for rows in rows_per_seed)
    edges = [k * window for k in range(int(top / window) + 1)]
    curve = [sum(v) / len(v) for v in zip(*(window_curve(rows, column, edges) for rows in rows_per_seed))]
    first = abs(curve[1] - curve[0])
    for k in range(1, len(curve) - 1):
        if abs(curve[k + 1] - curve[k]) < 0.01 * first:
            return edges[k], first, curve
    return None, first, curve


def deep(args):
    """The deep law's jump control (max_change, rate) against both halved, 5 MPa, seeds 11 and 12."""
    fresh_dir(args.workdir)
    k, seeds, sigma = 1.0e-5, (11, 12), 2.0e-7
    setups = {"deep": (args.max_change, args.rate), "half": (0.5 * args.max_change, 0.5 * args.rate)}
    cells = {}
    for name, (change, rate) in setups.items():
        for seed in seeds:
            v = cell_variables(k, 24, args.depth, 5.0e-11, seed=seed, out=f"{name}_s{seed}.dat")
            v.update({"nout": 200, "nslide": 5000000, "friction": "junction", "interface": "oxidised",
                      "jump_max_change": change, "jump_rate": rate})
            cells[f"{name}_s{seed}"] = v
    analyse_deep(args, run_all(args, cells), setups, seeds)


def analyse_deep(args, runs, setups, seeds):
    k, sigma = 1.0e-5, 2.0e-7
    for name, rows in runs.items():
        last = rows[-1]
        ratio = (last["h"] + last["h_cf"]) / (2.0 * k * PRESSURE * last["s"] / H)
        print(f"{name}: {int(last['step'] - rows[0]['step'])} sliding steps to h = {1e9 * last['h']:.4g} nm, "
              f"s = {last['s']:.5g} m, worn depth {ratio:.5f} x Archard k p s / H")
        if abs(ratio - 1.0) > 0.01:
            fail(f"{name}: worn depth {ratio:.5f} x Archard's k p s / H")
    grid = law_grid(args.depth)
    means = {}
    for name in setups:
        for column in ("mu", "rq"):
            per_seed = [on_grid(runs[f"{name}_s{seed}"], column, grid) for seed in seeds]
            means[name, column] = [sum(v) / len(v) for v in zip(*per_seed)]
    print("h [nm] | deep mu_body, Rq [nm] | half mu_body, Rq [nm]")
    for i, h in enumerate(grid):
        print(f"{1e9 * h:.4g} | " + " | ".join(f"{means[name, 'mu'][i]:.4f}, {1e9 * means[name, 'rq'][i]:.1f}"
                                                for name in setups))
    failures = []
    for column in ("mu", "rq"):
        rms = rms_relative(means["deep", column], means["half", column])
        print(f"tolerances halved: {column}(h) RMS difference {100 * rms:.2f} % over the law's grid")
        if rms > 0.03:
            failures.append(f"tolerances halved: {column}(h) differs by {100 * rms:.2f} % RMS > 3 %")
    depth, first, _ = settled_depth([runs[f"deep_s{seed}"] for seed in seeds], "rq", 0.1 * sigma)
    if depth is None:
        failures.append(f"Rq has not settled by h = {1e9 * args.depth:g} nm")
    else:
        print(f"rq settled from h = {1e9 * depth:.0f} nm (change over sigma/10 below 1 % of the first "
              f"sigma/10's, {first:.4g})")
    # mu_body of the junction cell has no run-in to settle: Tabor's value from the first contacts, its change per
    # sigma/10 past the first is at the rows' noise; it must stay within 1 % of its value
    depth, first, curve = settled_depth([runs[f"deep_s{seed}"] for seed in seeds], "mu", 0.1 * sigma)
    later = max(abs(b - a) for a, b in zip(curve[1:], curve[2:]))
    print(f"mu_body: change over the first sigma/10 {first:.4g}, largest later {later:.4g} "
          f"({100 * later / curve[-1]:.3f} % of its value), "
          + (f"settled from h = {1e9 * depth:.0f} nm" if depth is not None else "never below 1 % of the first"))
    if later > 0.01 * curve[-1]:
        failures.append(f"mu_body changes by {later:.4g} over sigma/10 past the first, > 1 % of its value")
    if failures:
        fail("; ".join(failures))
    print("PASS")


def settled(args):
    """Per pressure of a built state law: the depth from which the seed-mean Rq and mu_body change over sigma/10 of h
    by less than 1 % of their change over the first sigma/10 (linear in h between the law's points), and the
    range of mu_body and of Rq. mu_body without a run-in (its later changes within 1 % of its value) counts as
    settled, as in the deep study."""
    import json
    with open(args.law) as f:
        law = json.load(f)
    sigma, grid = law["surface"]["sigma"], law["worn_depth"]
    window = 0.1 * sigma
    edges = [k * window for k in range(int(grid[-1] / window + 1e-9) + 1)]

    def at(values, h):
        j = next(j for j in range(1, len(grid)) if grid[j] >= h)
        return values[j - 1] + (values[j] - values[j - 1]) * (h - grid[j - 1]) / (grid[j] - grid[j - 1])

    if len(edges) < 3:
        print(f"depth axis to {1e9 * grid[-1]:.4g} nm, shorter than two windows of sigma/10 = {1e9 * window:.4g} nm: "
              f"not settled")
        return
    unsettled = []
    for i, p in enumerate(law["pressure"]):
        line = [f"p = {p / 1e6:.3g} MPa:"]
        for name in ("rq", "mu_body"):
            values = law["fields"][name]["mean"][i]
            curve = [at(values, e) for e in edges]
            first = abs(curve[1] - curve[0])
            depth = next((edges[k] for k in range(1, len(curve) - 1)
                          if abs(curve[k + 1] - curve[k]) < 0.01 * first), None)
            scale = 1e9 if name == "rq" else 1.0
            line.append(f"{name} {scale * values[0]:.4g} -> {scale * values[-1]:.4g}, settled from "
                        + (f"h = {1e9 * depth:.0f} nm" if depth is not None else "- (not settled)"))
            if name == "mu_body":    # no run-in (junction): its later changes against its value, as the study
                later = max(abs(b - a) for a, b in zip(curve[1:], curve[2:]))
                line[-1] += f" (largest change per sigma/10 past the first {100 * later / curve[-1]:.3f} % of it)"
                if depth is None and later <= 0.01 * curve[-1]:
                    continue
            if depth is None:
                unsettled.append(f"{name} at {p:g} Pa")
        print("; ".join(line))
    print(f"depth axis to {1e9 * grid[-1]:.4g} nm = {grid[-1] / sigma:.3g} sigma; windows of sigma/10 = "
          f"{1e9 * window:.4g} nm")
    if unsettled:
        print("not settled: " + ", ".join(unsettled))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=["archard", "ranks", "convergence", "max_change", "deep", "settled"])
    parser.add_argument("--lmp")
    parser.add_argument("--workdir")
    parser.add_argument("--law", help="settled: a state law (JSON)")
    parser.add_argument("--controls", action="store_true", help="ranks: with jump_max_change and jump_rate")
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--max-change", type=float, default=3.2e-8, help="deep: max_change Z [m]")
    parser.add_argument("--rate", type=float, default=0.01, help="deep: rate tolerance T")
    parser.add_argument("--depth", type=float, default=2.0e-7, help="deep: depth [m]")
    args = parser.parse_args()
    if args.mode == "settled":
        if not args.law:
            parser.error("settled needs --law")
    elif not (args.lmp and args.workdir):
        parser.error(f"{args.mode} needs --lmp and --workdir")
    else:
        args.workdir = os.path.abspath(args.workdir)
    {"archard": archard, "ranks": ranks, "convergence": convergence, "max_change": max_change,
     "deep": deep, "settled": settled}[args.mode](args)


if __name__ == "__main__":
    main()
