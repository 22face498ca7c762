#!/usr/bin/env python3
"""RunIn in LIGGGHTS against LIGGGHTS's own granular pair on the same scene (bench/liggghts/README.md).

  python3 bench/liggghts/bench.py --liggghts build/liggghts_runin [--np 1] [--repeat 3] [--nsettle 2000] [--nslide 8000]
                                  [--variant full|lean]

The scene is tests/liggghts/decks/in.rough_slider (1741 asperities, load-controlled slider, 10 ns steps). Two decks
are made from it that differ only in the contact law: 'runin' keeps pair runin/asperity (elastic/plastic normal,
Mindlin/Coulomb static->kinetic, Archard wear with worn geometry), 'gran' replaces it with
'pair_style gran model hertz tangential history' on the same materials (E, nu of Al and Cu, e = 0.5,
mu = mu_k = 0.55). Neither prints RunIn's computes (the gran run cannot have them): thermo is the step only. Both
print the step and the slider's height; they run in the same binary, alternating, 'repeat' times; the median and
the best loop and Pair times of each are printed. Ratio = gran / runin (>= 1: RunIn is at least as fast).

--variant lean: the same physics on both sides, for a like-for-like cost of the contact law: RunIn with
'normal hertz', its default Mindlin spring and Coulomb limit, restitution damping, 'wear no reshape no' (no wear
state, nothing sent to ghosts), and the same E* and G* as LIGGGHTS derives from E and nu of Al and Cu, e = 0.5,
mu_s = mu_k = 0.55. --variant full (default): RunIn's law of the scene (elastic/plastic, wear, worn geometry).
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", ".."))
DECK = os.path.join(SOURCE, "tests", "liggghts", "decks", "in.rough_slider")

GRAN = """hard_particles  yes
fix             m1 all property/global youngsModulus peratomtype 69.0e9 110.0e9
fix             m2 all property/global poissonsRatio peratomtype 0.33 0.37
fix             m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix             m4 all property/global coefficientFriction peratomtypepair 2 0.55 0.55 0.55 0.55
pair_style      gran model hertz tangential history
pair_coeff      * *
"""


def lean_coeff():
    """pair_style/pair_coeff of RunIn with LIGGGHTS's E* and G* of the gran deck (Al, Cu)."""
    (e1, n1), (e2, n2) = (69.0e9, 0.33), (110.0e9, 0.37)
    estar = 1.0 / ((1.0 - n1 * n1) / e1 + (1.0 - n2 * n2) / e2)
    gstar = 1.0 / (2.0 * (2.0 - n1) * (1.0 + n1) / e1 + 2.0 * (2.0 - n2) * (1.0 + n2) / e2)
    return ("pair_style      runin/asperity wear no reshape no normal hertz friction coulomb\n"
            f"pair_coeff      * * {estar!r} {gstar!r} 0.5 0.55 0.55 1.0e-8 0.0 0.245e9\n")


def make_deck(kind, path, variant="full"):
    out = []
    skip_continuation = False
    for line in open(DECK):
        stripped = line.strip()
        if skip_continuation:
            skip_continuation = stripped.endswith("&")
            continue
        if stripped.startswith(("compute ", "print ", "fix             out", "variable        p_real")):
            continue
        if stripped.startswith(("thermo_style", "thermo_modify")):
            skip_continuation = stripped.endswith("&")
            if stripped.startswith("thermo_style"):
                out.append("variable        zs equal xcm(slider,z)\nthermo_style    custom step v_zs\n")
            continue
        replace = kind == "gran" or variant == "lean"
        if replace and stripped.startswith("pair_coeff"):
            continue
        if replace and stripped.startswith("pair_style"):
            out.append(GRAN if kind == "gran" else lean_coeff())
            continue
        out.append(line)
    open(path, "w").write("".join(out))


def loop_time(log):
    times = [float(m) for m in re.findall(r"Loop time of ([0-9.eE+-]+) on", log)]
    pair = [float(m) for m in re.findall(r"Pair\s+time \(%\) = ([0-9.eE+-]+)", log)]
    return sum(times), sum(pair)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--liggghts", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--nsettle", type=int, default=2000)
    parser.add_argument("--nslide", type=int, default=8000)
    parser.add_argument("--variant", choices=("full", "lean"), default="full")
    args = parser.parse_args()
    args.liggghts = os.path.abspath(args.liggghts)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMP_NUM_THREADS="1")
    work = tempfile.mkdtemp(prefix="runin_bench_liggghts_")
    os.symlink(os.path.join(SOURCE, "potentials"), os.path.join(work, "potentials"))
    times, heights = {"runin": [], "gran": []}, {}
    for kind in ("runin", "gran"):
        make_deck(kind, os.path.join(work, f"in.{kind}"), args.variant)
    for _ in range(args.repeat):
        for kind in ("runin", "gran"):
            command = [args.liggghts, "-st", "-in", f"in.{kind}", "-log", f"log.{kind}", "-screen", "none",
                       "-var", "nsettle", str(args.nsettle), "-var", "nslide", str(args.nslide),
                       "-var", "thermo_every", "1000"]
            if args.np > 1:
                command = [args.mpiexec, "-np", str(args.np)] + command
            result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, errors="replace")
            log = open(os.path.join(work, f"log.{kind}")).read()
            if result.returncode != 0:
                raise SystemExit(f"{kind}: exit {result.returncode}\n{result.stdout[-1500:]}\n{log[-1500:]}")
            total, pair = loop_time(log)
            rows = re.findall(r"^\s*(\d+)\s+([-0-9.eE+]+)\s*$", log, re.M)
            heights[kind] = float(rows[-1][1]) if rows else float("nan")
            times[kind].append((total, pair))
    steps = args.nsettle + args.nslide
    stats = {}
    for kind in ("runin", "gran"):
        loops, pairs = [t[0] for t in times[kind]], [t[1] for t in times[kind]]
        stats[kind] = (statistics.median(loops), statistics.median(pairs), min(loops), min(pairs))
        print(f"{kind:6s} loop median {stats[kind][0]:8.3f} s (best {stats[kind][2]:.3f})  pair median "
              f"{stats[kind][1]:8.3f} s (best {stats[kind][3]:.3f})  ({steps} steps, {args.np} rank(s), "
              f"{args.repeat} runs, variant {args.variant})")
    for label, k in (("median", 0), ("best", 2)):
        print(f"ratio gran/runin ({label}): loop {stats['gran'][k] / stats['runin'][k]:.2f}x, pair "
              f"{stats['gran'][k + 1] / stats['runin'][k + 1]:.2f}x")
    print(f"slider centre height at the end: runin {heights['runin']:.9g} m, gran {heights['gran']:.9g} m (both "
          f"carry the load on their contacts)")
    print(f"decks and logs: {work}")


if __name__ == "__main__":
    main()
