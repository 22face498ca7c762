#!/usr/bin/env python3
"""Deck-driven LAMMPS tests for RunIn (run by ctest; standard library only).

  run_deck.py slider  --lmp LMP --mpiexec MPIEXEC --np N --deck DECK --workdir DIR
  run_deck.py archard --lmp LMP --deck DECK --workdir DIR
  run_deck.py compare DIR_A DIR_B
  run_deck.py hosts --reference FILE --this FILE [--limit 1e-12]
  run_deck.py roughness --lmp LMP --mpiexec MPIEXEC --np N --deck DECK --workdir DIR
  run_deck.py expect-error --lmp LMP --deck DECK --workdir DIR --pattern REGEX [--registry HELPER]
  run_deck.py expect-warning --lmp LMP --deck DECK --workdir DIR --pattern REGEX [--registry HELPER]
  run_deck.py materials --lmp LMP --deck DECK --workdir DIR FILE:MAT_A:MAT_B ...
"""
import argparse
import math
import os
import re
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail, fresh_dir, mpi_env  # noqa: E402,F401  (re-exported to the LAMMPS checks)

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


# Warnings a LAMMPS host prints on its own for a correct deck, by name; any other WARNING in a run that
# must be clean fails the test. "no_time_integration": since 2022 LAMMPS warns for a run without an
# integrating fix, which the static single-contact decks are on purpose.
KNOWN_HOST_WARNINGS = {
    "no_time_integration": re.compile(r"^WARNING: No fixes with time integration, atoms won't move"),
}


def unexpected_warnings(log):
    """The WARNING lines of `log` that are not known host warnings (KNOWN_HOST_WARNINGS)."""
    return [line for line in log.splitlines() if line.startswith("WARNING")
            and not any(known.match(line) for known in KNOWN_HOST_WARNINGS.values())]


def run_lammps(args, deck, variables=None, log="log.lammps", np=1):
    """Runs args.lmp on `deck` (a path) in args.workdir, under args.mpiexec when np > 1, with
    -var NAME VALUE... for each entry of `variables` (a list or tuple value gives an index variable).
    A non-zero exit, or a parallel run that did not use np ranks, fails the test with the output's
    tail. Returns the log text."""
    command = [args.lmp, "-in", deck, "-log", log, "-screen", "none"]
    if np > 1:
        command = [args.mpiexec, "-np", str(np)] + command
    for name, value in (variables or {}).items():
        command += ["-var", name] + [str(v) for v in (value if isinstance(value, (list, tuple)) else [value])]
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True)
    log_path = os.path.join(args.workdir, log)
    text = open(log_path).read() if os.path.exists(log_path) else ""
    if result.returncode != 0:
        fail(f"{os.path.basename(deck)}: LAMMPS ({args.lmp}) exited with {result.returncode}\n{result.stdout[-2000:]}\n"
             f"{result.stderr[-2000:]}\n{text[-2000:]}")
    if np > 1 and f"with {np} MPI tasks" not in text:
        fail(f"{os.path.basename(deck)}: the run did not use {np} MPI ranks")
    return text


def run_lammps_two_at_a_time(args, deck, runs):
    """Runs args.lmp on `deck` (a path) once per (name, variables) of `runs`, two at a time (one per core), in
    args.workdir with -log log.NAME and -var NAME VALUE for each variable; a run that exits non-zero fails the test
    with the tail of its stderr."""
    pending, running = list(runs), []
    while pending or running:
        while pending and len(running) < 2:
            name, variables = pending.pop(0)
            command = [args.lmp, "-in", deck, "-log", f"log.{name}", "-screen", "none"]
            for key, value in variables.items():
                command += ["-var", key, str(value)]
            running.append((name, subprocess.Popen(command, cwd=args.workdir, env=mpi_env(),
                                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)))
        name, proc = running.pop(0)
        _, err = proc.communicate()
        if proc.returncode != 0:
            fail(f"cell {name}: LAMMPS exited with {proc.returncode}: {err[-1000:]}")


# Worn-asperity geometry for the checks, independent of the C++ kernels (bisection for the cap height).
def cap_height(radius, volume):
    """Root of pi h^2 (3R - h) / 3 = V in [0, 2R], by bisection to the last bit."""
    if volume <= 0.0:
        return 0.0
    lo, hi = 0.0, 2.0 * radius
    while True:
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            return mid
        if math.pi * mid * mid * (3.0 * radius - mid) / 3.0 < volume:
            lo = mid
        else:
            hi = mid


def worn(radius, lost, gained):
    """(summit drop h, flat radius a_w) of a truncated sphere; a net gain raises the summit over pi R^2."""
    net = lost - gained
    if net < 0.0:
        return net / (math.pi * radius * radius), 0.0
    h = cap_height(radius, net)
    return h, math.sqrt(h * (2.0 * radius - h))


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


def subdomain_crossings(dump_text, log_text, skin):
    """Atoms certain to have changed MPI rank during the slide of in.rough_slider.

    A uniform P_x x P_y x P_z decomposition (the log's processor grid) owns an atom by its slab in each
    dimension. With 'neigh_modify every 1 check yes' the last rebuild (where atoms migrate) happened less
    than skin/2 before the final position, so an atom whose whole skin/2 neighbourhood of the final
    position lies in another slab than its start (taken only if clear of slab faces) has migrated.
    """
    grid = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", log_text)
    procs = [int(g) for g in grid.groups()] if grid else [1, 1, 1]
    snapshots = dump_snapshots(dump_text)
    (lo, hi), first, last = snapshots[0][0], snapshots[0][1], snapshots[-1][1]
    crossed = 0
    for tag, start in first.items():
        end = last[tag]
        for dim in range(3):
            if procs[dim] == 1:
                continue
            length = hi[dim] - lo[dim]
            width = length / procs[dim]
            moved = end[dim] - start[dim]
            moved -= length * round(moved / length)    # periodic wrap (the slide is shorter than L/2)
            offset = (start[dim] - lo[dim]) / width
            if abs(offset - round(offset)) * width < 1e-3 * skin:
                continue    # starts on a slab face: owner ambiguous
            reached = [math.floor((start[dim] + moved + side - lo[dim]) / width) % procs[dim]
                       for side in (-0.5 * skin, 0.5 * skin)]
            if reached[0] == reached[1] != math.floor(offset) % procs[dim]:
                crossed += 1
                break
    return crossed, procs


def dump_snapshots(text):
    """[((lo, hi), {id: (x, y, z)}), ...] of a LAMMPS custom dump with id and x y z columns."""
    lines, snapshots, k = text.splitlines(), [], 0
    while k < len(lines):
        if not lines[k].startswith("ITEM: TIMESTEP"):
            k += 1
            continue
        count = int(lines[k + 3])
        bounds = [tuple(map(float, lines[k + 5 + d].split()[:2])) for d in range(3)]
        columns = lines[k + 8].split()[2:]
        ix = [columns.index(name) for name in ("id", "x", "y", "z")]
        atoms = {}
        for line in lines[k + 9:k + 9 + count]:
            words = line.split()
            atoms[int(words[ix[0]])] = tuple(float(words[i]) for i in ix[1:])
        snapshots.append((([b[0] for b in bounds], [b[1] for b in bounds]), atoms))
        k += 9 + count
    return snapshots


def deck_value(deck, name):
    """The default of 'variable NAME index VALUE' (or the 'timestep VALUE') of a deck, as a float."""
    text = open(os.path.join(SOURCE_DIR, deck)).read()
    pattern = r"^timestep\s+(\S+)" if name == "timestep" else rf"^variable\s+{name}\s+index\s+(\S+)"
    return float(re.search(pattern, text, re.M).group(1))


def run_slider(args):
    """Short deterministic slide of the micro deck, long enough that atoms migrate between ranks.

    After the deck's settling (in contact from about step 600 on), 6000 steps at 0.5 m/s (5 nm a step) slide
    the counter-body 30 um: its column next to the periodic x face (0.5 a_top = 10.3 um from it) crosses it by
    more than skin/2 (0.5 um), so with 2, 3 and 4 ranks atoms change rank (checked below). The square box gives
    LAMMPS no preference between cuts across and along x (the sliding direction): px 2 (3 with 3 ranks) puts
    them across.
    """
    fresh_dir(args.workdir)
    variables = {"coeffs": os.path.join(SOURCE_DIR, "potentials", "CuAl.runin"), "nslide": 6000, "speed": 0.5,
                 "thermo_every": 50}
    if args.np > 1:
        variables["px"] = 3 if args.np == 3 else 2
    log = run_lammps(args, os.path.join(SOURCE_DIR, args.deck), variables, np=args.np)
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
    builds = [int(n) for n in re.findall(r"Neighbor list builds = (\d+)", log)]
    dangerous = [int(n) for n in re.findall(r"Dangerous builds = (\d+)", log)]
    if len(builds) != 2 or builds[1] < 2 or any(dangerous):
        fail(f"the slide must rebuild the neighbour lists (builds {builds}, dangerous {dangerous})")
    skin = float(re.search(r"^neighbor\s+(\S+)\s+bin", open(os.path.join(SOURCE_DIR, args.deck)).read(),
                           re.M).group(1))
    crossed, procs = subdomain_crossings(open(os.path.join(args.workdir, "asperities.dump")).read(), log, skin)
    if args.np > 1 and crossed == 0:
        fail(f"no atom changed rank on the {procs} processor grid: lengthen the slide")
    # every thermo column, so the rank comparison covers whatever the deck reports (Rq included)
    with open(os.path.join(args.workdir, "sliding.tsv"), "w") as out:
        out.write("\t".join(sliding[0].keys()) + "\n")
        for row in sliding:
            out.write("\t".join(repr(value) for value in row.values()) + "\n")
    print(f"ok: {len(sliding)} sliding rows, contacts {min(contacts):.0f}-{max(contacts):.0f}, "
          f"mu_eff {mu[-1]:.6g}, wear {wear[-1]:.6g} m^3, {builds[1]} neighbour builds, "
          f"{crossed} atoms changed rank on the {'x'.join(map(str, procs))} grid")


def archard_budget(args):
    """Steady sliding: total wear must follow per-body Archard, V = k W s (1/H_Al + 1/H_Cu), for the deck's load."""
    fresh_dir(args.workdir)
    nslide = 4000
    speed, dt, load = (deck_value(args.deck, name) for name in ("speed", "timestep", "load"))
    k, hardness_al, hardness_cu = 1.0e-3, 0.245e9, 0.87e9    # potentials/CuAl.runin: pair k, materials' H
    log = run_lammps(args, os.path.join(SOURCE_DIR, args.deck),
                     {"coeffs": os.path.join(SOURCE_DIR, "potentials", "CuAl.runin"), "nslide": nslide,
                      "thermo_every": 1000})
    sliding = thermo_blocks(log)[1]
    worn = sliding[-1]["c_fric[5]"] - sliding[0]["c_fric[5]"]
    expected = k * load * nslide * dt * speed * (1.0 / hardness_al + 1.0 / hardness_cu)
    ratio = worn / expected
    # below 1: sliding distance lost to the stick phase; above 1: sum F_n exceeds the load on tilted contacts
    if not 0.9 <= ratio <= 1.05:
        fail(f"wear {worn:.4e} m^3 vs Archard k W s (1/H_Al + 1/H_Cu) = {expected:.4e} m^3 (ratio {ratio:.4f}, "
             "want 0.9-1.05)")
    print(f"ok: wear {worn:.4e} m^3, Archard {expected:.4e} m^3, ratio {ratio:.4f}")


def compare(args):
    """Every thermo column of two slider runs (different rank counts) row by row, 1e-8 relative."""
    def load(directory):
        with open(os.path.join(directory, "sliding.tsv")) as f:
            header = f.readline().split()
            return header, [[float(x) for x in line.split()] for line in f]

    (names_a, a), (names_b, b) = load(args.dir_a), load(args.dir_b)
    if names_a != names_b:
        fail(f"thermo columns differ: {names_a} vs {names_b}")
    if len(a) != len(b) or len(a) < 10:
        fail(f"row counts differ or too few: {len(a)} vs {len(b)}")
    worst, where, varying = 0.0, "", set()
    for row_a, row_b in zip(a, b):
        if row_a[0] != row_b[0]:
            fail(f"steps differ: {row_a[0]} vs {row_b[0]}")
        for name, x, y, first in zip(names_a, row_a, row_b, a[0]):
            if x != first:
                varying.add(name)
            scale = max(abs(x), abs(y))
            if scale > 0 and abs(x - y) / scale > worst:
                worst, where = abs(x - y) / scale, f"{name} at step {row_a[0]:.0f}"
    if worst > 1e-8:
        fail(f"thermo columns differ between rank counts by {worst:.3e} relative at {where} (limit 1e-8)")
    constant = [name for name in names_a if name not in varying]
    print(f"ok: {len(a)} rows x {len(names_a)} columns agree, worst relative difference {worst:.3e}"
          + (f" ({where})" if where else "") + (f"; constant columns: {' '.join(constant)}" if constant else ""))


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
    log = run_lammps(args, deck, np=args.np)
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
            if abs(atom[f"c_{name}[1]"] - want) > 1e-10 * scale:
                fail(f"atom {int(atom['id'])}: c_{name}[1] = {atom[f'c_{name}[1]']!r}, closed form {want!r}")
            if atom[f"c_{name}[2]"] != 0.0:    # no wear state in the deck: wear depth exactly 0
                fail(f"atom {int(atom['id'])}: c_{name}[2] (wear depth) = {atom[f'c_{name}[2]']!r}, want 0")
            checked += 1
    print(f"ok: {checked} values on {args.np} rank(s) match the closed form, worst global relative error {worst:.3e}")


REGISTRY_NAMES = re.compile(r"\{registry:(\w+)\}")


def with_registry_names(pattern, registry):
    """`pattern` with each {registry:KIND} replaced by the registry's names of that kind as the messages list them
    ("NAME, NAME, ..."), printed by `registry` (the helper runin_registry_names): the expected messages follow
    the registry, so adding a row needs no test edit."""
    if not REGISTRY_NAMES.search(pattern):
        return pattern
    if not registry:
        fail(f"the pattern {pattern!r} names the registry but no --registry helper was given")
    printed = subprocess.run([registry], capture_output=True, text=True, check=True).stdout
    names = dict(line.split(": ", 1) for line in printed.splitlines())

    def listed(match):
        if match.group(1) not in names:
            fail(f"{{registry:{match.group(1)}}}: no such kind (the registry's: {', '.join(names)})")
        return re.escape(names[match.group(1)])
    return REGISTRY_NAMES.sub(listed, pattern)


def single_error(result, pattern, refused="the deck was accepted"):
    """The one ERROR line of a finished lmp_runin run that must stop cleanly (no crash) naming `pattern`."""
    output = result.stdout + result.stderr
    if result.returncode == 0:
        fail(f"{refused}; expected an ERROR")
    if result.returncode < 0 or result.returncode >= 128:
        fail(f"crashed with signal/status {result.returncode}\n{output}")
    errors = [line for line in output.splitlines() if line.startswith("ERROR")]
    if len(errors) != 1:
        fail(f"expected exactly one ERROR line, got {errors}\n{output}")
    if not re.search(pattern, errors[0]):
        fail(f"ERROR line does not name the problem ({pattern!r}): {errors[0]}")
    return errors[0]


NON_FINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w.])", re.IGNORECASE)


def run_expecting(args):
    """Runs the deck (-var NAME VALUE for each --var; under mpiexec for --np > 1) in a fresh workdir. No
    thermo line or output file written before the ERROR or WARNING may hold a non-finite number: the
    styles must stop or warn before anything non-finite is printed."""
    fresh_dir(args.workdir)
    command = [args.lmp, "-in", os.path.join(SOURCE_DIR, args.deck), "-log", "none"]
    for name, value in args.var or []:
        command += ["-var", name, value]
    if args.np > 1:
        command = [args.mpiexec, "-np", str(args.np)] + command
    result = subprocess.run(command, cwd=args.workdir, env=mpi_env(), capture_output=True, text=True, timeout=120)
    printed = [line for line in (result.stdout + result.stderr).splitlines()
               if not line.startswith(("ERROR", "WARNING", "Last command", "Last input line"))]
    written = []
    for name in os.listdir(args.workdir):
        if name.endswith((".dat", ".csv", ".dump")):
            written += open(os.path.join(args.workdir, name), errors="replace").read().splitlines()
    bad = [line for line in printed + written if NON_FINITE.search(line)]
    if bad:
        fail(f"non-finite value printed or written: {bad[0]!r}")
    return result


# What a LAMMPS host does on its own, before any RunIn code runs, where it cannot give RunIn's ERROR, by
# name. "stod_overflow": LAMMPS 4Feb2025's variable parser reads numbers with std::stod, which throws
# out_of_range on 1e999; lmp's main catches it, prints "Exception: stod" and calls MPI_Abort (exit 1, no
# crash). Debian's 29Sep2021 reads 1e999 as inf with atof, and RunIn's guard names it.
KNOWN_HOST_LIMITATIONS = {
    "stod_overflow": re.compile(r"^Exception: stod$", re.M),
}


def expect_error(args):
    result = run_expecting(args)
    output = result.stdout + result.stderr
    limitation = KNOWN_HOST_LIMITATIONS.get(args.host_limitation) if args.host_limitation else None
    if limitation and not re.search(r"^ERROR", output, re.M):
        if result.returncode > 0 and limitation.search(output):
            print(f"ok: known host limitation '{args.host_limitation}' (exit {result.returncode}): "
                  f"{limitation.search(output).group(0)}")
            return
        fail(f"neither RunIn's ERROR nor the host's '{args.host_limitation}' (exit {result.returncode}):\n"
             f"{output[-2000:]}")
    print("ok: " + single_error(result, args.pattern))


def expect_warning(args):
    """The deck runs to the end and prints exactly --count WARNING lines matching the pattern (default one)."""
    result = run_expecting(args)
    output = result.stdout + result.stderr
    if result.returncode != 0:
        fail(f"LAMMPS ({args.lmp}) exited with {result.returncode}\n{output}")
    matching = [line for line in output.splitlines() if line.startswith("WARNING") and re.search(args.pattern, line)]
    if len(matching) != args.count:
        fail(f"expected {args.count} WARNING(s) matching {args.pattern!r}, got {matching}\n{output}")
    if "Loop time" not in output:
        fail("the run did not finish")
    print("ok: " + matching[0])


def runin_materials(path):
    """{name: (E, nu)} from the material lines of a .runin coefficient file."""
    materials = {}
    for line in open(path):
        words = line.split("#")[0].split()
        if words and words[0] == "material":
            materials[words[1]] = (float(words[2]), float(words[3]))
    return materials


def materials(args):
    """Each coefficient file through 'pair_coeff * * file': the Hertz energy of two asperities of
    radius R overlapping by delta, 8/15 E* sqrt(R/2) delta^5/2, from the file's E and nu."""
    radius, delta = 1.0e-6, 1.0e-8
    for spec in args.entries:
        name, mat_a, mat_b = spec.split(":")
        workdir = os.path.join(args.workdir, f"{name}_{mat_a}_{mat_b}")
        fresh_dir(workdir)
        command = [args.lmp, "-in", os.path.join(SOURCE_DIR, args.deck), "-var", "potdir",
                   os.path.join(SOURCE_DIR, "potentials"), "-var", "file", name, "-var", "matA", mat_a,
                   "-var", "matB", mat_b, "-var", "R", repr(radius), "-var", "delta", repr(delta),
                   "-log", "log.lammps", "-screen", "none"]
        result = subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True, text=True, timeout=60)
        log = open(os.path.join(workdir, "log.lammps")).read()
        if result.returncode != 0 or unexpected_warnings(log):
            fail(f"{name} {mat_a} {mat_b}: exit {result.returncode}, warnings {unexpected_warnings(log)}, log:\n"
                 f"{log[-2000:]}")
        table = runin_materials(os.path.join(SOURCE_DIR, "potentials", name))
        (e_a, nu_a), (e_b, nu_b) = table[mat_a], table[mat_b]
        e_eff = 1.0 / ((1.0 - nu_a ** 2) / e_a + (1.0 - nu_b ** 2) / e_b)
        expected = 8.0 / 15.0 * e_eff * math.sqrt(radius / 2.0) * delta ** 2.5
        got = thermo_blocks(log)[-1][-1]["PotEng"]
        if abs(got - expected) > 1e-10 * expected:
            fail(f"{name} {mat_a} {mat_b}: Hertz energy {got!r} J, closed form {expected!r} J")
        print(f"ok: {name} {mat_a}/{mat_b}: E* = {e_eff:.4g} Pa, energy {got:.6g} J matches the closed form")


# Greenwood-Williamson sample: 100 x 100 summits of radius R on a square grid of spacing a
# (eta = 1/a^2), heights sigma * Phi^-1(u), u stratified over (0, 1) with a seeded jitter and then
# shuffled: a deterministic Gaussian sample whose histogram follows phi closely in the tail.
GW = {"n": 100, "a": 2.0e-6, "R": 5.0e-6, "sigma": 1.0e-7, "Estar": 1.0e11, "seed": 20261122}


def gw_sample(path):
    import random
    import statistics
    rng = random.Random(GW["seed"])
    n = GW["n"] ** 2
    gauss = statistics.NormalDist(0.0, GW["sigma"])
    heights = [gauss.inv_cdf((k + rng.random()) / n) for k in range(n)]
    rng.shuffle(heights)
    side = GW["n"] * GW["a"]
    with open(path, "w") as out:
        out.write(f"RunIn GW sample (run_deck.py gw)\n\n{n} atoms\n1 atom types\n\n")
        out.write(f"0 {side!r} xlo xhi\n0 {side!r} ylo yhi\n{-3 * GW['R']!r} {2 * GW['R']!r} zlo zhi\n\n")
        out.write("Atoms # sphere\n\n")
        for k, h in enumerate(heights):
            x = (k % GW["n"] + 0.5) * GW["a"]
            y = (k // GW["n"] + 0.5) * GW["a"]
            out.write(f"{k + 1} 1 {2 * GW['R']!r} 7800.0 {x!r} {y!r} {h - GW['R']!r}\n")
    return heights


def hertz_sum(heights, wall_z):
    """Exact load of the sample: every summit above the flat is one Hertz contact."""
    c = 4.0 / 3.0 * GW["Estar"] * math.sqrt(GW["R"])
    return sum(c * (h - wall_z) ** 1.5 for h in heights if h > wall_z)


def run_gw(args):
    """Wall load vs separation: exact sum over the sample (1e-9) and the GW integral (3 %)."""
    fresh_dir(args.workdir)
    heights = gw_sample(os.path.join(args.workdir, "gw.data"))
    n = len(heights)
    mean = sum(heights) / n
    sigma = math.sqrt(sum((h - mean) ** 2 for h in heights) / n)
    area = (GW["n"] * GW["a"]) ** 2
    separations = [-1.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5]    # (wall z - mean) / sigma
    walls = [mean + s * sigma for s in separations]
    log = run_lammps(args, os.path.join(SOURCE_DIR, args.deck),
                     {"data": "gw.data", "R": GW["R"], "Estar": GW["Estar"], "zw": walls}, np=args.np)
    rows = [[float(w) for w in line.split()[1:]] for line in log.splitlines() if line.startswith("GW_LOAD")]
    if len(rows) != len(walls):
        fail(f"expected {len(walls)} GW_LOAD lines, got {len(rows)}")
    gw = subprocess.run([args.gw_expected, repr(1.0 / GW["a"] ** 2), repr(GW["R"]), repr(sigma), repr(GW["Estar"]),
                         *[repr(z - mean) for z in walls]], capture_output=True, text=True, check=True)
    expected_gw = [float(line.split()[1]) * area for line in gw.stdout.splitlines()]
    with open(os.path.join(args.workdir, "gw_load.tsv"), "w") as out:
        out.write("# (z-mean)/sigma  wall_z[m]  F_wall[N]  F_sum[N]  F_GW[N]  contacts\n")
        for s, z, (zw, force, contacts, fric_fn, fric_contacts), f_gw in zip(separations, walls, rows, expected_gw):
            exact = hertz_sum(heights, z)
            touching = sum(1 for h in heights if h > z)
            if abs(zw - z) > 1e-12 * GW["sigma"]:
                fail(f"wall z {zw!r} reported, {z!r} requested")
            if contacts != touching or fric_contacts != touching:
                fail(f"d = {s} sigma: {contacts:.0f} wall / {fric_contacts:.0f} compute contacts, sample has {touching}")
            if abs(force - exact) > 1e-9 * exact or abs(fric_fn - exact) > 1e-9 * exact:
                fail(f"d = {s} sigma: wall force {force!r} / compute {fric_fn!r} vs exact Hertz sum {exact!r}")
            if abs(force - f_gw) > 0.03 * f_gw:
                fail(f"d = {s} sigma: wall force {force:.6e} N vs GW {f_gw:.6e} N "
                     f"({100 * (force / f_gw - 1):+.2f} %, limit 3 %)")
            out.write(f"{s}\t{z!r}\t{force!r}\t{exact!r}\t{f_gw!r}\t{contacts:.0f}\n")
            print(f"d = {s:3.1f} sigma: {contacts:5.0f} contacts, F = {force:.6e} N, GW {f_gw:.6e} N "
                  f"({100 * (force / f_gw - 1):+.2f} %)")
    print(f"ok: {args.np} rank(s), sample mean {mean:.3e} m, sigma {sigma:.6e} m")


def run_lmp(args, deck, variables, log_name):
    """Thermo tables of a deck (path relative to the source tree) run on args.np ranks."""
    return thermo_blocks(run_lammps(args, os.path.join(SOURCE_DIR, deck), variables, log_name, np=args.np))


def run_gw_servo(args):
    """fix runin/wall load control, sliding, wear and restart on the GW sample (closed forms)."""
    fresh_dir(args.workdir)
    heights = gw_sample(os.path.join(args.workdir, "gw.data"))
    pressure, speed, dt, nload, nslide = 1.5e8, 1.0, 1.0e-9, 400, 200
    mu_k, k, h_asperity, h_wall = 0.4, 1.0e-3, 1.0e9, 3.0e9    # the deck's friction and wear values
    target = pressure * (GW["n"] * GW["a"]) ** 2
    load, slide1, slide2 = run_lmp(args, args.deck, {"data": "gw.data", "z0": "5.0e-7"}, "log.lammps")

    # 1. servo: monotone approach, no overshoot, converged onto the sample's exact Hertz-sum root
    forces = [row["f_wall[3]"] for row in load]
    if any(b < a * (1 - 1e-12) for a, b in zip(forces, forces[1:])):
        fail(f"servo force is not monotone: {forces}")
    if max(forces) > target * (1 + 1e-9):
        fail(f"servo overshoots: max {max(forces)!r} N, target {target!r} N")
    if abs(forces[-1] - target) > 1e-9 * target:
        fail(f"servo did not converge: {forces[-1]!r} N, target {target!r} N")
    lo, hi = min(heights) - GW["sigma"], max(heights)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if hertz_sum(heights, mid) > target else (lo, mid)
    z_wall = load[-1]["f_wall[4]"]
    if abs(z_wall - lo) > 1e-6 * GW["sigma"]:
        fail(f"wall z {z_wall!r} m vs exact-sum root {lo!r} m")

    # 2. sliding under load: Coulomb (kinetic) friction and the Archard budget of both bodies
    rows = slide1 + slide2
    share_asperity = h_wall / (h_asperity + h_wall)
    for row in rows:
        travel = speed * dt * (row["Step"] - nload)
        if abs(row["f_wall[5]"] - travel) > 1e-9 * max(travel, 1e-12) or row["f_wall[6]"] != 0.0:
            fail(f"wall travel {row['f_wall[5]']!r}, {row['f_wall[6]']!r} at step {row['Step']:.0f}; want {travel!r}, 0")
    steady = [row for row in rows if row["Step"] >= nload + 100]    # springs saturate within ~30 steps
    for a, b in zip(steady, steady[1:]):
        fz = b["f_wall[3]"]
        if abs(-b["f_wall[1]"] - mu_k * fz) > 1e-9 * fz or abs(b["c_fric[2]"] - mu_k * b["c_fric[1]"]) > 1e-9 * fz:
            fail(f"step {b['Step']:.0f}: friction {b['f_wall[1]']!r} N, want -mu_k Fz = {-mu_k * fz!r} N")
        worn = k * fz * speed * dt * (b["Step"] - a["Step"]) * (1.0 / h_asperity + 1.0 / h_wall)
        d_wall, d_asperity = b["f_wall[7]"] - a["f_wall[7]"], b["c_fric[5]"] - a["c_fric[5]"]
        if abs(d_wall - (1 - share_asperity) * worn) > 1e-6 * worn or abs(d_asperity - share_asperity * worn) > 1e-6 * worn:
            fail(f"step {b['Step']:.0f}: wear wall {d_wall!r} / asperities {d_asperity!r} m^3, "
                 f"Archard k F s (1/H_a + 1/H_w) = {worn!r} m^3 split {1 - share_asperity:.2f}/{share_asperity:.2f}")

    with open(os.path.join(args.workdir, "servo.tsv"), "w") as out:
        out.write("# step  Fx  Fz  z_wall  wall_wear  asperity_wear\n")
        for row in load + rows:
            out.write("\t".join(repr(row[name]) for name in ("Step", "f_wall[1]", "f_wall[3]", "f_wall[4]",
                                                              "f_wall[7]", "c_fric[5]")) + "\n")

    # 3. restart: the continued run repeats the last run of the original
    (again,) = run_lmp(args, "tests/lammps/decks/in.gw_servo_restart", {}, "log.restart")
    for original, repeated in zip(slide2, again):
        for name, value in original.items():
            if abs(repeated[name] - value) > 1e-12 * max(abs(value), 1e-30):
                fail(f"after restart {name} = {repeated[name]!r} at step {original['Step']:.0f}, original {value!r}")
    if len(again) != len(slide2):
        fail(f"restart run has {len(again)} rows, original {len(slide2)}")
    print(f"ok: {args.np} rank(s): servo reached {forces[-1]:.6g} N (target {target:.6g} N) at z = {z_wall:.6e} m, "
          f"mu = {-rows[-1]['f_wall[1]'] / rows[-1]['f_wall[3]']:.6g}, wall wear {rows[-1]['f_wall[7]']:.4e} m^3, "
          f"asperity wear {rows[-1]['c_fric[5]']:.4e} m^3, restart repeats {len(again)} rows")


def run_wall_bounce(args):
    """Elastic head-on impact on the wall, both sides: rebound speed v0 and the Hertz contact time."""
    fresh_dir(args.workdir)
    radius, v0, density, dt = 1.0e-6, 1.0, 7800.0, 1.0e-11    # the deck's values
    mass = density * 4.0 / 3.0 * math.pi * radius ** 3
    # file form: 1/E* = (1 - nu_A^2)/E_A + (1 - nu_B^2)/E_B
    with open(os.path.join(args.workdir, "bounce_coefficients"), "w") as out:
        out.write("material A 200.0e9 0.30 7800.0 2.0e9\nmaterial B 70.0e9 0.33 2700.0 0.5e9\n"
                  "pair A B 1.0 0.5 0.5 0.0 0.0\n")
    e_file = 1.0 / ((1 - 0.30 ** 2) / 200.0e9 + (1 - 0.33 ** 2) / 70.0e9)
    integral = 0.4 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)    # int_0^1 dx / sqrt(1 - x^5/2)
    cases = (("lo", 1.0, "none", 1.0e11), ("hi", -1.0, "none", 1.0e11), ("lo", 1.0, "bounce_coefficients", e_file))
    for side, sign, coefficients, e_star in cases:
        overlap_max = (15.0 * mass * v0 ** 2 / (16.0 * e_star * math.sqrt(radius))) ** 0.4
        contact_time = 2.0 * integral * overlap_max / v0
        (rows,) = run_lmp(args, args.deck, {"side": side, "file": coefficients},
                          f"log.{side}.{coefficients}")
        touching = [row for row in rows if row["f_wall[8]"] == 1.0]
        duration = len(touching) * dt
        rebound = rows[-1]["v_vz"]
        if rows[-1]["f_wall[8]"] != 0.0:
            fail(f"side {side}: the asperity is still on the wall at the end")
        if abs(rebound - sign * v0) > 1e-6 * v0:
            fail(f"side {side}: rebound velocity {rebound!r} m/s, elastic impact gives {sign * v0!r}")
        if abs(duration - contact_time) > 0.01 * contact_time:
            fail(f"side {side}: contact time {duration:.4e} s, Hertz {contact_time:.4e} s (limit 1 %)")
        if not touching or max(sign * row["f_wall[3]"] for row in touching) >= 0.0:
            fail(f"side {side}: the asperity must push the wall away from itself while they touch")
        print(f"ok: side {side}, coefficients {coefficients}: rebound {rebound:.9f} m/s, contact time "
              f"{duration:.4e} s vs Hertz {contact_time:.4e} s")


def run_wall_worn(args):
    """Worn asperity on the wall: Sneddon flat punch + Hertz (reshape yes), Hertz (reshape no)."""
    fresh_dir(args.workdir)
    radius, e_star = 1.0e-6, 1.0e11    # the deck's values
    h = 0.05 * radius
    lost = math.pi * h * h * (3 * radius - h) / 3.0    # cap volume of a truncated sphere
    b2 = 2 * radius * h - h * h                          # flat radius squared
    overlaps = [1.0e-9, 5.0e-9, 2.0e-8, 6.0e-8]
    for reshape in ("yes", "no"):
        drop = h if reshape == "yes" else 0.0
        walls = [drop + d for d in overlaps]    # the asperity's centre is at z = R
        blocks = run_lmp(args, args.deck, {"lost": lost, "reshape": reshape, "ztouch": drop, "zw": walls},
                         f"log.{reshape}")
        log = open(os.path.join(args.workdir, f"log.{reshape}")).read()
        rows = [[float(w) for w in line.split()[1:]] for line in log.splitlines() if line.startswith("WALL_WORN")]
        if len(rows) != len(walls):
            fail(f"expected {len(walls)} WALL_WORN lines, got {len(rows)}")
        def closed_form(d):
            if reshape == "yes":
                a2 = 0.5 * (b2 + math.sqrt(b2 * b2 + 4 * radius * radius * d * d))
                c = radius * d / math.sqrt(a2)
                return 2 * e_star / (3 * radius) * c * (2 * a2 + b2)
            return 4.0 / 3.0 * e_star * math.sqrt(radius) * d ** 1.5

        for d, (z, force) in zip(overlaps, rows):
            expected = closed_form(d)
            if abs(-force - expected) > 1e-9 * expected:
                fail(f"reshape {reshape}, overlap {d:.1e} m: wall force {-force!r} N, closed form {expected!r} N")
            print(f"ok: reshape {reshape}, overlap {d:.1e} m: F = {-force:.9e} N (closed form {expected:.9e} N)")
        # moving wall: z(n) = z0 + sum over steps k = 1..n of vz(k) dt, vz = 1 + 0.5 (k > 50) m/s
        moving = blocks[-1]
        if len(moving) != 11:
            fail(f"expected 11 rows of the moving-wall run, got {len(moving)}")
        for row in moving:
            n = row["Step"] - moving[0]["Step"]
            z = drop + 1.0e-11 * (n + 0.5 * max(0.0, row["Step"] - 50))
            if abs(row["f_wall[4]"] - z) > 1e-12 * z + 1e-24:
                fail(f"moving wall at step {row['Step']:.0f}: z = {row['f_wall[4]']!r}, want {z!r}")
            expected = closed_form(z - drop) if z > drop else 0.0
            if abs(-row["f_wall[3]"] - expected) > 1e-9 * expected + 1e-30:
                fail(f"moving wall at step {row['Step']:.0f}: force {-row['f_wall[3]']!r} N, closed form {expected!r} N")
        print(f"ok: reshape {reshape}, moving wall: z and force follow vz(t) over {len(moving)} rows")


def compare_gw(args):
    """Every value of gw_load.tsv (or --file) of two runs with different rank counts."""
    def load(directory):
        with open(os.path.join(directory, args.file)) as f:
            return [float(x) for line in f if not line.startswith("#") for x in line.split()]

    a, b = load(args.dir_a), load(args.dir_b)
    if len(a) != len(b) or not a:
        fail(f"value counts differ or empty: {len(a)} vs {len(b)}")
    worst = max(abs(x - y) / max(abs(x), abs(y)) if x != y else 0.0 for x, y in zip(a, b))
    if worst > 1e-12:
        fail(f"{args.file}: values differ between rank counts by {worst:.3e} relative (limit 1e-12)")
    print(f"ok: {len(a)} values of {args.file} agree, worst relative difference {worst:.3e}")


def numeric_table(path):
    """Rows of numbers of a whitespace table (lines starting with '#' and non-numeric header lines skipped)."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            try:
                rows.append([float(x) for x in line.split()])
            except ValueError:
                if rows:
                    fail(f"{path}: a non-numeric line among the data: {line.strip()!r}")
    return rows


def compare_hosts(args):
    """The same output file of two LAMMPS hosts (lmp_runin on Debian's LAMMPS, the plugin in a current one):
    every value equal to args.limit relative to the largest magnitude of its column (so round-off near a
    zero crossing is measured on the column's scale)."""
    reference, this = numeric_table(args.reference), numeric_table(args.this)
    if not reference:
        fail(f"{args.reference}: no rows (run the reference host's tests first)")
    if len(reference) != len(this) or any(len(a) != len(b) for a, b in zip(reference, this)):
        fail(f"table shapes differ: {len(reference)} rows in {args.reference}, {len(this)} in {args.this}")
    columns = len(reference[0])
    scale = [max(max(abs(row[c]), abs(other[c])) for row, other in zip(reference, this)) for c in range(columns)]
    worst, where = 0.0, ""
    for r, (a, b) in enumerate(zip(reference, this)):
        for c, (x, y) in enumerate(zip(a, b)):
            if not (math.isfinite(x) and math.isfinite(y)):
                fail(f"row {r + 1} column {c + 1}: not finite ({x!r}, {y!r})")
            difference = abs(x - y) / scale[c] if scale[c] > 0 else 0.0
            if difference > worst:
                worst, where = difference, f"row {r + 1} column {c + 1} ({x!r} vs {y!r})"
    if worst > args.limit:
        fail(f"{os.path.basename(args.this)}: hosts differ by {worst:.3e} of the column scale at {where} "
             f"(limit {args.limit:g})")
    print(f"ok: {len(this)} rows x {columns} columns of {os.path.basename(args.this)} agree across hosts, "
          f"worst difference {worst:.3e} of the column scale" + (f" at {where}" if where else ""))


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
    for kind in ("expect-error", "expect-warning"):
        p = sub.add_parser(kind)
        for name in ("--lmp", "--deck", "--workdir", "--pattern"):
            p.add_argument(name, required=True)
        p.add_argument("--var", nargs=2, action="append", metavar=("NAME", "VALUE"), help="-var NAME VALUE")
        p.add_argument("--np", type=int, default=1)
        p.add_argument("--mpiexec", default="mpiexec")
        p.add_argument("--registry", help="runin_registry_names, for {registry:KIND} in the pattern")
        if kind == "expect-error":
            p.add_argument("--host-limitation", choices=sorted(KNOWN_HOST_LIMITATIONS),
                           help="also accept this host's own known failure (KNOWN_HOST_LIMITATIONS) instead")
        if kind == "expect-warning":
            p.add_argument("--count", type=int, default=1, help="matching WARNING lines expected (e.g. one per run)")
    p = sub.add_parser("materials")
    for name in ("--lmp", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("entries", nargs="+", help="FILE:MATERIAL_A:MATERIAL_B")
    p = sub.add_parser("gw")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir", "--gw-expected"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("gw-servo")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("wall-bounce")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("wall-worn")
    for name in ("--lmp", "--mpiexec", "--deck", "--workdir"):
        p.add_argument(name, required=True)
    p.add_argument("--np", type=int, default=1)
    p = sub.add_parser("compare-gw")
    p.add_argument("dir_a")
    p.add_argument("dir_b")
    p.add_argument("--file", default="gw_load.tsv")
    p = sub.add_parser("hosts")
    p.add_argument("--reference", required=True, help="the file written on the reference host")
    p.add_argument("--this", required=True, help="the same file written on this host")
    p.add_argument("--limit", type=float, default=1e-12)
    args = parser.parse_args()
    if getattr(args, "pattern", None):
        args.pattern = with_registry_names(args.pattern, args.registry)
    {"hosts": compare_hosts, "slider": run_slider, "archard": archard_budget, "compare": compare, "roughness": roughness,
     "expect-error": expect_error, "expect-warning": expect_warning, "materials": materials,
     "gw": run_gw, "gw-servo": run_gw_servo, "wall-bounce": run_wall_bounce, "wall-worn": run_wall_worn, "compare-gw": compare_gw}[args.command](args)


if __name__ == "__main__":
    main()
