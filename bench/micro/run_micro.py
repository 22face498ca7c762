#!/usr/bin/python3
"""RunIn micro-scale benchmarks: throughput against the stock granular styles, 1 -> 2 rank speed-up,
timestep convergence of wear and mu_eff. Writes doc/benchmarks-micro.md and PNG plots.

  bench/run-micro [--quick]        (wrapper: finds lmp_runin, runs this with /usr/bin/python3)
  /usr/bin/python3 bench/micro/run_micro.py --lmp BUILD/lmp_runin [--out DIR] [--doc FILE] [--quick]
"""
import argparse
import datetime
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DECK = os.path.join(SOURCE_DIR, "bench", "micro", "in.slab")
SHORT_LABELS = {"a": "(a) gran/hertz/history", "b": "(b) granular", "c": "(c) runin, all physics",
                "d": "(d) runin, lean"}
STYLES = {   # key: (label, pair file)
    "a": ("gran/hertz/history (stock)", "pair_gran_hertz.in"),
    "b": ("granular hertz/material + mindlin (stock)", "pair_granular.in"),
    "c": ("runin/asperity, all physics (wear, reshape, transfer 0.3, adhesion + ploughing, re-stick)",
          "pair_runin_full.in"),
    "d": ("runin/asperity, wear no, friction coulomb", "pair_runin_lean.in"),
}
TIMER_ROWS = ("Pair", "Neigh", "Comm", "Output", "Modify", "Other")


def mpi_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env["OMP_NUM_THREADS"] = "1"
    # waiting ranks yield the core: on a shared machine busy-polling ranks slowed 2 ranks by 10x
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


def run_deck(lmp, workdir, variables, np=1):
    """Run in.slab; return the last run's loop time, timer breakdown, atoms, steps and thermo rows."""
    os.makedirs(workdir, exist_ok=True)
    command = [lmp, "-in", DECK, "-log", "log.lammps", "-screen", "none"]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    if np > 1:
        command = ["mpirun", "-np", str(np), "--bind-to", "none"] + command
    result = subprocess.run(command, cwd=workdir, env=mpi_env(),
                            capture_output=True, text=True)
    log = open(os.path.join(workdir, "log.lammps")).read() if os.path.exists(
        os.path.join(workdir, "log.lammps")) else ""
    if result.returncode != 0:
        sys.exit(f"run-micro: lmp_runin failed in {workdir} ({' '.join(command)}):\n{log[-1500:]}{result.stderr}")
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)
    loop, procs, steps, atoms = float(loops[-1][0]), int(loops[-1][1]), int(loops[-1][2]), int(loops[-1][3])
    last = log[log.rfind("Loop time of"):]
    timers = {}
    for row in TIMER_ROWS:
        m = re.search(rf"^{row}\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", last, re.M)
        timers[row] = float(m.group(1)) if m else 0.0
    cpu = re.findall(r"([0-9.]+)% CPU use with", log)
    cpu_fraction = float(cpu[-1]) / 100.0 if cpu else 1.0
    pair_spread = re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)", last, re.M)
    neighbors = re.findall(r"Total # of neighbors = (\d+)", log)
    header, rows = None, []
    for line in log[log.rfind("Step"):].splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = words
        elif header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                pass
    return {"pair_min_max": (float(pair_spread.group(1)), float(pair_spread.group(2))) if pair_spread else (0, 0),
            "cpu_fraction": cpu_fraction, "loop": loop, "cpu": loop * cpu_fraction, "load": os.getloadavg()[0], "procs": procs, "steps": steps, "atoms": atoms, "timers": timers,
            "neighbors": int(neighbors[-1]) if neighbors else 0, "rows": rows}


def rayleigh_time_al_slab():
    """t_R the guard computes for the slab: Al density, R = 1 um, the like-material equivalent of the
    Cu/Al pair's E* and G* (src/tribo/stability.cpp, equivalent_material and rayleigh_time)."""
    mats = {}
    for line in open(os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")):
        w = line.split("#")[0].split()
        if w and w[0] == "material":
            mats[w[1]] = (float(w[2]), float(w[3]))
    (e1, n1), (e2, n2) = mats["Cu"], mats["Al"]
    e_eff = 1.0 / ((1 - n1 ** 2) / e1 + (1 - n2 ** 2) / e2)
    g1, g2 = e1 / (2 * (1 + n1)), e2 / (2 * (1 + n2))
    g_eff = 1.0 / ((2 - n1) / g1 + (2 - n2) / g2)
    r = g_eff / e_eff
    nu = (1 - 4 * r) / (1 - 2 * r)
    shear = 2 * (1 - nu * nu) * e_eff / (2 * (1 + nu))
    return math.pi * 1.0e-6 * math.sqrt(2700.0 / shear) / (0.1631 * nu + 0.8766)


def median(values):
    return statistics.median(values)


def throughput(lmp, out, quick):
    nside, nsettle, nslide, repeats = (40, 1000, 400, 2) if quick else (87, 1500, 5000, 9)
    coeffs = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
    results = {key: [] for key in STYLES}
    for repeat in range(repeats):
        for key, (_, pairfile) in STYLES.items():    # interleaved: a b c d a b c d ...
            r = run_deck(lmp, os.path.join(out, "throughput", f"{key}{repeat}"),
                         {"pairfile": os.path.join(SOURCE_DIR, "bench", "micro", pairfile), "coeffs": coeffs,
                          "nside": nside, "nsettle": nsettle, "nslide": nslide})
            r["wall_rate"] = r["atoms"] * r["steps"] / r["loop"]
            r["rate"] = r["atoms"] * r["steps"] / r["cpu"]
            results[key].append(r)
            print(f"  throughput {key} repeat {repeat}: {r['rate']:.4g} atom-steps per CPU-s, "
                  f"{r['wall_rate']:.4g} per wall-s, load {r['load']:.1f} "
                  f"(pair {r['timers']['Pair']:.3f} s of {r['loop']:.3f} s)", flush=True)
    summary = {}
    for key, runs in results.items():
        summary[key] = {
            "rate": median([r["rate"] for r in runs]),
            "rates": [r["rate"] for r in runs],
            "wall_rate": median([r["wall_rate"] for r in runs]),
            "loads": [r["load"] for r in runs],
            "timers": {row: median([r["timers"][row] for r in runs]) for row in TIMER_ROWS},
            "loop": median([r["loop"] for r in runs]),
            "atoms": runs[0]["atoms"], "steps": runs[0]["steps"], "neighbors": runs[0]["neighbors"],
            "fz": runs[0]["rows"][-1].get("v_fz", float("nan")) if runs[0]["rows"] else float("nan"),
        }
        # ratio per repeat against the a-run of the same repeat: pairs the noise of a shared machine
    paired = {key: [results[key][k]["rate"] / results["a"][k]["rate"] for k in range(repeats)] for key in STYLES}
    return {"summary": summary, "paired": paired, "nside": nside, "nsettle": nsettle, "nslide": nslide,
            "repeats": repeats}


def speedup(lmp, out, quick):
    nside, nsettle, nslide, repeats = (60, 800, 200, 1) if quick else (160, 1000, 1500, 3)
    coeffs = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
    times = {1: [], 2: []}
    sp_loads = []
    spreads = {1: [], 2: []}
    atoms = 0
    for repeat in range(repeats):
        for np in (1, 2):
            r = run_deck(lmp, os.path.join(out, "speedup", f"np{np}_{repeat}"),
                         {"pairfile": os.path.join(SOURCE_DIR, "bench", "micro", "pair_runin_full.in"),
                          "coeffs": coeffs, "nside": nside, "nsettle": nsettle, "nslide": nslide}, np=np)
            times[np].append(r["loop"])
            sp_loads.append(r["load"])
            spreads[np].append((r["pair_min_max"], r["cpu_fraction"]))
            atoms = r["atoms"]
            print(f"  speed-up np {np} repeat {repeat}: {r['loop']:.3f} s for {r['steps']} steps", flush=True)
    t1, t2 = median(times[1]), median(times[2])
    best = min(times[1]) / min(times[2])
    return {"best": best, "atoms": atoms, "nslide": nslide, "nsettle": nsettle, "nside": nside, "t1": t1, "t2": t2,
            "times": times, "speedup": t1 / t2, "repeats": repeats,
            "loads": sp_loads, "spreads": spreads}


def convergence(lmp, out, quick):
    """Same physical settle and slide times at every dt; error against the finest dt."""
    settle_time, slide_time = (1.5e-7, 1.0e-7) if quick else (3.0e-7, 4.0e-7)
    dts = [4e-10, 2e-10, 1e-10, 5e-11, 2.5e-11] if not quick else [4e-10, 2e-10, 1e-10, 5e-11]
    reference_dt = 1.25e-11 if not quick else 2.5e-11
    coeffs = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
    points = []
    for dt in dts + [reference_dt]:
        nsettle, nslide = int(round(settle_time / dt)), int(round(slide_time / dt))
        r = run_deck(lmp, os.path.join(out, "convergence", f"dt{dt:.3g}"),
                     {"pairfile": os.path.join(SOURCE_DIR, "bench", "micro", "pair_runin_full.in"),
                      "coeffs": coeffs, "nside": 30, "nsettle": nsettle, "nslide": nslide, "dt": dt,
                      "friction": "yes", "thermo_every": max(1, nslide // 40)})
        rows = r["rows"]
        late = [row["c_fric[3]"] for row in rows if row["Step"] >= nsettle + nslide // 2]
        points.append({"dt": dt, "wear": rows[-1]["c_fric[5]"], "mu": sum(late) / len(late), "time": r["loop"],
                       "steps": nslide})
        print(f"  convergence dt {dt:.3g}: wear {points[-1]['wear']:.6g} m^3, mu_eff {points[-1]['mu']:.6g}, "
              f"{r['loop']:.2f} s", flush=True)
    reference = points[-1]
    for p in points:
        p["wear_error"] = abs(p["wear"] - reference["wear"]) / reference["wear"]
        p["mu_error"] = abs(p["mu"] - reference["mu"]) / reference["mu"]
    return {"points": points, "reference_dt": reference_dt, "settle_time": settle_time, "slide_time": slide_time}


def profile(lmp, out, quick):
    """perf profile (flat, by symbol) of the timed scene for (a), (c) and (d); None without perf."""
    if not shutil.which("perf"):
        return None
    nside, nsettle, nslide = (40, 600, 600) if quick else (60, 1000, 3000)
    coeffs = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
    tables = {}
    for key in ("a", "c", "d"):
        workdir = os.path.join(out, "profile", key)
        os.makedirs(workdir, exist_ok=True)
        data = os.path.join(workdir, "perf.data")
        command = ["perf", "record", "-q", "-F", "1999", "-o", data, lmp, "-in", DECK, "-log", "none", "-screen",
                   "none", "-var", "pairfile", os.path.join(SOURCE_DIR, "bench", "micro", STYLES[key][1]),
                   "-var", "coeffs", coeffs, "-var", "nside", str(nside), "-var", "nsettle", str(nsettle),
                   "-var", "nslide", str(nslide)]
        if subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True).returncode != 0:
            return None
        text = subprocess.run(["perf", "report", "-i", data, "--no-children", "--stdio", "-g", "none",
                               "--sort", "dso,symbol", "--percent-limit", "0.8"],
                              capture_output=True, text=True).stdout
        rows = []
        for line in text.splitlines():
            m = re.match(r"\s*([0-9.]+)%\s+(\S+)\s+\[.\]\s+(.+)$", line)
            if m and m.group(2) not in ("[kernel.kallsyms]", "ld-linux-x86-64.so.2"):
                rows.append((float(m.group(1)), m.group(2), re.sub(r"(\s+-)+\s*$", "", m.group(3)).strip()))
        tables[key] = rows[:14]
    return {"tables": tables, "nside": nside, "nsettle": nsettle, "nslide": nslide}


IMPACT_RAYLEIGH_TIME = 1.0894e-9    # Al, R = 1 um, rho = 2700: pi R sqrt(rho/G) / (0.1631 nu + 0.8766)


def impact_scan(lmp, out):
    """Rebound / approach speed of an undamped head-on impact (exact: 1) against dt / t_R."""
    factors, speeds = [0.1, 0.2, 0.5, 1.0, 1.5, 2.0, 3.0, 3.9], [0.2, 2.0, 20.0]
    deck = os.path.join(SOURCE_DIR, "bench", "micro", "in.impact")
    table = {}
    for speed in speeds:
        for factor in factors:
            workdir = os.path.join(out, "impact", f"v{speed}_f{factor}")
            os.makedirs(workdir, exist_ok=True)
            result = subprocess.run([lmp, "-in", deck, "-var", "dt", repr(factor * IMPACT_RAYLEIGH_TIME), "-var",
                                     "speed", repr(speed), "-log", "log.lammps", "-screen", "none"],
                                    cwd=workdir, env=mpi_env(), capture_output=True, text=True)
            log = open(os.path.join(workdir, "log.lammps")).read()
            if result.returncode != 0:
                sys.exit(f"run-micro: impact run failed in {workdir}:\n{log[-1500:]}")
            rows = [line.split() for line in log[log.rfind("Step"):].splitlines()[1:3]]
            table[(speed, factor)] = float(rows[-1][1]) / speed
    return {"factors": factors, "speeds": speeds, "table": table}


def rigid_block(lmp, out):
    """mu_eff of the slab scene (counter-body moved as one block) at dt = 3.9e-9 s vs 1e-10 s."""
    coeffs = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
    result = {}
    for dt in (1.0e-10, 3.9e-9):
        nsettle, nslide = int(round(3.0e-7 / dt)), int(round(4.0e-7 / dt))
        r = run_deck(lmp, os.path.join(out, "rigid_block", f"dt{dt:.3g}"),
                     {"pairfile": os.path.join(SOURCE_DIR, "bench", "micro", "pair_runin_full.in"),
                      "coeffs": coeffs, "nside": 30, "nsettle": nsettle, "nslide": nslide, "dt": dt,
                      "friction": "yes", "thermo_every": max(1, nslide // 20)})
        late = [row["c_fric[3]"] for row in r["rows"] if row["Step"] >= nsettle + nslide // 2]
        result[dt] = (sum(late) / len(late), r["rows"][-1]["c_fric[5]"])
    return result


def plot(tp, conv, img_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(img_dir, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    keys = list(STYLES)
    rates = [tp["summary"][k]["rate"] for k in keys]
    ratios = [statistics.median(tp["paired"][k]) for k in keys]
    ax.bar(keys, rates, color=["0.6", "0.45", "tab:blue", "tab:cyan"])
    for k, rate, ratio in zip(keys, rates, ratios):
        ax.text(k, rate, f"{ratio:.2f}", ha="center", va="bottom")
    ax.set_ylabel("atom-steps per CPU-second (median)")
    ax.set_title(f"{tp['summary']['a']['atoms']} atoms, ratio to (a) on the bars")
    ax.set_xticks(range(len(keys)), [SHORT_LABELS[k] for k in keys], fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(img_dir, "micro_throughput.png"), dpi=120)
    plt.close(fig)

    pts = [p for p in conv["points"] if p["dt"] != conv["reference_dt"]]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8.8, 3.6))
    ax1.loglog([p["dt"] for p in pts], [max(p["wear_error"], 1e-16) for p in pts], "o-", label="wear volume")
    ax1.loglog([p["dt"] for p in pts], [max(p["mu_error"], 1e-16) for p in pts], "s-", label="mu_eff")
    ax1.set_xlabel("dt [s]")
    ax1.set_ylabel(f"relative error vs dt = {conv['reference_dt']:.3g} s")
    ax1.legend()
    ax2.loglog([p["time"] for p in pts], [max(p["wear_error"], 1e-16) for p in pts], "o-", label="wear volume")
    ax2.loglog([p["time"] for p in pts], [max(p["mu_error"], 1e-16) for p in pts], "s-", label="mu_eff")
    ax2.set_xlabel("run time of the sliding run [s]")
    ax2.set_title("work-precision")
    ax2.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(img_dir, "micro_dt_convergence.png"), dpi=120)
    plt.close(fig)


def write_atomically(path, text):
    directory = os.path.dirname(os.path.abspath(path))
    os.makedirs(directory, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=".tmp-")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.replace(tmp, path)


# Reading of the profile: a note is printed when its symbol shows up in the (c) profile.
PROFILE_NOTES = [
    ("PairRuninAsperity::eval<",
     "`PairRuninAsperity::eval<WEAR, RESHAPE, STRENGTH, SUMS, EVFLAG>` is the whole force loop, compiled once per "
     "combination of features and picked once per step (OPT-package style). It runs in two passes: the touching "
     "pairs of the neighbor list are compacted without a branch per pair (whether a neighbor touches is close to "
     "random), then the contact forces run over them. The contact law of `src/tribo` is header-inline there "
     "(`flat_hertz_contact`: Sneddon's a, c, F, k with the square roots taken once, a Hertz branch for unworn "
     "pairs; `mindlin_spring`, whose slip increment needs no division; the damping; adhesion + ploughing); m* "
     "and R* come from one division; wear and transfer increments sit side by side per atom; contact sums are "
     "filled only when a `compute runin/friction` exists, and the finite-force check is one sum per contact "
     "(no pass over all atoms, no per-step MPI_Allreduce)."),
    ("PairRuninAsperity::compute",
     "`PairRuninAsperity::compute` adds each worn atom's increments to its state and refreshes its geometry "
     "(`TruncatedSphere::cap_height(V, h_previous)`: a fifth-order series-reversion step from the previous "
     "height and one Newton step, the root to round-off without acos/cos, inlined; a net gain is one division). "
     "Only atoms that wore in the step are visited and cleared (no pass over all "
     "owned + ghost atoms); the transfer array and its communication exist only with transfer > 0, and the "
     "geometry goes to the ghosts only with reshape yes."),
    ("memset",
     "`memset` is LAMMPS clearing forces and torques each step (the same in every style); part of it is "
     "start-up."),
]
COMMON_NOTE = ("The scene's fixes (`aveforce`, `setforce`, `nve`) and `Neighbor::check_distance` cost the same for "
               "every style; the pair-only ratio is in the `Pair s` column of the table. `pvm_irq_enable` "
               "(kernel, paravirtualised interrupts) is the virtual machine, the same for every style.")


def report(tp, sp, conv, impact, prof, args, started, img_rel):
    s = tp["summary"]
    a = s["a"]["rate"]
    lines = []
    w = lines.append
    t_r = rayleigh_time_al_slab()
    w("# Micro-scale benchmarks (pair runin/asperity)")
    w("")
    w("Generated by `bench/run-micro` (" + ("quick mode, " if args.quick else "") +
      f"{started:%Y-%m-%d %H:%M} UTC, {platform.node()}, {os.cpu_count()} cores, "
      f"load average at start {os.getloadavg()[0]:.2f}). Reproduce every number on this page with")
    w("")
    w("    bench/run-micro            # RUNIN_BUILD_DIR=<build> to pick the lmp_runin; --quick for a smoke run")
    w("")
    w("Scene: `bench/micro/in.slab`, a held rough slab of Al asperities (type 1, R = 1 um, summits spread")
    w("+-0.05 R) under a loaded Cu counter-body (type 2, 1.39e7 Pa nominal) sliding at 2 m/s, dt = 1e-10 s.")
    w("Only the included pair file differs (`bench/micro/pair_*.in`); each pair file states how its")
    w("coefficients reproduce the Cu/Al contact of `potentials/CuAl.runin`.")
    w("")
    w("## Throughput (issue 3)")
    w("")
    w(f"{s['a']['atoms']} atoms, {tp['nsettle']} settling steps (untimed), then {tp['nslide']} timed sliding steps; "
      f"{tp['repeats']} repeats run interleaved (a b c d a b c d ...). One MPI rank, OMP_NUM_THREADS=1.")
    w("Rates are atom-steps per CPU-second of the timed loop (LAMMPS's loop time x its '% CPU use'), so")
    w("they hold on a machine shared with other jobs; the wall-clock rate is listed too. The ratio is the")
    w("median over repeats of (style / (a)) within the same repeat, which cancels slow drifts in load.")
    w("")
    w("| style | atom-steps per CPU-s (median) | per wall-s (median) | ratio to (a) (median of paired) | paired ratios | Pair s | Neigh s | Comm s | Modify s | Other s | neighbors |")
    w("|---|---|---|---|---|---|---|---|---|---|---|")
    ratio = {key: median(tp["paired"][key]) for key in STYLES}
    for key, (label, _) in STYLES.items():
        t = s[key]["timers"]
        paired = " ".join(f"{x:.3f}" for x in tp["paired"][key])
        w(f"| ({key}) {label} | {s[key]['rate']:.4g} | {s[key]['wall_rate']:.4g} | {ratio[key]:.3f} | {paired} | "
          f"{t['Pair']:.3f} | {t['Neigh']:.3f} | {t['Comm']:.3f} | {t['Modify']:.3f} | {t['Other']:.3f} | "
          f"{s[key]['neighbors']} |")
    w("")
    loads = [x for key in STYLES for x in s[key]["loads"]]
    w(f"Load average (1 min) seen after the runs: {min(loads):.1f} to {max(loads):.1f} on {os.cpu_count()} cores.")
    w("")
    c_ratio, d_ratio = ratio["c"], ratio["d"]
    w(f"Targets: c/a >= 0.85 -> **{c_ratio:.3f}** ({'met' if c_ratio >= 0.85 else 'MISSED'}); "
      f"d/a >= 0.95 -> **{d_ratio:.3f}** ({'met' if d_ratio >= 0.95 else 'MISSED'}). For reference, the stock "
      f"`granular` style (b): b/a = {ratio['b']:.3f}.")
    w("")
    w(f"![throughput]({img_rel}/micro_throughput.png)")
    w("")
    if prof:
        w("### Where the time goes")
        w("")
        w(f"`perf record -F 1999` of the whole run (nside {prof['nside']}, {prof['nsettle']} + {prof['nslide']} "
          "steps), flat profile by symbol (`perf report --no-children --sort dso,symbol`), user-space symbols >= 0.8 % "
          "of all samples (kernel and dynamic-loader rows, mostly start-up and scheduling on a loaded machine, "
          "are left out):")
        w("")
        for key, rows in prof["tables"].items():
            w(f"({key}) {STYLES[key][0]}:")
            w("")
            w("| % samples | object | symbol |")
            w("|---|---|---|")
            for pct, dso, sym in rows:
                w(f"| {pct:.2f} | {dso} | `{sym[:90]}` |")
            w("")
        w("Reading (where (c) spends time that (a) does not):")
        w("")
        symbols = " ".join(sym for _, _, sym in prof["tables"].get("c", []))
        for key, note in PROFILE_NOTES:
            if key in symbols:
                w("- " + note)
        w("- " + COMMON_NOTE)
        w("")
    w("The timer columns are LAMMPS's own breakdown of the timed run (medians). `neighbors` is LAMMPS's")
    w("'Total # of neighbors' at the end, the same order for every style, so the scenes are comparable.")
    w("")
    w("## Parallel speed-up 1 -> 2 MPI ranks")
    w("")
    w(f"{sp['atoms']} asperities (nside {sp['nside']}), runin/asperity with wear, {sp['nsettle']} settling + "
      f"{sp['nslide']} timed sliding steps, {sp['repeats']} repeat(s), medians of the sliding loop time. "
      "OpenMPI runs with `OMPI_MCA_mpi_yield_when_idle=1` (set by the script; override it in the environment): on "
      "this shared machine (load average ~10) busy-polling ranks made the 2-rank run 8x slower than 1 rank: 15.8 s "
      "against 2.0 s, and 1.25 s with yielding (`OMPI_MCA_mpi_yield_when_idle=0|1 mpirun -np 2 --bind-to none "
      "lmp_runin -in bench/micro/in.slab -var pairfile bench/micro/pair_runin_full.in -var nside 100 -var nsettle 600 "
      "-var nslide 600`, 2026-11-22).")
    w("")
    w("| ranks | loop time [s] (median) | all repeats [s] |")
    w("|---|---|---|")
    for np in (1, 2):
        w(f"| {np} | {median(sp['times'][np]):.3f} | {' '.join(f'{x:.3f}' for x in sp['times'][np])} |")
    w("")
    w(f"Speed-up (best of {sp['repeats']} each, the usual estimate under interference): **{sp['best']:.2f}** "
      f"(parallel efficiency {sp['best'] / 2:.0%}); from the medians: {sp['speedup']:.2f}. Wall-clock. The machine has "
      f"2 cores shared with other jobs (load average {min(sp['loads']):.1f} to {max(sp['loads']):.1f} during these "
      "runs), so with a load above ~1 this is a lower bound on the real speed-up.")
    w("")
    w("Pair time per rank (LAMMPS breakdown, min / max over ranks) and LAMMPS's '% CPU use', per repeat:")
    w("")
    for np in (1, 2):
        w(f"- {np} rank(s): " + "; ".join(f"{lo:.3f} / {hi:.3f} s, {100 * cpu:.0f} % CPU"
                                         for (lo, hi), cpu in sp["spreads"][np]))
    w("")
    w("When the fastest rank's pair time is well below the 1-rank pair time but the slowest one is not, the "
      "ranks did not get a core each (another job shared one), and the step waits for the slow rank at the "
      "load-control allreduce of `fix aveforce`: the speed-up above is then set by the machine's load, not by "
      "the decomposition.")
    w("")
    w("## Timestep convergence (work-precision)")
    w("")
    w(f"Scene at nside 30 (1741 atoms), runin/asperity with wear; the same physical times at every dt "
      f"({conv['settle_time']:.3g} s settling, {conv['slide_time']:.3g} s sliding = "
      f"{2.0 * conv['slide_time'] * 1e6:.3g} um). Reference: dt = {conv['reference_dt']:.3g} s. "
      "mu_eff = mean of compute runin/friction [3] over the second half of the slide; wear = [5] at the end. "
      f"The guard's Rayleigh time for this scene is t_R = {t_r * 1e9:.4g} ns (`src/tribo/stability.h`); "
      "dt above 0.2 t_R runs with the guard's WARNING.")
    w("")
    w("| dt [s] | dt / t_R | wear [m^3] | rel. error | mu_eff | rel. error | sliding run time [s] |")
    w("|---|---|---|---|---|---|---|")
    for p in conv["points"]:
        ref = " (reference)" if p["dt"] == conv["reference_dt"] else ""
        w(f"| {p['dt']:.3g}{ref} | {p['dt'] / t_r:.3f} | {p['wear']:.6g} | {p['wear_error']:.2e} | "
          f"{p['mu']:.6f} | {p['mu_error']:.2e} | {p['time']:.2f} |")
    w("")
    pts = [p for p in conv["points"] if p["dt"] != conv["reference_dt"]]
    orders = []
    for name in ("wear_error", "mu_error"):
        pairs = [(p, q) for p, q in zip(pts, pts[1:]) if p[name] > 0 and q[name] > 0]
        orders.append(" ".join(f"{math.log(p[name] / q[name]) / math.log(p['dt'] / q['dt']):.2f}" for p, q in pairs))
    w(f"Observed order between neighbouring dt (log error ratio / log dt ratio): wear {orders[0]}; mu_eff {orders[1]}. "
      "The error against the finest run also contains that run's own error, so the last ratio is biased high.")
    w("")
    w(f"![convergence]({img_rel}/micro_dt_convergence.png)")
    w("")
    w("## Timestep guard")
    w("")
    w("`pair runin/asperity` checks the timestep at every `run` (`plugins/lammps/runin_timestep_guard.*`,")
    w("kernels in `src/tribo/stability.*`). It takes the smallest Rayleigh time")
    w("t_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766) over the atom types of every set type pair, with R and rho")
    w("(from rmass) the smallest per type and G, nu of the like-material pair that has the pair's E* and G*")
    w("(nu = 0.3 with E* when hand-set E*, G* are not those of an isotropic pair). Then:")
    w("")
    w("- dt > 0.2 t_R: one WARNING naming dt, the critical timestep 0.2 t_R and t_R (common DEM practice is")
    w("  0.1-0.3 t_R);")
    w("- dt > 4 t_R: ERROR, the run does not start (the measurements below show garbage well before that);")
    w("- every step, pair runin/asperity adds up the pair forces it computes (one add per contact, in its force")
    w("  loop); if the sum is not finite it stops the run at once, before the forces are communicated, with one")
    w("  ERROR naming the step and the atom IDs (a pass over the atoms' forces runs only then, to find them). So a")
    w("  NaN never reaches the integrator, a dump or thermo output. The internal fix RUNIN/FINITE_CHECK (one summed")
    w("  pass over owned + ghost forces and an MPI_Allreduce per step) now runs its pass only when some other force")
    w("  source precedes reverse communication (pair hybrid, bonds, kspace); with pair runin/asperity alone it is")
    w("  idle. On more than one rank the ERROR comes from the rank that found the force (`ERROR on proc N`), since")
    w("  agreeing on it would need the per-step collective this avoids.")
    w("")
    cfl = 2.0e-6 * math.sqrt(2700.0 / 69.0e9)
    w(f"The thesis's CFL form (eq. 2.1, `cfl_time_step`), dt <= beta h / sqrt(E/rho), with h = 2R and beta = 1 gives "
      f"{cfl:.3g} s for the Al asperities = {cfl / IMPACT_RAYLEIGH_TIME:.2f} t_R: it sits between the warning and the "
      "stability limit, and the guard uses t_R because it also carries nu and the particle shape.")
    w("")
    w("Why 4: an undamped head-on impact of two free Al asperities (`bench/micro/in.impact`, e = 1, so the exact")
    w("rebound/approach speed ratio is 1) at dt = f t_R (t_R = 1.089 ns):")
    w("")
    w("| dt / t_R | " + " | ".join(f"v = {v:g} m/s" for v in impact["speeds"]) + " |")
    w("|---|" + "---|" * len(impact["speeds"]))
    for f in impact["factors"]:
        w(f"| {f:g} | " + " | ".join(f"{impact['table'][(v, f)]:.4f}" for v in impact["speeds"]) + " |")
    w("")
    w("Up to 0.2 t_R the error is below 0.03 %; from about 1.5-2 t_R the impact gains energy (ratio > 1) or")
    w("loses it arbitrarily, and at 3 t_R the rebound is 2-5 times the approach speed at 2 and 20 m/s, which")
    w("in a many-body run compounds into a blow-up. Contacts that are held by a rigid, load-controlled")
    block = impact["block"]
    w("counter-body survive longer: the convergence scene above (nside 30, the `inputs/in.rough_slider` geometry")
    w(f"and load; the counter-body moves as one block) gives mu_eff = {block[3.9e-9][0]:.4f} and wear "
      f"{block[3.9e-9][1]:.4g} m^3 at dt = 3.9e-9 s (3.96 t_R, WARNING) against {block[1e-10][0]:.4f} and "
      f"{block[1e-10][1]:.4g} m^3 at 1e-10 s,")
    w("so the ERROR threshold sits just above the largest dt at which we saw a sane result and is not set lower.")
    w("Tests: `lammps.timestep_guard.warning|blowup|nan` (decks `tests/lammps/decks/in.dt_*`) and")
    w("the unit tests `Rayleigh.*`, `Hertz.ContactTimeAndOverlapMatchDirectIntegration`, `Verlet.*`, `Cfl.*`,")
    w("`EquivalentMaterial.*`, `Policy.*` (`tests/unit/test_tribo_stability.cpp`).")
    w("")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--out", default=os.path.join(SOURCE_DIR, "out", "bench-micro"))
    parser.add_argument("--doc", default=os.path.join(SOURCE_DIR, "doc", "benchmarks-micro.md"))
    parser.add_argument("--quick", action="store_true", help="small sizes, for a smoke test")
    args = parser.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    started = datetime.datetime.utcnow()
    shutil.rmtree(args.out, ignore_errors=True)
    print("throughput ...", flush=True)
    tp = throughput(args.lmp, args.out, args.quick)
    print("speed-up ...", flush=True)
    sp = speedup(args.lmp, args.out, args.quick)
    print("profile ...", flush=True)
    prof = profile(args.lmp, args.out, args.quick)
    print("impact scan ...", flush=True)
    impact = impact_scan(args.lmp, args.out)
    block = rigid_block(args.lmp, args.out)
    print("timestep convergence ...", flush=True)
    conv = convergence(args.lmp, args.out, args.quick)
    img_dir = os.path.join(os.path.dirname(os.path.abspath(args.doc)), "img")
    plot(tp, conv, img_dir)
    impact["block"] = block
    text = report(tp, sp, conv, impact, prof, args, started, os.path.relpath(img_dir, os.path.dirname(os.path.abspath(args.doc))))
    write_atomically(args.doc, text + "\n")
    import json
    write_atomically(os.path.join(args.out, "results.json"), json.dumps(
        {"throughput": {k: {kk: vv for kk, vv in v.items()} for k, v in tp["summary"].items()},
         "paired": tp["paired"], "speedup": sp, "convergence": conv,
         "impact": {f"{v}:{f}": x for (v, f), x in impact["table"].items()}}, indent=1, default=str))
    print(f"wrote {args.doc} and {img_dir}/micro_*.png")


if __name__ == "__main__":
    main()
