#!/usr/bin/env python3
"""RunIn in LIGGGHTS against LIGGGHTS's own granular pair on the same scene (bench/liggghts/README.md).

  python3 bench/liggghts/bench.py --liggghts build/liggghts_runin [--np 1] [--repeat 3] [--nsettle 2000] [--nslide 8000]

The scene is tests/liggghts/decks/in.rough_slider (1741 asperities, load-controlled slider, 10 ns steps). Two decks
are made from it that differ only in the contact law: 'runin' keeps pair runin/asperity (elastic/plastic normal,
Mindlin/Coulomb static->kinetic, Archard wear with worn geometry), 'gran' replaces it with
'pair_style gran model hertz tangential history' on the same materials (E, nu of Al and Cu, e = 0.5,
mu = mu_k = 0.55). Neither prints RunIn's computes (the gran run cannot have them): thermo is the step only. Both
print the step and the slider's height; they run in the same binary, alternating, 'repeat' times; the best loop time of each is kept. Ratio = gran / runin
(>= 1: RunIn is at least as fast).
"""
import argparse
import os
import re
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


def make_deck(kind, path):
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
        if kind == "gran" and stripped.startswith("pair_coeff"):
            continue
        if kind == "gran" and stripped.startswith("pair_style"):
            out.append(GRAN)
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
    args = parser.parse_args()
    args.liggghts = os.path.abspath(args.liggghts)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMP_NUM_THREADS="1")
    work = tempfile.mkdtemp(prefix="runin_bench_liggghts_")
    os.symlink(os.path.join(SOURCE, "potentials"), os.path.join(work, "potentials"))
    best, heights = {}, {}
    for kind in ("runin", "gran"):
        make_deck(kind, os.path.join(work, f"in.{kind}"))
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
            if kind not in best or total < best[kind][0]:
                best[kind] = (total, pair)
    steps = args.nsettle + args.nslide
    for kind in ("runin", "gran"):
        total, pair = best[kind]
        print(f"{kind:6s} loop {total:8.3f} s  pair {pair:8.3f} s  ({steps} steps, {args.np} rank(s), best of "
              f"{args.repeat})")
    print(f"ratio gran/runin: loop {best['gran'][0] / best['runin'][0]:.2f}x, pair "
          f"{best['gran'][1] / best['runin'][1]:.2f}x")
    print(f"slider centre height at the end: runin {heights['runin']:.9g} m, gran {heights['gran']:.9g} m (both "
          f"carry the load on their contacts)")
    print(f"decks and logs: {work}")


if __name__ == "__main__":
    main()
