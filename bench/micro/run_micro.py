#!/usr/bin/python3
"""RunIn micro-scale benchmarks: throughput of pair runin/asperity against the stock granular styles on a
sparse and a contact-dense scene (loop and Pair-timer ratios), 1 -> 2 rank speed-up with LAMMPS's load
balancing, an instruction profile (callgrind) of the force loops, timestep convergence of wear and mu_eff.
Writes doc/benchmarks-micro.md and PNG plots.

  bench/run-micro [--quick]        (wrapper: finds lmp_runin, runs this with /usr/bin/python3)
  /usr/bin/python3 bench/micro/run_micro.py --lmp BUILD/lmp_runin [--out DIR] [--doc FILE] [--quick]
      [--parts slab,dense,speedup,profile,convergence] [--quiet-load 0.5] [--max-wait 3600]
"""
import argparse
import datetime
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MICRO = os.path.join(SOURCE_DIR, "bench", "micro")
COEFFS = os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")
DECK = os.path.join(MICRO, "in.slab")
ALL_PARTS = ("slab", "dense", "speedup", "profile", "convergence")

# key: (label, short label, pair file, extra deck variables)
STYLES = {
    "a": ("gran/hertz/history (stock)", "(a) gran/hertz/history", "pair_gran_hertz.in", {}),
    "b": ("granular hertz/material + mindlin (stock)", "(b) granular", "pair_granular.in", {}),
    "c": ("runin/asperity, all physics, normal hertz (wear, reshape, transfer 0.3, adhesion + ploughing, "
          "re-stick)", "(c) runin, all physics", "pair_runin_full.in", {}),
    "d": ("runin/asperity, wear no, friction coulomb, normal hertz (wear, strength and plasticity off)",
          "(d) runin, lean", "pair_runin_lean.in", {}),
    "e": ("runin/asperity, all physics + elastic/plastic (as (c) with normal elastic/plastic)",
          "(e) runin, all + e/p", "pair_runin_full.in", {"normal": "elastic/plastic"}),
}
# the contact-dense scene also runs (e) with the worn/flattened geometry out of the contact (see the page)
DENSE_EXTRA = {
    "f": ("runin/asperity, all physics + elastic/plastic, reshape no (no worn or flattened summit in the "
          "contact)", "(f) = (e), reshape no", "pair_runin_full.in",
          {"normal": "elastic/plastic", "reshape": "no"}),
    "g": ("runin/asperity, (f) with friction junction/film (junction growth, per-summit film coverage worn off "
          "and regrown)", "(g) = (f), junction/film", "pair_runin_film.in",
          {"normal": "elastic/plastic", "reshape": "no"}),
}
TARGET_STYLES = {"e": 0.85, "d": 1.15}    # Pair-timer ratio to (a), from the issue
TIMER_ROWS = ("Pair", "Neigh", "Comm", "Output", "Modify", "Other")

SCENES = {
    # deck, full-size parameters, quick parameters
    "slab": {"deck": "in.slab",
             "full": {"nside": 87, "nsettle": 1500, "nslide": 5000, "repeats": 9},
             "quick": {"nside": 40, "nsettle": 1000, "nslide": 400, "repeats": 2}},
    "dense": {"deck": "in.dense",
              "full": {"nside": 87, "nsettle": 2000, "nslide": 1000, "repeats": 5},
              "quick": {"nside": 30, "nsettle": 300, "nslide": 200, "repeats": 2}},
}


def mpi_env():
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env["OMP_NUM_THREADS"] = "1"
    # waiting ranks yield the core: on a shared machine busy-polling ranks slowed 2 ranks by 10x
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return env


# ---- how busy the machine is -------------------------------------------------------------------------

def procs_running():
    with open("/proc/stat") as f:
        for line in f:
            if line.startswith("procs_running"):
                return int(line.split()[1])
    return 0


class LoadSampler:
    """Runnable tasks other than ours while a run lasts (/proc/stat procs_running, every 0.2 s, minus our
    own ranks and this sampler), so a run that shared the cores is visible in the results."""

    def __init__(self, own):
        self.own, self.samples, self._stop = own, [], threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def _run(self):
        while not self._stop.wait(0.2):
            self.samples.append(max(0, procs_running() - self.own - 1))

    def __enter__(self):
        self._thread.start()
        return self

    def __exit__(self, *exc):
        self._stop.set()
        self._thread.join()

    def mean(self):
        return statistics.mean(self.samples) if self.samples else 0.0


class Quiet:
    """Waits for a quiet machine before a run and repeats a run that shared the cores: other runnable tasks
    (averaged over 2 s before, and over the run) below `limit`; at most `budget` s of waiting in all."""

    def __init__(self, limit, budget):
        self.limit, self.budget, self.waited, self.reruns, self.before = limit, budget, 0.0, 0, []

    def wait(self):
        while True:
            samples = []
            for _ in range(10):
                samples.append(max(0, procs_running() - 1))
                time.sleep(0.2)
            other = statistics.mean(samples)
            if other < self.limit or self.waited >= self.budget:
                self.before.append(other)
                return other
            time.sleep(5.0)
            self.waited += 7.0

    def run(self, function, *args, **kwargs):
        """function(...) -> result with 'other'; up to two more tries when the run was shared."""
        for attempt in range(3):
            self.wait()
            result = function(*args, **kwargs)
            if result["other"] < self.limit or self.waited >= self.budget or attempt == 2:
                return result
            self.reruns += 1
            print(f"    (shared: {result['other']:.2f} other runnable tasks; repeating the run)", flush=True)


# ---- one LAMMPS run ----------------------------------------------------------------------------------

LOOP_RE = re.compile(r"Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms")


def parse_runs(log):
    """Every run of a log: loop time, steps, atoms, timer rows (min, avg, max), % CPU, per-rank atoms and
    neighbours (ave, max, min) and the total neighbour count."""
    marks = list(LOOP_RE.finditer(log))
    runs = []
    for k, m in enumerate(marks):
        section = log[m.end(): marks[k + 1].start() if k + 1 < len(marks) else len(log)]
        timers = {}
        for row in TIMER_ROWS:
            t = re.search(rf"^{row}\s*\|\s*([0-9.eE+-]*)\s*\|\s*([0-9.eE+-]+)\s*\|\s*([0-9.eE+-]*)\s*\|", section,
                          re.M)
            if t:
                avg = float(t.group(2))
                timers[row] = (float(t.group(1)) if t.group(1) else avg, avg,
                               float(t.group(3)) if t.group(3) else avg)
            else:
                timers[row] = (0.0, 0.0, 0.0)
        cpu = re.search(r"([0-9.]+)% CPU use with", section)
        stats = {}
        for name in ("Nlocal", "Neighs"):
            s = re.search(rf"^{name}:\s*([0-9.eE+-]+) ave\s+([0-9.eE+-]+) max\s+([0-9.eE+-]+) min", section, re.M)
            stats[name] = tuple(float(x) for x in s.groups()) if s else (0.0, 0.0, 0.0)
        total = re.search(r"Total # of neighbors = (\d+)", section)
        runs.append({"loop": float(m.group(1)), "procs": int(m.group(2)), "steps": int(m.group(3)),
                     "atoms": int(m.group(4)), "timers": timers,
                     "cpu_fraction": float(cpu.group(1)) / 100.0 if cpu else 1.0,
                     "nlocal": stats["Nlocal"], "neighs": stats["Neighs"],
                     "neighbors": int(total.group(1)) if total else 0})
    return runs


def thermo_rows(log):
    """Thermo rows after the last 'Step' header (the last run's)."""
    header, rows = None, []
    for line in log[log.rfind("Step "):].splitlines():
        words = line.split()
        if words and words[0] == "Step":
            header = words
        elif header and len(words) == len(header):
            try:
                rows.append(dict(zip(header, map(float, words))))
            except ValueError:
                pass
    return rows


def command_line(lmp, deck, variables, np=1, rel=False):
    """The command that reproduces a run (rel: paths relative to the source tree, for the page)."""
    def shown(value):
        value = str(value)
        return os.path.relpath(value, SOURCE_DIR) if rel and value.startswith(SOURCE_DIR + os.sep) else value
    command = [shown(lmp) if not rel else "$BUILD/lmp_runin", "-in", shown(deck)]
    for name, value in variables.items():
        command += ["-var", name, shown(value)]
    if np > 1:
        command = ["mpirun", "-np", str(np), "--bind-to", "none"] + command
    return command


def run_deck(lmp, workdir, variables, np=1, deck=DECK, prefix=()):
    """Run a deck; return the last run's loop time, timers, atoms, steps, thermo rows and all runs.

    prefix: words before the command (e.g. taskset -c 1, to pin a run to one core)."""
    os.makedirs(workdir, exist_ok=True)
    command = list(prefix) + command_line(lmp, deck, variables, np) + ["-log", "log.lammps", "-screen", "none"]
    with LoadSampler(np) as sampler:
        result = subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True, text=True)
    path = os.path.join(workdir, "log.lammps")
    log = open(path).read() if os.path.exists(path) else ""
    if result.returncode != 0:
        sys.exit(f"run-micro: lmp_runin failed in {workdir} ({' '.join(command)}):\n{log[-1500:]}{result.stderr}")
    runs = parse_runs(log)
    if not runs:
        sys.exit(f"run-micro: {lmp} exited 0 but {path} holds no finished run: is it an lmp_runin?")
    last = runs[-1]
    rows = thermo_rows(log)
    return {"loop": last["loop"], "cpu_fraction": last["cpu_fraction"], "cpu": last["loop"] * last["cpu_fraction"],
            "procs": last["procs"], "steps": last["steps"], "atoms": last["atoms"],
            "timers": {row: last["timers"][row][1] for row in TIMER_ROWS},
            "timer_spread": last["timers"], "neighbors": last["neighbors"], "runs": runs, "rows": rows,
            "load": os.getloadavg()[0], "other": sampler.mean()}


def rayleigh_time_al_slab():
    """t_R the guard computes for the slab: Al density, R = 1 um, the like-material equivalent of the
    Cu/Al pair's E* and G* (src/tribo/stability.cpp, equivalent_material and rayleigh_time)."""
    mats = {}
    for line in open(COEFFS):
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


def style_vars(key, styles):
    _, _, pairfile, extra = styles[key]
    return dict({"pairfile": os.path.join(MICRO, pairfile), "coeffs": COEFFS}, **extra)


# ---- throughput: all styles on one scene, interleaved repeats --------------------------------------------

def throughput(lmp, out, scene, quick, quiet):
    """quiet: a Quiet (shared by the whole benchmark)."""
    spec = SCENES[scene]
    params = dict(spec["quick" if quick else "full"])
    repeats = params.pop("repeats")
    deck = os.path.join(MICRO, spec["deck"])
    styles = dict(STYLES, **(DENSE_EXTRA if scene == "dense" else {}))
    results = {key: [] for key in styles}
    for repeat in range(repeats):
        for key in styles:    # interleaved: a b c d e a b c d e ...
            variables = dict(style_vars(key, styles), **params)
            r = quiet.run(run_deck, lmp, os.path.join(out, scene, f"{key}{repeat}"), variables, deck=deck)
            r["contacts_per_asperity"] = statistics.mean(
                [row["v_contacts_per_asperity"] for row in r["rows"]]) if r["rows"] else float("nan")
            r["rate"] = r["atoms"] * r["steps"] / r["cpu"]
            r["command"] = command_line(lmp, deck, variables, rel=True)
            results[key].append(r)
            print(f"  {scene} {key} repeat {repeat}: loop {r['loop']:.3f} s, pair {r['timers']['Pair']:.3f} s, "
                  f"{r['contacts_per_asperity']:.3f} contacts/asperity, {100 * r['cpu_fraction']:.0f} % CPU, "
                  f"other runnable tasks {r['other']:.2f}", flush=True)
    summary = {}
    for key, runs in results.items():
        contacts = median([r["contacts_per_asperity"] for r in runs])
        pair = median([r["timers"]["Pair"] for r in runs])
        summary[key] = {
            "loop": median([r["loop"] for r in runs]), "loops": [r["loop"] for r in runs],
            "pair": pair, "pairs": [r["timers"]["Pair"] for r in runs],
            "rate": median([r["rate"] for r in runs]),
            "cpu_fraction": median([r["cpu_fraction"] for r in runs]),
            "timers": {row: median([r["timers"][row] for r in runs]) for row in TIMER_ROWS},
            "others": [r["other"] for r in runs], "loads": [r["load"] for r in runs],
            "contacts_per_asperity": contacts,
            "pair_ns_per_contact": 1e9 * pair / (runs[0]["steps"] * contacts * runs[0]["atoms"])
            if contacts > 0 else float("nan"),
            "atoms": runs[0]["atoms"], "steps": runs[0]["steps"], "neighbors": runs[0]["neighbors"],
            "fz": statistics.mean([row.get("v_fz", float("nan")) for row in runs[0]["rows"]]) if runs[0]["rows"]
            else float("nan"),
            "command": runs[0]["command"],
        }
    # ratios within a repeat (a ran just before): pairs off slow drifts of the machine's load
    a = results["a"]
    paired = {"loop": {}, "pair": {}, "per_contact": {}}
    for key in styles:
        paired["loop"][key] = [a[k]["loop"] / results[key][k]["loop"] for k in range(repeats)]
        paired["pair"][key] = [a[k]["timers"]["Pair"] / results[key][k]["timers"]["Pair"] for k in range(repeats)]
        paired["per_contact"][key] = [
            (a[k]["timers"]["Pair"] / a[k]["contacts_per_asperity"]) /
            (results[key][k]["timers"]["Pair"] / results[key][k]["contacts_per_asperity"])
            if results[key][k]["contacts_per_asperity"] > 0 and a[k]["contacts_per_asperity"] > 0 else float("nan")
            for k in range(repeats)]
    # the contacts the RunIn pair itself evaluates (compute runin/friction [4]; it changes the force loop, so in
    # separate untimed runs): with worn or flattened summits they differ from the centre-distance count
    pair_contacts = {}
    for key in styles:
        if not styles[key][2].startswith("pair_runin"):
            continue
        variables = dict(style_vars(key, styles), **params)
        variables.update(nslide=min(params["nslide"], 400), thermo_every=50, friction="yes")
        r = run_deck(lmp, os.path.join(out, scene, f"{key}_contacts"), variables, deck=deck)
        counts = [row["c_fric[4]"] / r["atoms"] for row in r["rows"]]
        pair_contacts[key] = {"mean": statistics.mean(counts), "first": counts[0], "last": counts[-1],
                              "command": command_line(lmp, deck, variables, rel=True)}
        print(f"  {scene} {key}: the pair evaluates {pair_contacts[key]['mean']:.3f} contacts/asperity", flush=True)
    # per contact: the contacts the pair evaluates where known (RunIn styles), the geometric ones otherwise
    def evaluated(key, run):
        return pair_contacts[key]["mean"] if key in pair_contacts else run["contacts_per_asperity"]
    for key in styles:
        paired["per_contact"][key] = [
            (a[k]["timers"]["Pair"] / evaluated("a", a[k])) / (results[key][k]["timers"]["Pair"] /
                                                              evaluated(key, results[key][k]))
            if evaluated(key, results[key][k]) > 0 else float("nan") for k in range(repeats)]
        c = evaluated(key, {"contacts_per_asperity": summary[key]["contacts_per_asperity"]})
        summary[key]["pair_ns_per_contact"] = (1e9 * summary[key]["pair"] /
                                               (summary[key]["steps"] * c * summary[key]["atoms"])
                                               if c > 0 else float("nan"))
    return {"scene": scene, "styles": styles, "summary": summary, "paired": paired, "params": params,
            "repeats": repeats, "pair_contacts": pair_contacts}


# ---- speed-up 1 -> 2 ranks with LAMMPS's load balancing -----------------------------------------------------

SPEEDUP_CONFIGS = [
    # key, ranks, label, deck variables
    ("np1", 1, "1 rank", {}),
    ("np1off", 1, "1 rank, newton off (the reference of the rcb row)", {"newton": "off"}),
    ("none", 2, "2 ranks, LAMMPS's regular grid (2 x 1 x 1), no balancing", {}),
    ("shift", 2, "2 ranks, cut along x shifted once by contact weights (fix balance at the setup of a run 0)",
     {"balance": "shift", "bdims": "x"}),
    ("fixshift", 2, "2 ranks, fix balance every 250 steps along x, contact weights",
     {"balance": "fixshift", "bdims": "x"}),
    ("rcb", 2, "2 ranks, comm_style tiled, rcb once by contact weights (newton off)",
     {"balance": "rcb", "newton": "off"}),
    ("y", 2, "2 ranks, grid 1 x 2 x 1 (cut parallel to the sliding direction), shifted once along y by contact "
     "weights", {"balance": "shift", "bdims": "y", "px": 1, "py": 2}),
]


def speedup(lmp, out, quick, quiet):
    nside, nsettle, nslide, repeats = (60, 600, 300, 1) if quick else (160, 1000, 1500, 5)
    base = dict(style_vars("c", STYLES), nside=nside, nsettle=nsettle, nslide=nslide,
                balance_file=os.path.join(MICRO, "balance.in"))
    results = {key: [] for key, *_ in SPEEDUP_CONFIGS}
    commands = {}
    for repeat in range(repeats):
        for key, np, _, extra in SPEEDUP_CONFIGS:
            variables = dict(base, **extra)
            r = quiet.run(run_deck, lmp, os.path.join(out, "speedup", f"{key}_{repeat}"), variables, np=np)
            commands[key] = command_line(lmp, DECK, variables, np=np, rel=True)
            results[key].append(r)
            pair = r["timer_spread"]["Pair"]
            print(f"  speed-up {key} repeat {repeat}: loop {r['loop']:.3f} s, pair min/max {pair[0]:.3f}/{pair[2]:.3f} s,"
                  f" comm {r['timers']['Comm']:.3f} s, neighbours max/min {r['runs'][-1]['neighs'][1]:.0f}/"
                  f"{r['runs'][-1]['neighs'][2]:.0f}, other runnable tasks {r['other']:.2f}", flush=True)
    summary = {}
    for key, np, label, extra in SPEEDUP_CONFIGS:
        runs = results[key]
        loops = [r["loop"] for r in runs]
        # against one rank with the same newton setting
        t1 = [r["loop"] for r in results["np1off" if extra.get("newton") == "off" else "np1"]]
        summary[key] = {
            "label": label, "np": np, "loops": loops, "loop": median(loops),
            "speedup_median": median([t1[k] / loops[k] for k in range(repeats)]),
            "speedup_of_medians": median(t1) / median(loops), "speedup_best": min(t1) / min(loops),
            "speedups_paired": [t1[k] / loops[k] for k in range(repeats)],
            "comm_share": median([r["timers"]["Comm"] / r["loop"] for r in runs]),
            "pair_spread": [(r["timer_spread"]["Pair"][0], r["timer_spread"]["Pair"][2]) for r in runs],
            "cpu": [r["cpu_fraction"] for r in runs], "others": [r["other"] for r in runs],
            # per-rank neighbours: end of settling (before), after the balancing run 0 (if any), end of the timed run
            "neighs_before": runs[0]["runs"][0]["neighs"], "neighs_after": runs[0]["runs"][-1]["neighs"],
            "neighs_balanced": runs[0]["runs"][1]["neighs"] if len(runs[0]["runs"]) > 2 else None,
            "nlocal_after": runs[0]["runs"][-1]["nlocal"],
            "command": commands[key],
        }
    return {"summary": summary, "atoms": results["np1"][0]["atoms"], "nside": nside, "nsettle": nsettle,
            "nslide": nslide, "repeats": repeats}


# ---- instruction profile (callgrind) of the force loops ------------------------------------------------------

LIBM = ("exp", "pow", "log", "expm1", "log1p", "sin", "cos", "asin", "acos", "atan", "atan2", "tanh", "cbrt", "sqrt",
        "hypot", "sincos")


def callgrind_profile(lmp, out, quick):
    """Instructions per contact of each pair style on the contact-dense scene (identical positions for every
    style), and the libm calls per contact; None without valgrind."""
    if not shutil.which("valgrind") or not shutil.which("callgrind_annotate"):
        return None
    nside, nsettle, nslide = (16, 100, 100) if quick else (24, 300, 300)
    deck = os.path.join(MICRO, "in.dense")
    styles = dict(STYLES, **DENSE_EXTRA)
    table = {}
    for key in ("a", "c", "d", "f"):
        workdir = os.path.join(out, "callgrind", key)
        os.makedirs(workdir, exist_ok=True)
        variables = dict(style_vars(key, styles), nside=nside, nsettle=nsettle, nslide=nslide, thermo_every=25,
                         friction="no")
        cg = os.path.join(workdir, "callgrind.out")
        command = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                   "--toggle-collect=LAMMPS_NS::Verlet::run*"] + command_line(lmp, deck, variables) + \
                  ["-log", "log.lammps", "-screen", "none"]
        if subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True).returncode != 0:
            return None
        log = open(os.path.join(workdir, "log.lammps")).read()
        # geometric contacts of both runs (settle + timed, the collected range), one row per thermo step
        contacts = []
        for chunk in log.split("Loop time of")[:-1]:
            contacts += [row["v_contacts_per_asperity"] for row in thermo_rows(chunk)]
        atoms = parse_runs(log)[-1]["atoms"]
        contact_steps = statistics.mean(contacts) * atoms * (nsettle + nslide)
        text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--tree=calling", cg],
                              capture_output=True, text=True).stdout
        total = re.search(r"([0-9,]+)\s+\(100.0%\)\s+PROGRAM TOTALS", text)
        pair_ir, evaluated = 0, None
        calls, caller = {}, None
        for line in text.splitlines():
            m = re.match(r"\s*([0-9,]+) \([ 0-9.]+%\)\s+([*>])\s+(\S.*?)(?: \(([0-9,]+)x\))? \[(.*)\]\s*$", line)
            if not m:
                continue
            ir, kind, name, count, obj = int(m.group(1).replace(",", "")), m.group(2), m.group(3), m.group(4), m.group(5)
            if kind == "*":
                caller = (name, obj)
                if re.search(r"Pair\w+::compute\(int, int\)", name):
                    pair_ir = max(pair_ir, ir)
            elif caller and "libm" not in caller[1] and "libm" in obj and count:
                fn = re.sub(r".*:", "", name).split("@")[0].lstrip("_")
                fn = re.sub(r"^(ieee754_)?", "", re.sub(r"_(fma|avx2|sse2|fma4)$", "", fn))
                calls[fn] = calls.get(fn, 0) + int(count.replace(",", ""))
            elif caller and kind == ">" and "ElasticPlasticNormalModel::evaluate" in name and count:
                evaluated = (evaluated or 0) + int(count.replace(",", ""))
        table[key] = {"total": int(total.group(1).replace(",", "")) if total else 0, "pair": pair_ir,
                      "contact_steps": contact_steps, "contacts_per_asperity": statistics.mean(contacts),
                      "evaluated": evaluated, "libm": calls, "command": command_line(lmp, deck, variables, rel=True)}
        print(f"  callgrind {key}: pair {pair_ir / 1e6:.1f} M instructions, {pair_ir / contact_steps:.0f} per contact, "
              f"libm calls per contact {sum(calls.values()) / contact_steps:.1f}", flush=True)
    return {"table": table, "nside": nside, "nsettle": nsettle, "nslide": nslide}


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





def plot(scenes, conv, img_dir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(img_dir, exist_ok=True)
    if scenes:
        fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 3.8), squeeze=False)
        for ax, tp in zip(axes[0], scenes):
            keys = list(tp["styles"])
            x = range(len(keys))
            loop = [median(tp["paired"]["loop"][k]) for k in keys]
            pair = [median(tp["paired"]["pair"][k]) for k in keys]
            ax.bar([i - 0.2 for i in x], loop, width=0.4, color="0.6", label="loop time")
            ax.bar([i + 0.2 for i in x], pair, width=0.4, color="tab:blue", label="Pair timer")
            shown = [max(l, p) for l, p, k in zip(loop, pair, keys) if not contacts_lost(tp, k)]
            ymax = max(1.3, 1.25 * max(shown))
            ax.set_ylim(0.0, ymax)
            for i, v, k in zip(x, pair, keys):
                note = "\n(few contacts\nevaluated)" if contacts_lost(tp, k) else ""
                ax.text(i + 0.2, min(v, 0.72 * ymax), f"{v:.2f}{note}", ha="center", va="bottom", fontsize=7)
            ax.axhline(1.0, color="k", lw=0.6)
            for key, target in TARGET_STYLES.items():
                if key in keys:
                    i = keys.index(key)
                    ax.plot([i - 0.45, i + 0.45], [target, target], "r--", lw=1.0)
            ax.set_xticks(list(x), [tp["styles"][k][1] for k in keys], fontsize=7, rotation=25, ha="right")
            ax.set_ylabel("throughput ratio to (a) (median of paired)")
            ax.set_title(f"{tp['scene']}: {tp['summary']['a']['atoms']} atoms, "
                         f"{tp['summary']['a']['contacts_per_asperity']:.2f} contacts/asperity (a)", fontsize=9)
            ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(img_dir, "micro_throughput.png"), dpi=120)
        plt.close(fig)

    if conv:
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


def fmt_list(values, digits=2):
    return " ".join(f"{v:.{digits}f}" for v in values)


def spread(values):
    return f"{min(values):.2f}-{max(values):.2f}"


def git_state():
    def git(*args):
        return subprocess.run(["git", "-C", SOURCE_DIR] + list(args), capture_output=True, text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD")
    dirty = git("status", "--porcelain", "--", "src", "plugins")
    return head, bool(dirty)


def quiet_note(runs_others):
    busy = sum(1 for o in runs_others if o >= 0.5)
    return (f"other runnable tasks during the runs {spread(runs_others)}"
            + (f", {busy} of {len(runs_others)} runs above 0.5" if busy else ""))


def scene_text(tp, w):
    s, paired = tp["summary"], tp["paired"]
    p = tp["params"]
    keys = list(tp["styles"])
    w(f"{s['a']['atoms']} atoms, {p['nsettle']} untimed + {p['nslide']} timed steps, {tp['repeats']} repeats run "
      f"interleaved ({' '.join(keys)} {' '.join(keys)} ...); one MPI rank, OMP_NUM_THREADS=1; "
      f"{quiet_note([o for k in keys for o in s[k]['others']])}.")
    w("")
    pc = tp.get("pair_contacts", {})
    w("| style | contacts / asperity | evaluated by the pair | loop ratio | Pair ratio | per-contact Pair ratio | Pair s | Pair ns per contact-step | loop s | Neigh s | Comm s | Modify s | % CPU | other tasks | neighbors |")
    w("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for key in keys:
        t, r = s[key]["timers"], s[key]
        evaluated = f"{pc[key]['mean']:.3f}" if key in pc else "-"
        w(f"| ({key}) {tp['styles'][key][0]} | {r['contacts_per_asperity']:.3f} | {evaluated} | "
          f"**{median(paired['loop'][key]):.3f}** ({spread(paired['loop'][key])}) | "
          f"**{median(paired['pair'][key]):.3f}** ({spread(paired['pair'][key])}) | "
          f"{median(paired['per_contact'][key]):.3f} | {r['pair']:.3f} | {r['pair_ns_per_contact']:.0f} | "
          f"{r['loop']:.3f} | {t['Neigh']:.3f} | {t['Comm']:.3f} | {t['Modify']:.3f} | {100 * r['cpu_fraction']:.0f} | "
          f"{spread(r['others'])} | {r['neighbors']} |")
    w("")
    w("Ratios are throughput of the style over throughput of (a) = (a)'s time / the style's time, per repeat "
      "against the (a) run of the same repeat, median over repeats (range in brackets). Loop ratio: LAMMPS's "
      "'Loop time' of the timed run; Pair ratio: the Pair row of its timer breakdown; per-contact Pair ratio: "
      "the Pair ratio times (the style's contacts / (a)'s contacts), with the contacts the pair evaluates "
      "where known, which matters where a style's physics changes the scene (load control); Pair ns per "
      "contact-step likewise. Contacts per asperity: pairs whose centre distance is at most the sum "
      "of the radii, counted once per pair, over the asperity count (compute contact/atom, reduce sum / 2 / "
      "atoms, mean over the thermo steps of the timed run); each asperity touches twice that many. 'evaluated by "
      "the pair': compute runin/friction [4] / atoms in a separate untimed run of the same scene (the compute adds "
      "work to the force loop), which leaves out sunk (worn or flattened) summits. 'other tasks': "
      "runnable tasks besides this run during it (/proc/stat procs_running, sampled every 0.2 s), range over "
      "repeats; 0 means the run had a core to itself.")
    w("")
    w("Commands (one repeat; `$BUILD` = the build directory):")
    w("")
    for key in keys:
        w(f"- ({key}) `{' '.join(s[key]['command'])}`")
    if pc:
        w("- contacts evaluated by the pair: the same commands with " +
          " ".join(f"`-var {k} {v}`" for k, v in (("nslide", 400), ("thermo_every", 50), ("friction", "yes"))) +
          " (nslide at most that of the timed run)")
    w("")


def contacts_lost(tp, key):
    """The pair evaluates under half the geometric contacts of a style (sunk summits): its Pair time is then
    no measure of the cost of a contact."""
    pc = tp.get("pair_contacts", {}).get(key)
    return pc is not None and pc["mean"] < 0.5 * tp["summary"][key]["contacts_per_asperity"]


def targets_text(scenes, w):
    w("| target (Pair timer, against (a)) | " + " | ".join(tp["scene"] for tp in scenes) + " |")
    w("|---|" + "---|" * len(scenes))
    for key, target in TARGET_STYLES.items():
        cells = []
        for tp in scenes:
            v = median(tp["paired"]["pair"][key])
            if contacts_lost(tp, key) and "f" in tp["paired"]["pair"]:
                f = median(tp["paired"]["pair"]["f"])
                cells.append(f"not measurable: {v:.3f}, but the pair evaluates "
                             f"{tp['pair_contacts'][key]['mean']:.2f} of {tp['summary'][key]['contacts_per_asperity']:.2f} "
                             f"contacts/asperity; (f), every contact evaluated: **{f:.3f}** "
                             f"({'met' if f >= target else 'MISSED'})")
                continue
            cells.append(f"**{v:.3f}** ({'met' if v >= target else 'MISSED'})")
        name = {"e": "all physics, elastic-plastic included (e)", "d": "wear, strength and plasticity off (d)"}[key]
        w(f"| {name} >= {target} | " + " | ".join(cells) + " |")
    for key in ("c",):
        cells = [f"{median(tp['paired']['pair'][key]):.3f}" for tp in scenes]
        w("| for reference: all physics, Hertz (c) | " + " | ".join(cells) + " |")
    w("")


def speedup_text(sp, w):
    s = sp["summary"]
    w(f"{sp['atoms']} asperities (`in.slab`, nside {sp['nside']}), style (c) (runin/asperity, all physics, Hertz), "
      f"{sp['nsettle']} settling + {sp['nslide']} timed sliding steps, {sp['repeats']} repeat(s) interleaved over the "
      f"configurations; {quiet_note([o for r in s.values() for o in r['others']])}. OpenMPI runs with `OMPI_MCA_mpi_yield_when_idle=1` (set by the "
      "script; override it in the environment): on a shared machine busy-polling ranks made 2 ranks up to 8x slower "
      "than 1. Loop time is wall-clock.")
    w("")
    w("| configuration | loop s (median) | all repeats | speed-up (median of paired; of the medians; best of each) | paired speed-ups | Comm share of loop | Pair s min / max over ranks | neighbours per rank before -> after balancing -> end of run (max / min) | atoms per rank at the end (max / min) | other tasks |")
    w("|---|---|---|---|---|---|---|---|---|---|")
    for key, r in s.items():
        before = f"{r['neighs_before'][1]:.0f} / {r['neighs_before'][2]:.0f}"
        bal = f"{r['neighs_balanced'][1]:.0f} / {r['neighs_balanced'][2]:.0f}" if r["neighs_balanced"] else "-"
        after = f"{r['neighs_after'][1]:.0f} / {r['neighs_after'][2]:.0f}"
        pairs = "; ".join(f"{lo:.3f} / {hi:.3f}" for lo, hi in r["pair_spread"])
        speed = ("-" if r["np"] == 1 else
                 f"**{r['speedup_median']:.2f}**; {r['speedup_of_medians']:.2f}; {r['speedup_best']:.2f}")
        paired = "-" if r["np"] == 1 else fmt_list(r["speedups_paired"])
        w(f"| {r['label']} | {r['loop']:.3f} | {fmt_list(r['loops'], 3)} | "
          f"{speed} | {paired} | {100 * r['comm_share']:.0f} % | {pairs} | "
          f"{before} -> {bal} -> {after} | {r['nlocal_after'][1]:.0f} / {r['nlocal_after'][2]:.0f} | "
          f"{spread(r['others'])} |")
    w("")
    best_key = max((k for k in s if s[k]["np"] == 2), key=lambda k: s[k]["speedup_median"])
    w("Speed-ups are against the 1-rank run of the same repeat with the same newton setting (the rcb row against "
      "'1 rank, newton off'). The same 1-rank command took from 1.4 s to over 2.5 s in different sessions of this "
      "virtual machine, and single repeats up to 4.3 s, with no other task runnable inside it (load on the host "
      "that the guest cannot see); the 2-rank times moved less, so the speed-up of one configuration moved by "
      "0.3 to 0.9 between sessions (`doc/measurements.md` lists four sessions): compare configurations within "
      "one run, and read one run's verdict with that spread. Above 2 the Pair time per rank falls more than half (a rank's atoms, "
      "neighbour lists and contact histories fit the caches better).")
    w("")
    best = s[best_key]
    w(f"Target 1 -> 2 ranks >= 1.7x: best configuration '{best['label']}': **{best['speedup_median']:.2f}** "
      f"(median of the paired speed-ups; range {spread(best['speedups_paired'])}) -> "
      f"**{'met' if best['speedup_median'] >= 1.7 else 'MISSED'}** in this run; without balancing "
      f"{s['none']['speedup_median']:.2f}. Picking the best of {sum(1 for r in s.values() if r['np'] == 2)} "
      "configurations favours the one with the luckiest repeats; the paired ranges show how far a single repeat "
      "moves on this machine.")
    w("")
    w("Commands:")
    w("")
    for key, r in s.items():
        w(f"- {r['label']}: `{' '.join(r['command'])}`")
    w("")


def profile_text(prof, w):
    t = prof["table"]
    w(f"`valgrind --tool=callgrind` (instruction counts, deterministic) of both runs of `in.dense` at nside "
      f"{prof['nside']} ({prof['nsettle']} + {prof['nslide']} steps; the counter-layer is moved, so every style sees "
      "the same positions), collected inside `Verlet::run`. Pair = inclusive instructions of the pair's "
      "`compute()`, both passes (neighbour list and contacts); contacts = geometric contacts per step (as in the "
      "tables) times steps, all of which (a), (d) and (f) evaluate ((c) skips the few worn below touching). (e) is "
      "left out: on this scene it evaluates few contacts (above).")
    w("")
    names = sorted({fn for r in t.values() for fn in r["libm"]}, key=lambda fn: -sum(r["libm"].get(fn, 0) for r in t.values()))
    w("| style | contacts / asperity (geometric) | contacts evaluated | Pair instructions | per contact | vs (a) | libm calls per contact | " + " | ".join(names) + " |")
    w("|---|---|---|---|---|---|---|" + "---|" * len(names))
    a_per = t["a"]["pair"] / t["a"]["contact_steps"]
    for key, r in t.items():
        evaluated = r["evaluated"] if r["evaluated"] is not None else r["contact_steps"]
        per = r["pair"] / evaluated if evaluated else float("nan")
        libm = sum(r["libm"].values()) / evaluated if evaluated else float("nan")
        w(f"| ({key}) | {r['contacts_per_asperity']:.3f} | {evaluated:.4g} | {r['pair'] / 1e6:.1f} M | {per:.0f} | "
          f"{per / a_per:.2f} | {libm:.1f} | " +
          " | ".join(f"{r['libm'].get(fn, 0) / evaluated:.2f}" if evaluated else "-" for fn in names) + " |")
    w("")
    w("Commands: " + "; ".join(f"({k}) `valgrind --tool=callgrind --toggle-collect='LAMMPS_NS::Verlet::run*' "
                                f"{' '.join(r['command'])}`" for k, r in t.items()) +
      ", then `callgrind_annotate --inclusive=yes --tree=calling callgrind.out.*`.")
    w("")


def report(parts, args, started, img_rel, build_note):
    lines = []
    w = lines.append
    head, dirty = git_state()
    w("# Micro-scale benchmarks (pair runin/asperity)")
    w("")
    w("Generated by `bench/run-micro` (" + ("quick mode, " if args.quick else "") +
      f"{started:%Y-%m-%d %H:%M} UTC, {platform.node()}, {os.cpu_count()} cores, load average at start "
      f"{parts['load_at_start']:.2f}; source {head}{' with uncommitted changes in src/ or plugins/' if dirty else ''}"
      f"{build_note}). Before each timed run the script waited until fewer than {parts['quiet']['limit']} other "
      "tasks were runnable (/proc/stat procs_running, over 2 s) and repeated a run during which more were "
      f"({parts['quiet']['reruns']} run(s) repeated, {parts['quiet']['waited']:.0f} s of waiting in all). "
      "Reproduce every number on this page with")
    w("")
    w("    bench/run-micro            # RUNIN_BUILD_DIR=<build> to pick the lmp_runin; --quick for a smoke run")
    w("")
    w("Each number below also names the single command that reproduces it. The pair files "
      "(`bench/micro/pair_*.in`) state how their coefficients reproduce the Cu/Al contact of "
      "`potentials/CuAl.runin`:")
    w("")
    for key, (label, _, pairfile, extra) in dict(STYLES, **DENSE_EXTRA).items():
        w(f"- ({key}) {label}: `bench/micro/{pairfile}`" + "".join(f" `-var {k} {v}`" for k, v in extra.items()))
    w("")
    scenes = [parts[s] for s in ("slab", "dense") if parts.get(s)]
    if scenes:
        w("## Throughput against stock gran/hertz/history")
        w("")
        if parts.get("slab"):
            w("### Sparse slab (`bench/micro/in.slab`)")
            w("")
            w("A held rough slab of Al asperities (type 1, R = 1 um, on a square lattice of spacing 2R, summits "
              "spread +-0.05 R) under a loaded Cu counter-body (type 2, one asperity fewer per side, 1.39e7 Pa "
              "nominal) sliding at 2 m/s, dt = 1e-10 s. Load control: every style starts from the same positions "
              "and velocities, and each settles under the same load by its own contact law.")
            w("")
            scene_text(parts["slab"], w)
        if parts.get("dense"):
            w("### Contact-dense scene (`bench/micro/in.dense`)")
            w("")
            d = parts["dense"]["summary"]["a"]
            w("Two rough asperity layers pressed together: Al (type 1, held) and Cu (type 2), R = 1 um, each on a "
              "square lattice of spacing R/2 (summits of one surface closer than their diameter, as on a ground "
              "surface; pairs within a layer are excluded, as in the slab), heights spread +-0.05 R, the Cu lattice "
              "one summit fewer per side (incommensurate), its mean plane 0.15 R below touching. Displacement "
              "control: the Cu layer is moved as a rigid block at 2 m/s (fix move), so every style sees exactly "
              f"the same positions and velocities at every step. {d['contacts_per_asperity']:.2f} contacts per "
              f"asperity counted once per pair (each asperity touches {2 * d['contacts_per_asperity']:.1f} "
              "counter-asperities). At this interference elastic Hertz carries an unphysical nominal pressure "
              f"({abs(d['fz']) / (87 * 0.5e-6) ** 2 / 1e9:.0f} GPa for (a)): the scene is the heavily loaded, fully "
              "plastic contact of early run-in, and the elastic styles run it as a timing reference on the same "
              "geometry.")
            w("")
            scene_text(parts["dense"], w)
            pc = parts["dense"].get("pair_contacts", {})
            if "e" in pc and "f" in pc:
                e, f = pc["e"], pc["f"]
                w(f"(e) on this scene: the pair evaluates {e['mean']:.3f} contacts per asperity (first thermo step "
                  f"of the timed run {e['first']:.3f}, last {e['last']:.3f}) against {f['mean']:.3f} for (f). Under "
                  "displacement control a plastically flattened summit sinks to its residual interference, and each "
                  "summit has already been flattened by the deepest counter-summit that passed over it, so only "
                  "higher ones touch it again: the plastic layers conform and unload, and (e)'s Pair time here is "
                  "mostly the neighbour pass, not a measure of the cost of a contact. (f) is (e) with `reshape no` "
                  "(no worn or flattened summit in the contact, all else as (e)), so every geometric contact is "
                  "evaluated: it is the per-contact cost of the elastic-plastic law at this density.")
                w("")
        w("### Targets")
        w("")
        targets_text(scenes, w)
        w(f"![throughput]({img_rel}/micro_throughput.png)")
        w("")
    if parts.get("speedup"):
        w("## Parallel speed-up 1 -> 2 MPI ranks")
        w("")
        speedup_text(parts["speedup"], w)
        w("Reading: the contacts of the slab sit where the two lattices are in register (the Cu lattice has one "
          "asperity fewer per side), a patch that moves along x at about nside x the sliding speed (a moire "
          "pattern: 320 m/s at nside 160, 48 um of the 320 um box in the timed run). A cut across x is loaded "
          "unevenly and the imbalance changes as the patch moves; a cut parallel to the sliding direction (grid "
          "1 x 2 x 1) sees a load that does not change with sliding, so one balance keeps holding. The weight "
          "of an atom is 1 + 3 x its contacts (`compute contact/atom`; one contact costs about six atoms' fix "
          "updates and the pair work is shared by its two atoms), `bench/micro/balance.in`; LAMMPS's built-in "
          "`weight neigh` and `weight time` give one value to all atoms of a rank and so cannot place a cut "
          "within a rank's patch. `comm_style tiled` needs `newton off` for the contact history in this LAMMPS "
          "version (FixNeighHistory's reverse communication is not implemented by CommTiled), which makes the "
          "contacts across the cut be computed on both ranks.")
        w("")
    if parts.get("profile"):
        w("## Where the time goes (instruction profile)")
        w("")
        profile_text(parts["profile"], w)
        for line in parts.get("profile_notes", []):
            w(line)
        w("")
    conv = parts.get("convergence")
    if conv:
        impact = parts["impact"]
        t_r = rayleigh_time_al_slab()
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
        w("`pair runin/asperity` checks the timestep at every `run` (`plugins/common/timestep_guard.h`, on both hosts; the")
        w("per-step finite-force fix in `plugins/lammps/runin_timestep_guard.*`,")
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


def profile_notes(prof):
    """A reading of the callgrind table: where (e) spends its instructions relative to (a) and (c)."""
    t = prof["table"]
    notes = []
    if not all(k in t for k in ("a", "c", "d", "f")):
        return notes
    def per(k):
        r = t[k]
        n = r["evaluated"] if r["evaluated"] is not None else r["contact_steps"]
        return r["pair"] / n if n else float("nan"), sum(r["libm"].values()) / n if n else float("nan")
    a, c, d, f = per("a"), per("c"), per("d"), per("f")
    notes.append(f"Reading: per contact, stock (a) executes {a[0]:.0f} instructions in its pair (both passes); (d) "
                 f"{d[0]:.0f} ({d[0] / a[0]:.2f}x), (c) {c[0]:.0f} ({c[0] / a[0]:.2f}x) and the elastic-plastic (f) "
                 f"{f[0]:.0f} ({f[0] / a[0]:.1f}x) with {f[1]:.1f} libm calls per contact ((a), (c) and (d) call no "
                 "libm function: their square roots and divisions are single instructions, whose latency is why "
                 "(c) and (d) lose more time than instructions to (a)).")
    notes.append("")
    notes.append("Where (f) spends them (line-level callgrind of a `-DCMAKE_CXX_FLAGS=-g` Release build, "
                 "`callgrind_annotate --auto=yes`): in a sliding contact about half of the contact-steps load "
                 "(the interference grows until the closest approach) and half unload. A loading step of a plastic "
                 "contact evaluates the Jackson-Green fit branch (`JacksonGreen::fit`: one log, five exp, one "
                 "expm1; every power of omega* is an exponential of the one logarithm, x^(5/12) and x^(5/9) are y^3 "
                 "and y^4 of y = x^(5/36)), then, from the fit's ln x, the EKK residual ratio (two expm1) and the "
                 "unloading exponent (one exp) for the history cache, and the groove area (`sphere_groove_area`: "
                 "asin; the sine of 4 asin(s) is algebraic), about 10 libm calls; an unloading step uses the cached "
                 "curve (one log and one exp while the contact is open above its residual). The Hertz-type work "
                 "around it (Mindlin spring with its three square roots, damping, strength, wear increments) is "
                 "what (c) also does.")
    notes.append("")
    notes.append("Suggestions (`src/tribo/elastic_plastic.h`, `src/tribo/contact_model.h`): "
                 "(1) the loading curve is one unit-radius function of x = omega/omega_c per type pair: tabulate "
                 "P, a, dP/domega, the residual ratio, the unloading exponent and the groove area on a grid in "
                 "ln x (x from 1.9 to the largest x of interest, a few thousand nodes; cubic Hermite leaves "
                 "errors of order h^4 in P but h^3 in dP/domega, so check the stiffness against the closed form "
                 "at the tests' 1e-10 or use quintic nodes), so a loading step costs one log and a few "
                 "multiply-adds instead of about 10 libm calls; "
                 "(2) evaluate the groove (asin) only when the residual grows enough to matter, or from the "
                 "same table; (3) the Hertz path: `mindlin_spring` takes three square roots per contact (spring "
                 "length, projected length, force magnitude) where stock gran/hertz/history takes one after "
                 "projecting (pair granular's Mindlin, which it follows bit for bit, unit test "
                 "MindlinLammps.AgreesWithPairGranularBitForBit; (b) is as slow): the latency of that chain, not "
                 "the instruction count, is most of what (d) loses to (a) in time; and the compaction pass writes "
                 "a record for every neighbour, touching or not. "
                 "Measured dead ends (callgrind): the residual ratio from 1 - exp instead of expm1 in the fit "
                 "range saves libm instructions but made GCC outline the elastic-plastic `evaluate` (a net loss "
                 "of 1-5 % of (f)'s pair instructions; `[[gnu::always_inline]]` on single functions made GCC "
                 "outline others), so the force loop is `[[gnu::flatten]]`; under it the cheaper residual saves "
                 "about 1 % more, but it moves examples/restart_continuation by 2.5e-11 relative against its 1e-12 "
                 "reference and is not applied; "
                 "SLP vectorisation of the force loop's 3-vectors (-O3 default) added 12 % shuffles, so "
                 "`pair_runin_asperity.cpp` is built with -fno-tree-slp-vectorize.")
    return notes


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--out", default=os.path.join(SOURCE_DIR, "out", "bench-micro"))
    parser.add_argument("--doc", default=os.path.join(SOURCE_DIR, "doc", "benchmarks-micro.md"))
    parser.add_argument("--quick", action="store_true", help="small sizes, for a smoke test")
    parser.add_argument("--parts", default=",".join(ALL_PARTS),
                        help="comma-separated subset of " + ",".join(ALL_PARTS) + " (the page lists only these)")
    parser.add_argument("--quiet-load", type=float, default=0.5,
                        help="wait before each run until other runnable tasks average below this, and repeat a run "
                             "that shared the cores with more")
    parser.add_argument("--max-wait", type=float, default=3600.0,
                        help="longest wait for a quiet machine, over the whole benchmark [s]")
    parser.add_argument("--build-note", default="", help="appended to the page's header (e.g. how lmp_runin was built)")
    args = parser.parse_args()
    args.lmp = os.path.abspath(args.lmp)
    wanted = [p for p in args.parts.split(",") if p]
    for p in wanted:
        if p not in ALL_PARTS:
            sys.exit(f"run-micro: unknown part '{p}' (expected {', '.join(ALL_PARTS)})")
    quiet = Quiet(args.quiet_load, args.max_wait)
    started = datetime.datetime.utcnow()
    parts = {"load_at_start": os.getloadavg()[0]}
    shutil.rmtree(args.out, ignore_errors=True)
    for scene in ("slab", "dense"):
        if scene in wanted:
            print(f"throughput, {scene} ...", flush=True)
            parts[scene] = throughput(args.lmp, args.out, scene, args.quick, quiet)
    if "speedup" in wanted:
        print("speed-up ...", flush=True)
        parts["speedup"] = speedup(args.lmp, args.out, args.quick, quiet)
    if "profile" in wanted:
        print("callgrind profile ...", flush=True)
        parts["profile"] = callgrind_profile(args.lmp, args.out, args.quick)
        if parts["profile"]:
            parts["profile_notes"] = profile_notes(parts["profile"])
    if "convergence" in wanted:
        print("impact scan ...", flush=True)
        parts["impact"] = impact_scan(args.lmp, args.out)
        parts["impact"]["block"] = rigid_block(args.lmp, args.out)
        print("timestep convergence ...", flush=True)
        parts["convergence"] = convergence(args.lmp, args.out, args.quick)
    parts["quiet"] = {"limit": quiet.limit, "waited": quiet.waited, "reruns": quiet.reruns,
                      "before": quiet.before}
    img_dir = os.path.join(os.path.dirname(os.path.abspath(args.doc)), "img")
    plot([parts[s] for s in ("slab", "dense") if parts.get(s)], parts.get("convergence"), img_dir)
    build_note = f"; {args.build_note}" if args.build_note else ""
    text = report(parts, args, started, os.path.relpath(img_dir, os.path.dirname(os.path.abspath(args.doc))),
                  build_note)
    write_atomically(args.doc, text + "\n")
    if "impact" in parts:
        parts["impact"]["table"] = {f"{v}:{f}": x for (v, f), x in parts["impact"]["table"].items()}
    write_atomically(os.path.join(args.out, "results.json"), json.dumps(parts, indent=1, default=str))
    print(f"wrote {args.doc} and {img_dir}/micro_*.png")


if __name__ == "__main__":
    main()
