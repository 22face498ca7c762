#!/usr/bin/env python3
"""Cross-host tests of the LIGGGHTS host (ctest labels liggghts, lammps; standard library only).

  compare_hosts.py scene   --liggghts LG --lmp LMP --mpiexec MPIEXEC --np N --scene NAME --workdir DIR [--set V=X]
  compare_hosts.py bad     --liggghts LG --workdir DIR --pattern REGEX [--registry HELPER] -- <deck lines>
  compare_hosts.py restart --liggghts LG --mpiexec MPIEXEC --np N --deck DECK --workdir DIR
  compare_hosts.py warning --liggghts LG --mpiexec MPIEXEC --np N --deck DECK --workdir DIR --pattern REGEX
                           [--count K] [--set V=X]
  compare_hosts.py error   --liggghts LG --mpiexec MPIEXEC --np N --deck DECK --workdir DIR --pattern REGEX [--set V=X]

scene: runs the scene's LAMMPS deck (inputs/) with lmp_runin and its LIGGGHTS deck (tests/liggghts/decks/)
with liggghts_runin, both at N ranks with the same variables, and compares every thermo column both print
(the mu, wear and roughness entries of compute runin/friction and runin/roughness, the forces on the counter-body)
row by row: relative difference <= 1e-10 (absolute below 1e-300 for zeros).
The scene single_pair also checks the pair's single() (compute group/group) against its force loop (compute
runin/friction [1]) in every row, loading and unloading.
bad: one deck with a wrong style argument must stop with exit 1 and one ERROR line matching REGEX, no crash
({registry:KIND} in REGEX: the registry's names of that kind, printed by HELPER, run_deck.with_registry_names).
warning: a LIGGGHTS deck runs to the end and prints exactly K (default 1) WARNING lines matching REGEX.
error: a LIGGGHTS deck at N ranks stops with exit 1 and one ERROR line matching REGEX, no crash, nothing non-finite
printed before it.
restart: a LIGGGHTS restart deck (tests/liggghts/decks/in.restart_*) run as mode 0 (N/2 + N/2 steps), mode 1
(N/2 steps, write_restart) and mode 2 (read_restart, N/2 steps): the final per-atom dumps of modes 0 and 2 and
the thermo rows of their last run must be identical (bit for bit: every digit of %.17g), and the run must have
contacts and wear (else the check would be empty).
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lammps"))
from run_deck import mpi_env, with_registry_names  # noqa: E402  (the LAMMPS tier's MPI environment; registry names)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOLERANCE = 1e-10

SCENES = {
    # LAMMPS deck, LIGGGHTS deck, variables (shortened runs), text edits applied to both decks (copied into the
    # work directory)
    "rough_slider": ("inputs/in.rough_slider", "tests/liggghts/decks/in.rough_slider",
                     {"nsettle": 600, "nslide": 1400, "thermo_every": 100}, ()),
    # a 200 um box (10 x 10 base summits): nearly every worn summit is also a ghost (periodic image or the other
    # rank's), so the worn geometry sent to ghosts enters the forces (without that send it fails at 2 ranks)
    "rough_slider_small": ("inputs/in.rough_slider", "tests/liggghts/decks/in.rough_slider",
                           {"nside": 10, "nsettle": 600, "nslide": 1400, "thermo_every": 100}, ()),
    # wear no: plastic flattening alone changes the summits (no Archard wear on either host)
    "rough_slider_nowear": ("inputs/in.rough_slider", "tests/liggghts/decks/in.rough_slider",
                            {"nsettle": 600, "nslide": 1400, "thermo_every": 100, "wear": "no"}, ()),
    # rough on flat (fix runin/wall, servo-held load, wear, re-stick after a dwell); the deck prints 10 digits:
    # every digit for the comparison
    "runin_wall": ("inputs/in.runin_wall", "tests/liggghts/decks/in.runin_wall",
                   {"nload": 300, "nslide": 1500, "nhold": 200, "nresume": 500, "thermo_every": 100},
                   (("thermo_modify   format float %.10g", "thermo_modify   format float %.17g"),)),
    # two summits pressed, slid and lifted: single() through compute group/group (c_pair) next to the loop's force
    "single_pair": ("tests/liggghts/decks/in.single_pair.lammps", "tests/liggghts/decks/in.single_pair",
                    {"nrun": 200, "nlift": 120, "thermo_every": 20}, ()),
}
# columns the LAMMPS deck of a scene must print (else the comparison would be empty)
NEEDED = {"single_pair": {"c_pair", "c_pair[1]", "c_pair[2]", "c_pair[3]", "c_fric[1]"}}
NEEDED_DEFAULT = {"c_fric[3]", "c_fric[5]", "c_fric[16]", "c_rough[2]", "c_rough[3]"}


def run(command, workdir, log, np, mpiexec, variables, extra=()):
    command = list(command) + ["-in", "DECK", "-log", log, "-screen", "none"] + list(extra)
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    if np > 1:
        command = [mpiexec, "-np", str(np)] + command
    return command


def used_ranks(text):
    """The number of MPI ranks of the processor grid a log reports (0: none found)."""
    grid = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", text)
    return int(grid.group(1)) * int(grid.group(2)) * int(grid.group(3)) if grid else 0


def thermo_blocks(text):
    """Each run's thermo table as a list of dicts; LIGGGHTS drops the c_/v_/f_ prefixes of the header
    names (and cuts them at 8 characters), so rows are keyed by position against the LAMMPS names."""
    blocks, header, rows = [], None, []
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header, rows = words, []
            continue
        if header is not None:
            if words and re.fullmatch(r"-?\d+", words[0]) and len(words) == len(header):
                rows.append(words)
                continue
            if rows:
                blocks.append((header, rows))
            header = None
    return blocks


def strip(name):
    return re.sub(r"^[cvf]_", "", name)[:8]


def scene(args):
    lammps_deck, liggghts_deck, variables, edits = SCENES[args.scene]
    variables = dict(variables)
    for item in args.set or []:
        name, _, value = item.partition("=")
        variables[name] = value
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    os.symlink(os.path.join(SOURCE_DIR, "potentials"), os.path.join(args.workdir, "potentials"))
    logs = {}
    for host, exe, deck, extra in (("lammps", args.lmp, lammps_deck, ()),
                                   ("liggghts", args.liggghts, liggghts_deck, ("-st",))):
        command = run([exe], args.workdir, f"log.{host}", args.np, args.mpiexec, variables, extra)
        deck_path = os.path.join(SOURCE_DIR, deck)
        if edits:
            text = open(deck_path).read()
            for old, new in edits:
                if text.count(old) != 1:
                    fail(f"{deck}: expected one {old!r}")
                text = text.replace(old, new)
            deck_path = os.path.join(args.workdir, f"in.{host}")
            with open(deck_path, "w") as f:
                f.write(text)
        command[command.index("DECK")] = deck_path
        result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
        log = os.path.join(args.workdir, f"log.{host}")
        text = open(log).read() if os.path.exists(log) else ""
        if result.returncode != 0:
            fail(f"{host}: {' '.join(command)} exited with {result.returncode}\n{result.stdout[-1500:]}\n"
                 f"{result.stderr[-1500:]}\n{text[-1500:]}")
        if used_ranks(text) != args.np and args.np > 1:
            fail(f"{host}: the run did not use {args.np} MPI ranks")
        logs[host] = thermo_blocks(text)
    if len(logs["lammps"]) != len(logs["liggghts"]):
        fail(f"thermo tables: LAMMPS {len(logs['lammps'])}, LIGGGHTS {len(logs['liggghts'])}")
    worst, compared = 0.0, 0
    for (lh, lrows), (gh, grows) in zip(logs["lammps"], logs["liggghts"]):
        gindex = {strip(name): k for k, name in enumerate(gh)}
        columns = [(name, k, gindex[strip(name)]) for k, name in enumerate(lh)
                   if strip(name) in gindex and name not in ("Step",)]
        if len(lrows) != len(grows):
            fail(f"rows: LAMMPS {len(lrows)}, LIGGGHTS {len(grows)}")
        for lrow, grow in zip(lrows, grows):
            if lrow[0] != grow[0]:
                fail(f"steps differ: {lrow[0]} vs {grow[0]}")
            for name, kl, kg in columns:
                a, b = float(lrow[kl]), float(grow[kg])
                scale = max(abs(a), abs(b))
                rel = abs(a - b) / scale if scale > 1e-300 else 0.0
                compared += 1
                if rel > worst:
                    worst = rel
                if rel > TOLERANCE:
                    fail(f"step {lrow[0]} {name}: LAMMPS {a!r}, LIGGGHTS {b!r} (relative {rel:.3g} > {TOLERANCE})")
    needed = NEEDED.get(args.scene, NEEDED_DEFAULT)
    seen = {name for header, _ in logs["lammps"] for name in header}
    if not needed <= seen:
        fail(f"the LAMMPS deck does not print {sorted(needed - seen)}")
    print(f"{args.scene} at {args.np} rank(s): {compared} values in {len(logs['lammps'])} thermo tables, worst "
          f"relative difference {worst:.3g} (tolerance {TOLERANCE})")
    if args.scene == "single_pair":
        single_against_loop(logs)


def single_against_loop(logs):
    """single() (compute group/group: the normal force on the upper summit, F_n along x_2 - x_1) against the force
    loop (compute runin/friction [1], F_n) on both hosts, in the pressing and the lifting run."""
    for host, tables in logs.items():
        if len(tables) != 2:
            fail(f"{host}: expected the pressing and the lifting thermo tables, found {len(tables)}")
        for run, (header, rows) in zip(("pressing", "lifting"), tables):
            column = {strip(name): k for k, name in enumerate(header)}
            touching = 0
            for row in rows:
                force = [float(row[column[f"pair[{k}]"]]) for k in (1, 2, 3)]
                loop = float(row[column["fric[1]"]])
                distance = [float(row[column[name]]) for name in ("dx", "dy", "dz")]
                size = math.sqrt(sum(f * f for f in force))
                along = sum(f * d for f, d in zip(force, distance)) / math.sqrt(sum(d * d for d in distance))
                if abs(size - loop) > 1e-12 * loop or abs(along - size) > 1e-12 * max(size, 1e-300):
                    fail(f"{host}, {run}, step {row[0]}: single() gives the normal force {force} (|F| {size!r}, "
                         f"along x_2 - x_1 {along!r}), the force loop {loop!r}")
                touching += loop > 0.0
            if touching < len(rows) // 2:
                fail(f"{host}, {run}: the summits press in only {touching} of {len(rows)} rows (empty check)")
    print("single() (compute group/group) = the force loop's normal force in every row on both hosts, pressing and "
          "lifting")


def warning(args):
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    os.symlink(os.path.join(SOURCE_DIR, "potentials"), os.path.join(args.workdir, "potentials"))
    variables = dict(item.partition("=")[::2] for item in args.set or [])
    command = run([args.liggghts], args.workdir, "log.liggghts", args.np, args.mpiexec, variables, ("-st",))
    command[command.index("DECK")] = os.path.join(SOURCE_DIR, args.deck)
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
    log = os.path.join(args.workdir, "log.liggghts")
    text = open(log).read() if os.path.exists(log) else ""
    if result.returncode != 0:
        fail(f"{' '.join(command)} exited with {result.returncode}\n{result.stderr[-1500:]}\n{text[-1500:]}")
    if args.np > 1 and used_ranks(text) != args.np:
        fail(f"the run did not use {args.np} MPI ranks")
    matching = [line for line in text.splitlines() if line.startswith("WARNING") and re.search(args.pattern, line)]
    if len(matching) != args.count:
        fail(f"expected {args.count} WARNING line(s) matching {args.pattern!r}, got {matching}")
    values = [word for _, rows in thermo_blocks(text) for row in rows for word in row]
    if any(re.fullmatch(r"[-+]?(nan|inf)", word, re.I) for word in values):
        fail("a thermo value is not finite")
    print(f"ok: {matching[0]}")


def error(args):
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    os.symlink(os.path.join(SOURCE_DIR, "potentials"), os.path.join(args.workdir, "potentials"))
    command = [args.liggghts, "-st", "-in", os.path.join(SOURCE_DIR, args.deck), "-log", "none"]
    for item in args.set or []:
        name, _, value = item.partition("=")
        command += ["-var", name, value]
    if args.np > 1:
        command = [args.mpiexec, "-np", str(args.np)] + command
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True,
                            errors="replace", timeout=120)
    out = result.stdout + result.stderr
    error = one_error(result, out, args.pattern, f"{' '.join(command)}: ")
    if args.np > 1 and used_ranks(out) != args.np:
        fail(f"the run did not use {args.np} MPI ranks")
    printed = [line for line in out.splitlines() if not line.startswith(("ERROR", "WARNING"))]
    if any(re.search(r"(?<![\w.])[-+]?(nan|inf)(?![\w.])", line, re.I) for line in printed):
        fail("a non-finite value was printed before the ERROR")
    print(f"ok: {error}")


def one_error(result, out, pattern, prefix=""):
    """A run that must stop with exit 1, exactly one ERROR line matching `pattern` and no crash: that line."""
    errors = [line for line in out.splitlines() if line.startswith("ERROR")]
    if result.returncode != 1:
        fail(f"{prefix}exit code {result.returncode} (expected 1)\n{out[-2000:]}")
    if len(errors) != 1 or not re.search(pattern, errors[0]):
        fail(f"expected one ERROR line matching '{pattern}', got {errors}\n{out[-2000:]}")
    if re.search(r"Segmentation|signal|core dumped|MPI_ABORT", out):
        fail(f"crash output:\n{out[-2000:]}")
    return errors[0]


def bad(args):
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    deck = os.path.join(args.workdir, "in.bad")
    with open(deck, "w") as f:
        f.write("\n".join(args.lines) + "\n")
    result = subprocess.run([args.liggghts, "-st", "-in", deck, "-log", "none"], cwd=args.workdir, env=mpi_env(),
                            capture_output=True, text=True, errors="replace")
    out = result.stdout + result.stderr
    print(f"ok: {one_error(result, out, args.pattern)}")


def restart(args):
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    os.symlink(os.path.join(SOURCE_DIR, "potentials"), os.path.join(args.workdir, "potentials"))
    deck = os.path.join(SOURCE_DIR, args.deck)
    tables = {}
    for mode in (0, 1, 2):
        command = [args.liggghts, "-st", "-in", deck, "-log", f"log.{mode}", "-screen", "none", "-var", "mode",
                   str(mode)]
        if args.np > 1:
            command = [args.mpiexec, "-np", str(args.np)] + command
        result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
        text = open(os.path.join(args.workdir, f"log.{mode}")).read() if os.path.exists(
            os.path.join(args.workdir, f"log.{mode}")) else ""
        if result.returncode != 0:
            fail(f"mode {mode}: {' '.join(command)} exited with {result.returncode}\n{result.stdout[-1500:]}\n"
                 f"{result.stderr[-1500:]}\n{text[-1500:]}")
        if args.np > 1 and used_ranks(text) != args.np:
            fail(f"mode {mode}: the run did not use {args.np} MPI ranks")
        tables[mode] = thermo_blocks(text)
    dumps = []
    for mode in (0, 2):
        with open(os.path.join(args.workdir, f"final.{mode}.dump")) as f:
            dumps.append(f.read().splitlines())
    if dumps[0] != dumps[1]:
        for n, (a, b) in enumerate(zip(*dumps)):
            if a != b:
                fail(f"final.0.dump and final.2.dump differ at line {n + 1}:\n  {a}\n  {b}")
        fail("final.0.dump and final.2.dump differ in length")
    straight, restarted = tables[0][-1], tables[2][-1]
    if straight != restarted:
        fail(f"the thermo rows of the last run differ:\n{straight}\n{restarted}")
    atoms = [line.split() for line in dumps[0][9:]]
    worn = sum(1 for words in atoms if float(words[17]) > 0.0 or float(words[21]) > 0.0)
    contacts = [float(row[header.index("fric[4]" if "fric[4]" in header else "c_fric[4]")])
                for header, rows in tables[2] for row in rows] if tables[2] else []
    if not worn or not contacts or max(contacts) <= 0:
        fail(f"empty check: {worn} worn or flattened atoms, contacts {contacts[:3]}")
    print(f"{args.deck} at {args.np} rank(s): {len(atoms)} atoms (x, v, omega, f, torque, wear state; {worn} worn "
          f"or flattened) and {len(restarted[1])} thermo rows bit-identical after write_restart/read_restart")


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="mode", required=True)
    p = sub.add_parser("scene")
    p.add_argument("--liggghts", required=True)
    p.add_argument("--lmp", required=True)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--scene", required=True, choices=sorted(SCENES))
    p.add_argument("--workdir", required=True)
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help="override a deck variable of the scene")
    p = sub.add_parser("bad")
    p.add_argument("--liggghts", required=True)
    p.add_argument("--workdir", required=True)
    p.add_argument("--pattern", required=True)
    p.add_argument("--registry", help="runin_registry_names, for {registry:KIND} in the pattern")
    p.add_argument("lines", nargs="+")
    for mode in ("restart", "warning", "error"):    # a LIGGGHTS deck at N ranks
        p = sub.add_parser(mode)
        p.add_argument("--liggghts", required=True)
        p.add_argument("--mpiexec", default="mpiexec")
        p.add_argument("--np", type=int, default=1)
        p.add_argument("--deck", required=True)
        p.add_argument("--workdir", required=True)
        if mode != "restart":
            p.add_argument("--pattern", required=True)
            p.add_argument("--set", action="append", metavar="NAME=VALUE", help="a deck variable")
        if mode == "warning":
            p.add_argument("--count", type=int, default=1)
    args = parser.parse_args()
    args.liggghts = os.path.abspath(args.liggghts)
    if args.mode == "bad":
        args.pattern = with_registry_names(args.pattern, args.registry)
    if getattr(args, "lmp", None):
        args.lmp = os.path.abspath(args.lmp)
    {"scene": scene, "bad": bad, "restart": restart, "warning": warning, "error": error}[args.mode](args)


if __name__ == "__main__":
    main()
