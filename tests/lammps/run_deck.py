#!/usr/bin/env python3
"""Deck-driven LAMMPS tests for RunIn (run by ctest; standard library only).

  run_deck.py slider  --lmp LMP --mpiexec MPIEXEC --np N --deck DECK --workdir DIR
  run_deck.py archard --lmp LMP --deck DECK --workdir DIR
  run_deck.py compare DIR_A DIR_B
  run_deck.py roughness --lmp LMP --mpiexec MPIEXEC --np N --deck DECK --workdir DIR
  run_deck.py expect-error --lmp LMP --deck DECK --workdir DIR --pattern REGEX
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def mpi_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    return env


def fresh_dir(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)


def thermo_blocks(log_text):
    """Each run's thermo table as a list of dicts keyed by the header names."""
    blocks, header, rows = [], None, []
    for line in log_text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header, rows = words, []
        elif header and line.startswith("Loop time"):
            blocks.append(rows)
            header = None
        elif header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                pass
    return blocks


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run_slider(args):
    fresh_dir(args.workdir)
    command = [args.mpiexec, "-np", str(args.np), args.lmp, "-in", os.path.join(SOURCE_DIR, args.deck),
               "-var", "coeffs", os.path.join(SOURCE_DIR, "potentials", "CuAl.runin"),
               "-var", "nsettle", "200", "-var", "nslide", "100", "-var", "thermo_every", "10",
               "-log", "log.lammps", "-screen", "none"]
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
    log = open(os.path.join(args.workdir, "log.lammps")).read() if os.path.exists(
        os.path.join(args.workdir, "log.lammps")) else ""
    if result.returncode != 0:
        fail(f"lmp_runin exited with {result.returncode}\n{result.stdout}\n{result.stderr}\n{log[-2000:]}")
    blocks = thermo_blocks(log)
    if len(blocks) != 2:
        fail(f"expected the settle and slide thermo tables, found {len(blocks)}")
    sliding = blocks[1]
    for row in blocks[0] + sliding:
        for name, value in row.items():
            if not math.isfinite(value):
                fail(f"non-finite {name} at step {row['Step']}")
    contacts = [row["c_fric[4]"] for row in sliding]
    wear = [row["c_fric[5]"] for row in sliding]
    mu = [row["c_fric[3]"] for row in sliding]
    if min(contacts) <= 0:
        fail(f"no contacts while sliding: {contacts}")
    if wear[-1] <= 0:
        fail(f"no wear after sliding: {wear}")
    if any(b < a for a, b in zip(wear, wear[1:])) or wear[-1] <= wear[1]:
        fail(f"wear volume must grow while sliding: {wear}")
    if not 0.0 < max(mu) <= 0.95 + 1e-12:
        fail(f"mu_eff outside (0, mu_s]: {mu}")
    with open(os.path.join(args.workdir, "sliding.tsv"), "w") as out:
        for row in sliding:
            out.write(f"{int(row['Step'])}\t{row['c_fric[3]']!r}\t{row['c_fric[5]']!r}\t{row['c_rough[2]']!r}\n")
    print(f"ok: {len(sliding)} sliding rows, contacts {min(contacts):.0f}-{max(contacts):.0f}, "
          f"mu_eff {mu[-1]:.6g}, wear {wear[-1]:.6g} m^3")


def archard_budget(args):
    """Steady sliding: total wear must follow Archard, V = k W s / H_soft, for the deck's load."""
    fresh_dir(args.workdir)
    nslide, speed, dt, load = 4000, 2.0, 1.0e-10, 5.0e-2
    k, hardness_al = 1.0e-3, 0.245e9    # potentials/CuAl.runin: pair Cu Al k, material Al H
    command = [args.lmp, "-in", os.path.join(SOURCE_DIR, args.deck),
               "-var", "coeffs", os.path.join(SOURCE_DIR, "potentials", "CuAl.runin"),
               "-var", "nslide", str(nslide), "-var", "thermo_every", "1000", "-log", "log.lammps",
               "-screen", "none"]
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"lmp_runin exited with {result.returncode}: {result.stderr[-2000:]}")
    sliding = thermo_blocks(open(os.path.join(args.workdir, "log.lammps")).read())[1]
    worn = sliding[-1]["c_fric[5]"] - sliding[0]["c_fric[5]"]
    expected = k * load * nslide * dt * speed / hardness_al
    ratio = worn / expected
    # below 1: sliding distance lost to the stick phase; above 1: sum F_n exceeds the load on tilted contacts
    if not 0.9 <= ratio <= 1.05:
        fail(f"wear {worn:.4e} m^3 vs Archard k W s / H = {expected:.4e} m^3 (ratio {ratio:.4f}, want 0.9-1.05)")
    print(f"ok: wear {worn:.4e} m^3, Archard {expected:.4e} m^3, ratio {ratio:.4f}")


def compare(args):
    def load(directory):
        with open(os.path.join(directory, "sliding.tsv")) as f:
            return [tuple(float(x) for x in line.split()) for line in f]

    a, b = load(args.dir_a), load(args.dir_b)
    if len(a) != len(b) or len(a) < 10:
        fail(f"row counts differ or too few: {len(a)} vs {len(b)}")
    worst = 0.0
    for (step_a, *values_a), (step_b, *values_b) in zip(a, b):
        if step_a != step_b:
            fail(f"steps differ: {step_a} vs {step_b}")
        for x, y in zip(values_a, values_b):
            scale = max(abs(x), abs(y))
            if scale > 0:
                worst = max(worst, abs(x - y) / scale)
    if worst > 1e-8:
        fail(f"mu_eff / wear / Rq differ between rank counts by {worst:.3e} relative (limit 1e-8)")
    print(f"ok: {len(a)} rows agree, worst relative difference {worst:.3e}")


def deck_roughness_closed_form(deck_text):
    """Closed-form statistics of every compute runin/roughness in a deck of literal atoms.

    Reads 'create_atoms T single X Y Z', 'set atom ID diameter D', 'group NAME type T' and
    'compute ID GROUP runin/roughness [bearing d...] [side up|down] [mean z]'. Returns
    {compute id: (statistics list, {atom id: height above the mean plane})}."""
    atoms, groups, computes = [], {}, []
    for line in deck_text.splitlines():
        words = line.split("#")[0].split()
        if len(words) >= 6 and words[0] == "create_atoms" and words[2] == "single":
            atoms.append({"type": int(words[1]), "z": float(words[5]), "radius": 0.5})
        elif len(words) == 5 and words[0] == "set" and words[1] == "atom" and words[3] == "diameter":
            atoms[int(words[2]) - 1]["radius"] = 0.5 * float(words[4])
        elif len(words) == 4 and words[0] == "group" and words[2] == "type":
            groups[words[1]] = int(words[3])
        elif len(words) >= 4 and words[0] == "compute" and words[3] == "runin/roughness":
            depths, sign, rest = [], 1.0, words[4:]
            i = 0
            while i < len(rest):
                if rest[i] == "bearing":
                    i += 1
                    while i < len(rest) and re.fullmatch(r"[-+0-9.eE]+", rest[i]):
                        depths.append(float(rest[i]))
                        i += 1
                else:
                    if rest[i] == "side":
                        sign = -1.0 if rest[i + 1] == "down" else 1.0
                    i += 2
            computes.append((words[1], words[2], depths, sign))
    result = {}
    for name, group, depths, sign in computes:
        members = [(k + 1, sign * a["z"] + a["radius"]) for k, a in enumerate(atoms)
                   if group == "all" or a["type"] == groups[group]]
        h = [v for _, v in members]
        n = len(h)
        mean = sum(h) / n
        d = [v - mean for v in h]
        m2, m3, m4 = (sum(x ** p for x in d) / n for p in (2, 3, 4))
        ra = sum(abs(x) for x in d) / n
        rp, rv = max(h) - mean, mean - min(h)
        stats = [ra, math.sqrt(m2), m3 / m2 ** 1.5, m4 / m2 ** 2, rp, rv, rp + rv]
        stats += [sum(1 for v in h if v >= max(h) - depth) / n for depth in depths]
        result[name] = (stats, {atom_id: v - mean for atom_id, v in members})
    return result


def roughness(args):
    """compute runin/roughness: every global statistic and per-atom height vs the closed form."""
    fresh_dir(args.workdir)
    deck = os.path.join(SOURCE_DIR, args.deck)
    command = [args.mpiexec, "-np", str(args.np), args.lmp, "-in", deck, "-log", "log.lammps", "-screen", "none"]
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
    log_path = os.path.join(args.workdir, "log.lammps")
    log = open(log_path).read() if os.path.exists(log_path) else ""
    if result.returncode != 0:
        fail(f"lmp_runin exited with {result.returncode}\n{result.stdout}\n{result.stderr}\n{log[-2000:]}")
    if args.np > 1 and f"with {args.np} MPI tasks" not in log:
        fail(f"the run did not use {args.np} MPI ranks")
    expected = deck_roughness_closed_form(open(deck).read())
    row = thermo_blocks(log)[-1][-1]
    worst, checked = 0.0, 0
    for name, (stats, _) in expected.items():
        for k, value in enumerate(stats, start=1):
            got = row[f"c_{name}[{k}]"]
            error = abs(got - value) / abs(value) if value != 0 else abs(got)
            if error > 1e-10:
                fail(f"c_{name}[{k}] = {got!r}, closed form {value!r} (relative error {error:.3e} > 1e-10)")
            worst, checked = max(worst, error), checked + 1
    # per-atom summit heights above the mean plane, from the dump
    lines = open(os.path.join(args.workdir, "heights.dump")).read().splitlines()
    columns = lines[lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))].split()[2:]
    body = [dict(zip(columns, map(float, l.split()))) for l in lines[lines.index(
        next(l for l in lines if l.startswith("ITEM: ATOMS"))) + 1:]]
    for name, (stats, heights) in expected.items():
        scale = max(abs(v) for v in heights.values())
        for atom in body:
            want = heights.get(int(atom["id"]), 0.0)
            if abs(atom[f"c_{name}"] - want) > 1e-10 * scale:
                fail(f"atom {int(atom['id'])}: c_{name} = {atom[f'c_{name}']!r}, closed form {want!r}")
            checked += 1
    print(f"ok: {checked} values on {args.np} rank(s) match the closed form, worst global relative error {worst:.3e}")


def expect_error(args):
    fresh_dir(args.workdir)
    result = subprocess.run([args.lmp, "-in", os.path.join(SOURCE_DIR, args.deck), "-log", "none"],
                            cwd=args.workdir, env=mpi_env(), capture_output=True, text=True, timeout=60)
    output = result.stdout + result.stderr
    if result.returncode == 0:
        fail("the deck was accepted; expected an ERROR")
    if result.returncode < 0 or result.returncode >= 128:
        fail(f"crashed with signal/status {result.returncode}\n{output}")
    errors = [line for line in output.splitlines() if line.startswith("ERROR")]
    if len(errors) != 1:
        fail(f"expected exactly one ERROR line, got {errors}\n{output}")
    if not re.search(args.pattern, errors[0]):
        fail(f"ERROR line does not name the problem ({args.pattern!r}): {errors[0]}")
    print("ok: " + errors[0])


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("slider")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("archard")
    for name in ("--lmp", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p = sub.add_parser("compare")
    p.add_argument("dir_a")
    p.add_argument("dir_b")
    p = sub.add_parser("roughness")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("expect-error")
    for name in ("--lmp", "--deck", "--workdir", "--pattern"):
        p.add_argument(name, required=True)
    args = parser.parse_args()
    {"slider": run_slider, "archard": archard_budget, "compare": compare, "roughness": roughness,
     "expect-error": expect_error}[args.command](args)


if __name__ == "__main__":
    main()
