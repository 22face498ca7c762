#!/usr/bin/python3
"""Sensitivity of a machine element to the micro contact law's own parameters (d_c, the slip distance of the
static-to-kinetic drop, and e, the coefficient of restitution), which reach the continuum only through the
fitted friction law: for each value, the micro rough slider (inputs/in.rough_slider, pair runin/asperity with
the Cu/Al coefficient file edited in that one number) -> `runin fit-law` on mu_body -> the element with
`--law`. Writes DIR/sweep.csv in the format of `runin sweep` (so tools/plot_sweep.py draws it) and keeps every
run's coefficient file, micro output, law and element output under DIR/runs/ (each row reruns from them).

  /usr/bin/python3 tools/sweep_micro_law.py --lmp build/lmp_runin --runin build/runin \\
      --element journal-bearing --case inputs/journal_bearing_micro.toml --output-dir out/sweep_micro [--np 1]

Values span one decade, log-spaced, centred on the file's value, or ending at it where the law bounds the
parameter (e <= 1). A failed run is a row with its message; the others are kept (exit 1).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

HERE = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
COEFFS = os.path.join(HERE, "potentials", "CuAl.runin")
DECK = os.path.join(HERE, "inputs", "in.rough_slider")
NUMBERS = ["peak_friction_force_N", "peak_time_s", "breakaway_time_s", "steady_time_s", "steady_mu", "wear_volume_m3"]
PREFIX = {"pin-on-disk": "pin_on_disk", "journal-bearing": "journal_bearing", "piston-ring": "piston_ring"}
# column of the 'pair Cu Al e mu_s mu_k d_c k' line, and the largest value the law accepts
KEYS = {"d_c": (6, None), "e": (3, 1.0)}


def factors_for(value, upper, span, points):
    factors = [span ** (i / (points - 1) - 0.5) for i in range(points)]
    if upper is not None and value * factors[-1] > upper:    # end the decade at the file's value
        factors = [span ** (i / (points - 1) - 1.0) for i in range(points)]
    return factors


def edited_coefficients(text, column, factor):
    lines = []
    for line in text.splitlines():
        words = line.split("#")[0].split()
        if words[:3] == ["pair", "Cu", "Al"]:
            words[column] = repr(float(words[column]) * factor)
            line = " ".join(words)
        lines.append(line)
    return "\n".join(lines) + "\n"


def pair_value(text, column):
    for line in text.splitlines():
        words = line.split("#")[0].split()
        if words[:3] == ["pair", "Cu", "Al"]:
            return float(words[column])
    sys.exit(f"sweep_micro_law: no 'pair Cu Al' line in {COEFFS}")


def run(command, cwd, log):
    with open(log, "w") as f:
        result = subprocess.run(command, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if result.returncode != 0:
        with open(log) as f:
            lines = [line.strip() for line in f if line.strip()]
        raise RuntimeError(next((line for line in reversed(lines) if "ERROR" in line or "error" in line),
                                lines[-1] if lines else f"exit {result.returncode}"))


def one_run(args, directory, coefficients):
    os.makedirs(directory, exist_ok=True)
    coeff_file = os.path.join(directory, "CuAl.runin")
    with open(coeff_file, "w") as f:
        f.write(coefficients)
    lmp = [args.lmp, "-in", DECK, "-var", "coeffs", coeff_file, "-var", "out", "friction.dat", "-log", "log.lammps",
           "-screen", "none"]
    if args.np > 1:
        lmp = [args.mpiexec, "-np", str(args.np)] + lmp
    run(lmp, directory, os.path.join(directory, "micro.out"))
    run([args.runin, "fit-law", "--input", "friction.dat", "--distance-column", "v_slide", "--mu-column", "c_fric[16]",
         "--output", "law.json"], directory, os.path.join(directory, "fit.out"))
    run([args.runin, args.element, os.path.abspath(args.case), "--law", "law.json", "--output-dir", "element",
         "--no-plot"], directory, os.path.join(directory, "element.out"))
    with open(os.path.join(directory, "element", PREFIX[args.element] + "_summary.csv"), newline="") as f:
        return next(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--runin", required=True)
    parser.add_argument("--mpiexec", default="mpiexec")
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--element", required=True, choices=sorted(PREFIX))
    parser.add_argument("--case", required=True, help="an element case with friction.model = 'law_file'")
    parser.add_argument("--output-dir", required=True)
    parser.add_argument("--key", action="append", choices=sorted(KEYS), help="default: d_c and e")
    parser.add_argument("--span", type=float, default=10.0)
    parser.add_argument("--points", type=int, default=3)
    parser.add_argument("--no-plot", action="store_true")
    args = parser.parse_args()
    args.lmp, args.runin = os.path.abspath(args.lmp), os.path.abspath(args.runin)  # the runs change directory
    if not args.span > 1.0 or args.points < 3 or args.points % 2 == 0:
        sys.exit("sweep_micro_law: --span must be > 1 and --points odd >= 3")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    os.environ.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    with open(COEFFS) as f:
        base_text = f.read()
    staging = args.output_dir.rstrip("/") + ".part"
    shutil.rmtree(staging, ignore_errors=True)
    os.makedirs(staging)
    runs, failed = {}, 0

    def cached(name, coefficients):
        nonlocal failed
        if name not in runs:
            try:
                runs[name] = (one_run(args, os.path.join(staging, "runs", name), coefficients), "ok")
            except RuntimeError as e:
                runs[name] = (None, "failed: " + str(e))
                failed += 1
            print(f"sweep_micro_law: {name}: {runs[name][1]}", flush=True)
        return runs[name]

    rows = []
    for key in args.key or sorted(KEYS):
        column, upper = KEYS[key]
        value = pair_value(base_text, column)
        for factor in factors_for(value, upper, args.span, args.points):
            name = "base" if factor == 1.0 else f"{key}_{factor:.4g}"
            summary, status = cached(name, edited_coefficients(base_text, column, factor) if name != "base" else base_text)
            rows.append([key, f"{factor:.12g}", f"{value * factor:.12g}"] +
                        ([summary[n] for n in NUMBERS] if summary else [""] * len(NUMBERS)) +
                        [f"runs/{name}", status])
    with open(os.path.join(staging, "sweep.csv"), "w", newline="") as f:
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["key", "factor", "value"] + NUMBERS + ["case", "status"])
        writer.writerows(rows)
    if not args.no_plot:
        subprocess.run(["/usr/bin/python3", os.path.join(HERE, "tools", "plot_sweep.py"),
                        os.path.join(staging, "sweep.csv"), os.path.join(staging, "sweep_tornado.png"), "--title",
                        f"{args.element} with the micro law: d_c and restitution"], check=True)
    shutil.rmtree(args.output_dir, ignore_errors=True)
    os.replace(staging, args.output_dir)
    print(f"sweep_micro_law: {len(rows)} rows, {len(runs)} runs, {failed} failed -> {args.output_dir}/sweep.csv")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
