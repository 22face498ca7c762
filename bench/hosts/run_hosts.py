#!/usr/bin/python3
"""RunIn on two LAMMPS hosts, timed side by side: the contact-dense scene bench/micro/in.dense with
(a) stock pair gran/hertz/history, (d) runin/asperity lean and (c) runin/asperity with all physics, in
Debian's 29Sep2021 (lmp_runin) and as runinplugin.so in the stock lmp of 4Feb2025. Runs are interleaved
(host x style, `--repeats` rounds) and reduced to medians of the Pair time and the loop time; ratios are taken
within one invocation only. Writes a Markdown table to stdout (or --doc).

  /usr/bin/python3 bench/hosts/run_hosts.py --lmp-runin build/lmp_runin \\
      --lmp-current .cache/lammps-current/build/lmp --plugin-dir build-lammps-current [--repeats 3] [--np 1]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MICRO = os.path.join(SOURCE_DIR, "bench", "micro")
STYLES = {"a": ("stock gran/hertz/history", "pair_gran_hertz.in"),
          "d": ("runin/asperity lean (wear no, friction coulomb)", "pair_runin_lean.in"),
          "c": ("runin/asperity all physics (wear, reshape, transfer, strength, re-stick)", "pair_runin_full.in")}
LOOP_RE = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps")
PAIR_RE = re.compile(r"^Pair\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]+)", re.M)


def run(command, env, workdir):
    result = subprocess.run(command, cwd=workdir, env=env, capture_output=True, text=True)
    log = open(os.path.join(workdir, "log.lammps")).read() if os.path.exists(os.path.join(workdir, "log.lammps")) else ""
    if result.returncode != 0 or "ERROR" in log:
        sys.exit(f"run_hosts: {' '.join(command)} failed ({result.returncode}):\n{result.stdout[-1500:]}{log[-1500:]}")
    loops, pairs = LOOP_RE.findall(log), PAIR_RE.findall(log)
    if len(loops) < 2 or len(pairs) < 2:
        sys.exit(f"run_hosts: no timed run in the log of {' '.join(command)}")
    return float(loops[-1][0]), float(pairs[-1][1])    # the sliding run: loop time, average Pair time


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp-runin", required=True)
    parser.add_argument("--lmp-current", required=True)
    parser.add_argument("--plugin-dir", required=True, help="directory holding runinplugin.so for --lmp-current")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--nside", type=int, default=50)
    parser.add_argument("--nsettle", type=int, default=300)
    parser.add_argument("--nslide", type=int, default=600)
    parser.add_argument("--doc", help="write the table here instead of stdout")
    args = parser.parse_args()

    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMP_NUM_THREADS="1")
    env.pop("LAMMPS_PLUGIN_PATH", None)
    hosts = {"29Sep2021 lmp_runin": ([os.path.abspath(args.lmp_runin)], env),
             "4Feb2025 lmp + plugin": ([os.path.abspath(args.lmp_current)],
                                       dict(env, LAMMPS_PLUGIN_PATH=os.path.abspath(args.plugin_dir)))}
    times = {(host, key): [] for host in hosts for key in STYLES}
    with tempfile.TemporaryDirectory() as workdir:
        for round_ in range(args.repeats):
            for key in STYLES:
                for host, (lmp, host_env) in hosts.items():
                    command = lmp + ["-in", os.path.join(MICRO, "in.dense"), "-log", "log.lammps", "-screen", "none",
                                     "-var", "pairfile", os.path.join(MICRO, STYLES[key][1]),
                                     "-var", "coeffs", os.path.join(SOURCE_DIR, "potentials", "CuAl.runin"),
                                     "-var", "nside", str(args.nside), "-var", "nsettle", str(args.nsettle),
                                     "-var", "nslide", str(args.nslide)]
                    if args.np > 1:
                        command = ["mpiexec", "-np", str(args.np)] + command
                    times[(host, key)].append(run(command, host_env, workdir))
                    print(f"run_hosts: round {round_ + 1}/{args.repeats} {key} {host}: loop {times[(host, key)][-1][0]:.3f} s",
                          file=sys.stderr)
    median = {k: (statistics.median(t[0] for t in v), statistics.median(t[1] for t in v)) for k, v in times.items()}
    old, new = list(hosts)
    lines = [f"in.dense, nside {args.nside}, {args.nslide} timed steps after {args.nsettle}, {args.np} rank(s), "
             f"medians of {args.repeats} interleaved rounds (seconds).", "",
             "| style | 29Sep2021 loop | 29Sep2021 Pair | 4Feb2025 loop | 4Feb2025 Pair | Pair 2021 / 2025 (> 1: plugin in 4Feb2025 faster) | Pair (a) / this style, 4Feb2025 |",
             "|---|---|---|---|---|---|---|"]
    for key, (label, _) in STYLES.items():
        (lo, po), (ln, pn) = median[(old, key)], median[(new, key)]
        lines.append(f"| ({key}) {label} | {lo:.3f} | {po:.3f} | {ln:.3f} | {pn:.3f} | {po / pn:.3f} | "
                     f"{median[(new, 'a')][1] / pn:.3f} |")
    text = "\n".join(lines) + "\n"
    if args.doc:
        with open(args.doc + ".tmp", "w") as f:
            f.write(text)
        os.replace(args.doc + ".tmp", args.doc)
    print(text)


if __name__ == "__main__":
    main()
