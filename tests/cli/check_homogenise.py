#!/usr/bin/env python3
"""runin homogenise end to end on the test fixture cell (tests/cli/homogenise/in.rve_fixture), 2 pressures x 2
seeds of 36 summits. Standard library only.

  check_homogenise.py --runin BIN --lmp LMP --reader READ_LAW --deck DECK --workdir DIR --mode MODE
  (--deck default: no --deck option, i.e. runin's default inputs/in.rve_rough; mode fail needs a deck file)

MODE build:  a cold run (4 samples under one mpirun, 2 partitions) writes a law the continuum reader
             (runin_read_state_law = coupling::StateLaw::read_file) accepts, with the grid, seeds, band and
             provenance; the top pressure's wear rate is the Archard rate k p / H of the physical k (the cell ran
             at acceleration x k); a rerun finds every sample cached ("0 samples to run", no mpirun) and writes
             the same tables. Prints both wall times (not asserted; doc/homogenise.md has the measured ones).
MODE fail:   a deck that stops with an ERROR for one (pressure, seed): the other samples complete and are cached,
             the failing one is named with its ERROR line, the law is written from the other seed, exit 1; a
             rerun runs only the failing sample again. A deck that fails at every seed of one pressure: exit 1,
             no law written.
MODE launcher: --launcher names a wrapper script (written in the work directory) that logs its arguments and
             execs mpirun: the cold run goes through it (one call, -np 2 and -partition 2x1 for the 2 partitions),
             and the law equals, to the bit, the one mode build wrote with the default launcher in its own cache
             (WORKDIR/build/law.json; all but the provenance and the cache path).
MODE launcher_alone: the same wrapper named by the case's [run] launcher = "./launch.sh ..." (beside the case
             file, runin started elsewhere) with a deck that fails at one (pressure, seed): the 2-partition run and,
             after it, the sample run alone go through the wrapper (-np 2, then -np 1).
MODE extra:  grid.extra_pressures = [5e5] added below the cached 2-pressure grid: the rerun takes the 4 grid
             samples from the cache and runs only the 2 new ones; the law spans 5e5 .. 4e6 Pa, its grid rows equal
             the first law's to the bit and its new row is the seed mean of the new samples. Then
             grid.extra_nside = [9]: only the 2 samples at 5e5 Pa rerun, in 9^2 summits (their logs), the grid rows
             stay, and the law records surface.nside_at_pressure = [9, 6, 6].
MODE relink: the cache is keyed on the physics lmp_runin was built from (lmp_runin.physics beside it), not on its
             bytes: (a) the build's lmp_runin.physics is the identity its physics sources give now (the build
             regenerated it); a cold run of 2 samples; (b) a relinked executable (a copy with other bytes, its
             .physics beside it) takes both from the cache, the law records its other SHA-256 and the same
             physics identity; (c) a physics source changed by one comment line gives another identity, and an
             executable carrying it runs both samples again; (d) so does a changed deck. Needs --cmake,
             --source-dir, --physics-script, --physics-list and --physics-config.
MODE interrupt: SIGTERM to runin homogenise after its first finished sample (shipped cell, 4 samples of 576
             summits, several seconds each): it stops its mpirun (no lmp_runin or mpirun left with the work
             directory in its command line), exits 1 with one line naming the signal, keeps the finished samples;
             a rerun runs only the others.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import time
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

CASE = """title = "homogenise test fixture"
[material]
file = "{material}"
rough = "Steel1020"
counterface = "Steel1020"
[surface]
nside = 6
[sliding]
speed = 0.1
[grid]
pressure_min = 1.0e6
pressure_max = 4.0e6
pressures = 2
seeds = 2
acceleration = [2000.0, 1000.0]
depth = 2.0e-9
depth_points = 5
nslide = 4000
nout = 10
"""
SEED_1 = 4711 + 7919  # the second derived seed (homogenise_plan.cpp: derived_seed)
K, H = 7.0e-3, 1.19e9  # the fixture's Archard k and hardness


def homogenise(args, case, law, cache, deck, expect, extra=()):
    command = [args.runin, "homogenise", case, "--output", law, "--cache-dir", cache, "--np", "2", "--lmp", args.lmp]
    command += list(extra)
    if deck != "default":  # default: runin's own, inputs/in.rve_rough
        command += ["--deck", deck]
    start = time.monotonic()
    result = subprocess.run(command, capture_output=True, text=True)
    seconds = time.monotonic() - start
    print(result.stdout + result.stderr)
    if result.returncode != expect:
        fail(f"{' '.join(command)}: exit {result.returncode}, expected {expect}")
    return result, seconds


def read_law(args, law):
    result = subprocess.run([args.reader, law], capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"the continuum reader rejects {law}: {result.stderr}")
    return json.loads(result.stdout)


def setup(args, name):
    work = os.path.join(args.workdir, name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(work, "case.toml")
    with open(case, "w") as f:
        f.write(CASE.format(material=args.material))
    return work, case


def mode_build(args):
    shipped = args.deck == "default" or os.path.basename(args.deck) != "in.rve_fixture"
    work, case = setup(args, "build_" + os.path.basename(args.deck).replace(".", "_") if shipped else "build")
    law, cache = os.path.join(work, "law.json"), os.path.join(work, "cache")
    first, cold = homogenise(args, case, law, cache, args.deck, 0)
    if "4 samples to run" not in first.stdout or "mpirun -np 2" not in first.stdout:
        fail("the cold run did not run 4 samples under one mpirun -np 2")
    if "sample 4/4 done" not in first.stdout:
        fail("no progress line 'sample 4/4 done'")
    read = read_law(args, law)
    if len(read["pressure"]) != 2 or len(read["worn_depth"]) != 5 or not read["has_band"]:
        fail(f"grid or band: {read}")
    with open(law) as f:
        doc = json.load(f)
    if doc["samples"]["seeds"] != [4711, SEED_1] or doc["samples"]["acceleration"] != [2000.0, 1000.0]:
        fail(f"samples: {doc['samples']}")
    keys = {s["key"] for s in doc["samples"]["list"]}
    if len(keys) != 4 or any(s["status"] != "ok" for s in doc["samples"]["list"]):
        fail("the law does not list 4 good samples with distinct cache keys")
    for key in keys:
        if not os.path.isfile(os.path.join(cache, key, "out.dat")):
            fail(f"sample {key} is not in the cache")
    prov = doc["provenance"]
    for field in ("runin_version", "runin_git", "lammps_version", "lmp", "command_line", "date_utc", "host", "case"):
        if not prov.get(field):
            fail(f"provenance.{field} missing")
    if doc["material"]["rough"] != "Steel1020" or len(doc["material"]["sha256"]) != 64:
        fail(f"material: {doc['material']}")
    # provenance without this machine's paths (the work directory, the build tree, the cache are all absolute here)
    def strings(node):
        if isinstance(node, dict):
            for v in node.values():
                yield from strings(v)
        elif isinstance(node, list):
            for v in node:
                yield from strings(v)
        elif isinstance(node, str):
            yield node
    absolute = [t for t in strings({k: v for k, v in doc.items() if k != "fields"})
                if any(word.startswith("/") or "=/" in word for word in t.split())]
    if absolute:
        fail(f"the law names absolute paths: {absolute}")
    if doc["provenance"]["lmp"]["path"] != os.path.basename(args.lmp) and "/" not in doc["provenance"]["lmp"]["path"]:
        fail(f"provenance.lmp.path {doc['provenance']['lmp']['path']}: neither relative to the source tree nor the name")
    # physical wear rate at the top pressure: Archard k p / H (the cell's k was acceleration x k). Mean over
    # the law's depths: the 36-summit cell is chaotic (a change of S_y by 3e-14 moves the rate at one depth by
    # a few per cent), the mean is not
    p = read["pressure"][-1]
    with open(law) as f:
        rates = json.load(f)["fields"]["wear_rate"]["mean"][-1]
    rate = sum(rates) / len(rates)
    if abs(rate / (K * p / H) - 1.0) > 0.25:
        fail(f"wear rate at p = {p:g} (mean over depths): {rate:.4g}, Archard k p / H = {K * p / H:.4g}")

    second, warm = homogenise(args, case, law, cache, args.deck, 0)
    if "0 samples to run" not in second.stdout or "mpirun" in second.stdout:
        fail("the rerun did not take every sample from the cache")
    with open(law) as f:
        again = json.load(f)
    if again["fields"] != doc["fields"] or again["pressure"] != doc["pressure"]:
        fail("the cached rerun wrote different tables")
    print(f"check_homogenise: cold {cold:.2f} s, cached rerun {warm:.3f} s (4 samples of 36 summits)")


def mode_extra(args):
    work, case = setup(args, "extra")
    law, cache = os.path.join(work, "law.json"), os.path.join(work, "cache")
    homogenise(args, case, law, cache, args.deck, 0)
    with open(law) as f:
        grid_law = json.load(f)
    with open(case) as f:
        text = f.read()
    with open(case, "w") as f:
        f.write(text.replace("pressures = 2\n", "pressures = 2\nextra_pressures = [5.0e5]\n")
                .replace("acceleration = [2000.0, 1000.0]", "acceleration = [2000.0, 2000.0, 1000.0]"))
    extended, _ = homogenise(args, case, law, cache, args.deck, 0)
    if "6 samples of 36 summits; 4 cached" not in extended.stdout or "2 samples to run" not in extended.stdout:
        fail("the extended grid did not reuse the 4 cached grid samples and run only the 2 new ones")
    read = read_law(args, law)
    with open(law) as f:
        doc = json.load(f)
    if read["pressure"] != [5.0e5] + grid_law["pressure"]:
        fail(f"pressures {read['pressure']}, expected 5e5 then {grid_law['pressure']}")
    for name, field in grid_law["fields"].items():
        for band, rows in field.items():
            if doc["fields"][name][band][1:] != rows:
                fail(f"{name}.{band}: the grid rows changed with the extra pressure")
    new = [s for s in doc["samples"]["list"] if s["pressure"] == 5.0e5]
    if len(new) != 2 or any(s["status"] != "ok" for s in new):
        fail(f"the extra pressure's samples: {new}")
    # a larger cell at the extra pressure (grid.extra_nside): only its samples rerun, in 9^2 summits
    with open(case) as f:
        text = f.read()
    with open(case, "w") as f:
        f.write(text.replace("extra_pressures = [5.0e5]\n", "extra_pressures = [5.0e5]\nextra_nside = [9]\n"))
    larger, _ = homogenise(args, case, law, cache, args.deck, 0)
    if "6 samples of 36 summits (81 at 5e+05 Pa); 4 cached" not in larger.stdout or "2 samples to run" not in larger.stdout:
        fail(f"the larger cell at 5e5 Pa did not rerun only its 2 samples: {larger.stdout}")
    with open(law) as f:
        doc = json.load(f)
    if doc["surface"].get("nside_at_pressure") != [9, 6, 6]:
        fail(f"the law's surface.nside_at_pressure is {doc['surface'].get('nside_at_pressure')}, not [9, 6, 6]")
    for sample in (s for s in doc["samples"]["list"] if s["pressure"] == 5.0e5):
        with open(os.path.join(cache, sample["key"], "log.lammps")) as f:
            if "Created 81 atoms" not in f.read():
                fail(f"sample {sample['key']} at 5e5 Pa did not run 81 summits")
    for name, field in grid_law["fields"].items():
        for band, rows in field.items():
            if doc["fields"][name][band][1:] != rows:
                fail(f"{name}.{band}: the grid rows changed with the larger cell below them")
    print("check_homogenise: extra pressure 5e5 Pa below the grid, 4 grid samples cached, grid rows unchanged; "
          "its larger cell (9^2 summits) reran only its 2 samples")


def failing_deck(args, work, condition):
    deck = os.path.join(work, "in.rve_fail")
    with open(args.deck) as f:
        text = f.read()
    with open(deck, "w") as f:
        f.write(text.replace("units           si",
                             f'if "{condition}" then "runin_forced_failure"\nunits           si', 1))
    return deck


def mode_fail(args):
    work, case = setup(args, "fail")
    law, cache = os.path.join(work, "law.json"), os.path.join(work, "cache")
    deck = failing_deck(args, work, f"${{pressure}} > 3.0e6 && ${{seed}} == {SEED_1}")
    first, _ = homogenise(args, case, law, cache, deck, 1)
    err = first.stderr.strip().splitlines()
    if not err or not err[-1].startswith("runin: error: homogenise: 1 of 4 samples failed") or "seed 12630" not in err[-1]:
        fail(f"last stderr line does not name the failed sample: {err[-1:]}")
    if len(err) != 1:
        fail(f"stderr is not one line: {err}")
    if not any("sample FAILED: p = 4e+06 Pa, seed 12630" in line and "runin_forced_failure" in line
               for line in first.stdout.splitlines()):
        fail("no report of the failed sample with its ERROR line")
    read = read_law(args, law)  # written: every pressure has a good seed
    with open(law) as f:
        doc = json.load(f)
    status = {(s["pressure"], s["seed"]): s["status"] for s in doc["samples"]["list"]}
    if status[(4.0e6, SEED_1)] != "failed" or list(status.values()).count("ok") != 3:
        fail(f"statuses: {status}")
    if read["mid_depth"][-1]["mu_body"] <= 0:
        fail("the top pressure has no law from its good seed")
    again, _ = homogenise(args, case, law, cache, deck, 1)
    if "1 samples to run" not in again.stdout:
        fail("the rerun did not keep the 3 good samples cached")

    # every seed of one pressure fails: no law
    work2, case2 = setup(args, "fail_pressure")
    law2 = os.path.join(work2, "law.json")
    deck2 = failing_deck(args, work2, "${pressure} > 3.0e6")
    third, _ = homogenise(args, case2, law2, os.path.join(work2, "cache"), deck2, 1)
    last = third.stderr.strip().splitlines()[-1]
    if not last.startswith("runin: error: homogenise: no law written: no good seed at p = 4e+06 Pa"):
        fail(f"last line: {last}")
    if os.path.exists(law2):
        fail("a law was written with a pressure that has no good seed")


WRAPPER = """#!/bin/sh
# a user's MPI launcher: logs its arguments, then runs mpirun with them
printf '%s\\n' "$*" >> "{log}"
exec "{mpirun}" "$@"
"""


def law_without_run(path):
    """The law's content that does not depend on how or when it was run."""
    with open(path) as f:
        doc = json.load(f)
    del doc["provenance"]
    del doc["samples"]["cache_dir"]
    return doc


def write_wrapper(work):
    """The wrapper script, its log and the --launcher option naming it."""
    mpirun = shutil.which(os.environ.get("RUNIN_MPIRUN") or "mpirun")
    if not mpirun:
        fail("no mpirun to wrap")
    log = os.path.join(work, "launcher.log")
    wrapper = os.path.join(work, "launch.sh")
    with open(wrapper, "w") as f:
        f.write(WRAPPER.format(log=log, mpirun=mpirun))
    os.chmod(wrapper, 0o755)
    return wrapper, log, ["--launcher", f"{wrapper} -np {{np}} --oversubscribe"]


def mode_launcher(args):
    work, case = setup(args, "launcher")
    wrapper, log, launcher = write_wrapper(work)

    law_default = os.path.join(args.workdir, "build", "law.json")  # mode build's, same case, deck and --np
    if not os.path.isfile(law_default):
        fail(f"no {law_default}: run mode build first (ctest: cli_homogenise_build)")
    law = os.path.join(work, "law.json")
    result, cold = homogenise(args, case, law, os.path.join(work, "cache"), args.deck, 0, launcher)
    if f"{wrapper} -np 2 --oversubscribe ..." not in result.stdout or "sample 4/4 done" not in result.stdout:
        fail("the run did not announce the wrapper or did not finish its 4 samples")
    with open(log) as f:
        calls = f.read().splitlines()
    if len(calls) != 1 or not calls[0].startswith(f"-np 2 --oversubscribe {args.lmp} -partition 2x1 -in "):
        fail(f"the wrapper was not the one launcher of the 2 partitions: {calls}")
    if law_without_run(law) != law_without_run(law_default):
        fail("the law through the wrapper differs from the default launcher's")
    print(f"check_homogenise: launcher: cold {cold:.2f} s through the wrapper")


def mode_launcher_alone(args):
    work, case = setup(args, "launcher_alone")
    _, log, _ = write_wrapper(work)
    with open(case, "a") as f:
        f.write('[run]\nlauncher = "./launch.sh -np {np} --oversubscribe"\n')
    if os.path.samefile(os.getcwd(), work):
        fail("run from the case's directory: ./launch.sh would not test the lookup beside the case file")
    deck = failing_deck(args, work, f"${{pressure}} > 3.0e6 && ${{seed}} == {SEED_1}")
    homogenise(args, case, os.path.join(work, "law_fail.json"), os.path.join(work, "cache_fail"), deck, 1)
    with open(log) as f:
        calls = f.read().splitlines()
    alone = [c for c in calls if c.startswith(f"-np 1 --oversubscribe {args.lmp} -in ")]
    if not calls or not calls[0].startswith(f"-np 2 --oversubscribe {args.lmp} -partition 2x1 ") \
            or len(alone) != len(calls) - 1 or not alone:
        fail(f"the samples run alone did not go through the wrapper: {calls}")
    print(f"check_homogenise: launcher: {len(alone)} sample(s) alone through the wrapper after the failure")


def mode_interrupt(args):
    import signal
    work = os.path.abspath(args.workdir)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(work, "case.toml")
    with open(case, "w") as f:
        # samples of several seconds: mpirun takes about a second to stop its ranks after SIGTERM
        f.write(CASE.format(material=args.material).replace("nside = 6", "nside = 24")
                .replace("depth = 2.0e-9", "depth = 3.0e-8").replace("nslide = 4000", "nslide = 200000")
                .replace("acceleration = [2000.0, 1000.0]", "acceleration = [30.0, 15.0]"))
    cache, law = os.path.join(work, "cache"), os.path.join(work, "law.json")
    command = [args.runin, "homogenise", case, "--output", law, "--cache-dir", cache, "--np", "2", "--lmp", args.lmp]
    if args.deck != "default":
        command += ["--deck", args.deck]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in proc.stdout:
        if "sample 1/4 done" in line:
            break
    else:
        fail("the run ended before its first sample: " + proc.stderr.read())
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    if proc.returncode != 1 or "interrupted by signal 15" not in err or len(err.strip().splitlines()) != 1:
        fail(f"after SIGTERM: exit {proc.returncode}, stderr {err!r}")
    time.sleep(0.5)
    left = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmdline = f.read()
        except OSError:
            continue
        if work.encode() in cmdline and (b"lmp_runin" in cmdline or b"mpirun" in cmdline or b"runin" in cmdline):
            left.append(cmdline.replace(b"\0", b" ").decode(errors="replace")[:120])
    if left:
        fail(f"processes left running after SIGTERM: {left}")
    if os.path.exists(law):
        fail("a law was written by the interrupted run")
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"rerun failed: {result.stderr}")
    todo = [l for l in result.stdout.splitlines() if "samples to run" in l]
    if not todo or not 0 < int(todo[0].split("runin homogenise: ")[1].split()[0]) < 4:
        fail(f"the rerun should run the stopped samples and reuse the finished ones: {todo}")
    print("interrupt: " + err.strip() + "; rerun: " + todo[0])


def physics_identity(args, source_dir, output):
    """The identity physics_identity.cmake computes for the sources under source_dir (the build's list)."""
    subprocess.run([args.cmake, f"-DSOURCE_DIR={source_dir}", f"-DLIST={args.physics_list}",
                    f"-DCONFIG={args.physics_config}", f"-DOUTPUT={output}", "-P", args.physics_script], check=True)
    with open(output) as f:
        return f.read()


def mode_relink(args):
    work, case = setup(args, "relink")
    with open(case) as f:
        text = f.read()
    with open(case, "w") as f:  # one seed: 2 samples, one per partition
        f.write(text.replace("seeds = 2", "seeds = 1"))
    physics = args.lmp + ".physics"
    if not os.path.isfile(physics):
        fail(f"no {physics}: the build did not write lmp_runin's physics identity")
    with open(physics) as f:
        built = f.read()
    # (a) the build's identity is that of the sources as they are
    if physics_identity(args, args.source_dir, os.path.join(work, "identity_now")) != built:
        fail(f"{physics} is not the identity of the current physics sources: the build did not regenerate it")

    law, cache = os.path.join(work, "law.json"), os.path.join(work, "cache")
    cold, _ = homogenise(args, case, law, cache, args.deck, 0)
    if "2 samples to run" not in cold.stdout:
        fail("the cold run did not run its 2 samples")

    # (b) a relink: other bytes, the same physics
    bindir = os.path.join(work, "bin")
    os.makedirs(bindir)
    relinked = os.path.join(bindir, "lmp_runin")
    shutil.copy2(args.lmp, relinked)
    with open(relinked, "ab") as f:
        f.write(b"\0relinked\0")
    shutil.copy2(physics, relinked + ".physics")
    relinked_args = argparse.Namespace(**{**vars(args), "lmp": relinked})
    law2 = os.path.join(work, "law_relinked.json")
    again, _ = homogenise(relinked_args, case, law2, cache, args.deck, 0)
    if "0 samples to run" not in again.stdout or "mpirun" in again.stdout:
        fail("a relinked lmp_runin with the same physics did not take the samples from the cache")
    with open(law) as f:
        first = json.load(f)
    with open(law2) as f:
        second = json.load(f)
    lmp1, lmp2 = first["provenance"]["lmp"], second["provenance"]["lmp"]
    if lmp1["sha256"] == lmp2["sha256"] or lmp1.get("physics_sha256") != built.splitlines()[0] \
            or lmp2.get("physics_sha256") != lmp1["physics_sha256"]:
        fail(f"provenance.lmp: {lmp1} then {lmp2}: expected two executables with the one physics identity")
    if second["fields"] != first["fields"]:
        fail("the law from the cache differs")

    # (c) a physics source changed: another identity, every sample again
    tree = os.path.join(work, "src")
    with open(args.physics_list) as f:
        sources = [line.strip() for line in f if line.strip()]
    for name in sources:
        os.makedirs(os.path.dirname(os.path.join(tree, name)), exist_ok=True)
        shutil.copy2(os.path.join(args.source_dir, name), os.path.join(tree, name))
    changed = next(name for name in sources if name.startswith("src/tribo/") and name.endswith(".cpp"))
    with open(os.path.join(tree, changed), "a") as f:
        f.write("// a changed physics source\n")
    other = physics_identity(args, tree, os.path.join(work, "identity_changed"))
    if other.splitlines()[0] == built.splitlines()[0]:
        fail(f"a change of {changed} did not change the physics identity")
    with open(relinked + ".physics", "w") as f:
        f.write(other)
    rebuilt, _ = homogenise(relinked_args, case, os.path.join(work, "law_changed.json"), cache, args.deck, 0)
    if "2 samples to run" not in rebuilt.stdout:
        fail(f"an lmp_runin built from a changed {changed} did not run the samples again")

    # (d) the same executable, a changed deck
    shutil.copy2(physics, relinked + ".physics")
    deck = os.path.join(work, "in.deck_changed")
    with open(args.deck) as f:
        text = f.read()
    with open(deck, "w") as f:
        f.write(text + "# a changed deck\n")
    redecked, _ = homogenise(relinked_args, case, os.path.join(work, "law_deck.json"), cache, deck, 0)
    if "2 samples to run" not in redecked.stdout:
        fail("a changed deck did not run the samples again")
    print(f"check_homogenise: relink: cached; {changed} changed: rerun; deck changed: rerun")


def main():
    parser = argparse.ArgumentParser()
    for option in ("--runin", "--lmp", "--reader", "--deck", "--workdir", "--material"):
        parser.add_argument(option, required=True)
    modes = {"build": mode_build, "fail": mode_fail, "interrupt": mode_interrupt, "launcher": mode_launcher,
             "launcher_alone": mode_launcher_alone, "extra": mode_extra, "relink": mode_relink}
    parser.add_argument("--mode", choices=list(modes), required=True)
    for option in ("--cmake", "--source-dir", "--physics-script", "--physics-list", "--physics-config"):
        parser.add_argument(option)  # mode relink
    args = parser.parse_args()
    modes[args.mode](args)
    print("check_homogenise: ok")


if __name__ == "__main__":
    main()
