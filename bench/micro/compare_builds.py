#!/usr/bin/env python3
"""Pair time of two lmp_runin builds on the contact-dense scene, interleaved (A B A B ...), per style.

  /usr/bin/python3 bench/micro/compare_builds.py --before OLD/lmp_runin --after NEW/lmp_runin
      [--styles d,f] [--repeats 7] [--nside 87] [--out DIR] [--concurrent]

For a refactor that must not slow the kernel: both builds run the same deck, so they evaluate the same contacts
(checked: their thermo rows must agree to 1e-9 relative) and the ratio of Pair timers is the ratio per evaluated
contact-step. Each repeat runs both builds back to back in alternating order; the quoted figure is the median of
the paired ratios after/before, with their range, so drifts of the machine's speed cancel pair by pair.

This guest's runs are bimodal: most take the undisturbed time, and a share (a third or more, at random) take
1.3-1.9 times as long while the host is busy, so paired ratios spread over 0.6-1.6 even for one binary run against
itself. The figure that resolves a few per cent is the ratio of the undisturbed times: the mean of each build's fastest
quarter of runs (and, beside it, the ratio of the fastest runs); an A/A run (--same-binary) shows its resolution.

--concurrent runs the two builds of a pair at the same time, each pinned to its own core (taskset), and swaps the
cores every repeat: both then see the same moment of a guest whose speed drifts by tens of per cent within minutes,
and the swap cancels a difference between the cores. --same-binary gives both sides the --after build (an A/A run
that shows the method's own spread).
"""
import argparse
import math
import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_micro as rm    # noqa: E402


def same_rows(a, b, tol=1e-9):
    if len(a) != len(b):
        return False
    for ra, rb in zip(a, b):
        for key in ra:
            x, y = ra[key], rb.get(key)
            if y is None or abs(x - y) > tol * max(1.0, abs(x), abs(y)):
                return False
    return True


def mean_ratio_interval(ratios, draws=20000, seed=1):
    """Geometric mean of the paired ratios and its 95 % bootstrap interval (resampling the pairs)."""
    logs = [math.log(r) for r in ratios]
    rng = random.Random(seed)
    means = sorted(statistics.fmean(rng.choices(logs, k=len(logs))) for _ in range(draws))
    return (math.exp(statistics.fmean(logs)), math.exp(means[int(0.025 * draws)]),
            math.exp(means[int(0.975 * draws) - 1]))


def fastest_quarter(times):
    """Mean of the fastest quarter of a build's runs (at least one)."""
    times = sorted(times)
    return statistics.fmean(times[:max(1, len(times) // 4)])


def fail(message):
    """A bad option: one line naming it, exit 2 (argparse's own code for a usage error)."""
    print(f"compare_builds: error: {message}", file=sys.stderr)
    sys.exit(2)


class OneLineParser(argparse.ArgumentParser):
    def error(self, message):
        fail(f"{message} (see --help)")


def check_build(option, path):
    """An lmp_runin: an executable file whose -h lists pair style runin/asperity."""
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        fail(f"{option}: {path} is not an executable file (give the lmp_runin of a build)")
    try:
        help_text = subprocess.run([path, "-h"], env=rm.mpi_env(), capture_output=True, text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError) as e:
        fail(f"{option}: {path} -h did not run ({e}); give the lmp_runin of a build")
    if "runin/asperity" not in help_text:
        fail(f"{option}: {path} is not an lmp_runin (its -h lists no pair style runin/asperity)")


def main():
    ap = OneLineParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", required=True, help="lmp_runin of the tree before the change")
    ap.add_argument("--after", required=True, help="lmp_runin of the tree after the change")
    ap.add_argument("--styles", default="d,f", help="style keys of bench/micro/run_micro.py (default d,f)")
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--nside", type=int, default=rm.SCENES["dense"]["full"]["nside"])
    ap.add_argument("--out", default=None)
    ap.add_argument("--concurrent", action="store_true",
                    help="run each pair at the same time on cores 0 and 1, swapping cores every repeat")
    ap.add_argument("--same-binary", action="store_true", help="A/A run: --after on both sides")
    args = ap.parse_args()
    if args.repeats < 1:
        fail(f"--repeats: the number of paired runs must be >= 1, got {args.repeats}")
    # the deck's counter-body has nside - 1 summits a side
    if args.nside < 2:
        fail(f"--nside: summits per side of the dense scene must be >= 2, got {args.nside}")
    if args.out is not None and os.path.exists(args.out) and not os.path.isdir(args.out):
        fail(f"--out: {args.out} is an existing file, not a directory")
    if args.concurrent:
        if shutil.which("taskset") is None:
            fail("--concurrent: pins each run to a core with taskset, which is not on PATH")
        if not {0, 1} <= os.sched_getaffinity(0):
            fail("--concurrent: pins the runs to cores 0 and 1, which this process may not use all of")
    styles = dict(rm.STYLES, **rm.DENSE_EXTRA)
    keys = args.styles.split(",")
    for key in keys:
        if key not in styles:
            fail(f"--styles: unknown style '{key}' (known: {', '.join(styles)})")
        if keys.count(key) > 1:
            fail(f"--styles: style '{key}' given twice")
    if args.same_binary:
        args.before = args.after
    check_build("--after", args.after)
    if not args.same_binary:
        check_build("--before", args.before)
    out = args.out or tempfile.mkdtemp(prefix="compare_builds_")
    params = dict(rm.SCENES["dense"]["full"])
    params.pop("repeats")
    params["nside"] = args.nside
    deck = os.path.join(rm.MICRO, "in.dense")
    builds = {"before": os.path.abspath(args.before), "after": os.path.abspath(args.after)}
    ratios = {key: [] for key in keys}
    pair = {key: {"before": [], "after": []} for key in keys}
    for repeat in range(args.repeats):
        order = ("before", "after") if repeat % 2 == 0 else ("after", "before")
        for key in keys:
            variables = dict(rm.style_vars(key, styles), **params)
            runs = {}
            if args.concurrent:
                with ThreadPoolExecutor(max_workers=2) as pool:
                    jobs = {which: pool.submit(rm.run_deck, builds[which], os.path.join(out, f"{key}_{which}{repeat}"),
                                               variables, deck=deck, prefix=("taskset", "-c", str(core)))
                            for core, which in enumerate(order)}
                    runs = {which: job.result() for which, job in jobs.items()}
            else:
                for which in order:
                    runs[which] = rm.run_deck(builds[which], os.path.join(out, f"{key}_{which}{repeat}"), variables,
                                              deck=deck)
            if not same_rows(runs["before"]["rows"], runs["after"]["rows"]):
                sys.exit(f"compare_builds: style ({key}): the two builds' thermo rows differ, so they do not "
                         "evaluate the same contacts and their Pair timers cannot be compared")
            pb, pa = runs["before"]["timers"]["Pair"], runs["after"]["timers"]["Pair"]
            pair[key]["before"].append(pb)
            pair[key]["after"].append(pa)
            ratios[key].append(pa / pb)
            print(f"  ({key}) repeat {repeat}: Pair before {pb:.3f} s, after {pa:.3f} s, ratio {pa / pb:.4f}, "
                  f"other runnable tasks {runs['before']['other']:.2f}/{runs['after']['other']:.2f}", flush=True)
    mode = "concurrent on cores 0/1, swapped each repeat" if args.concurrent else "back to back"
    print(f"dense scene, nside {args.nside}, {args.repeats} paired repeats ({mode}); Pair time after/before "
          "(> 1: the change is slower):")
    for key in keys:
        r = ratios[key]
        gmean, low, high = mean_ratio_interval(r)
        print(f"  ({key}) {styles[key][1]}: median {statistics.median(r):.4f} (range {min(r):.4f}-{max(r):.4f}); "
              f"geometric mean {gmean:.4f}, 95 % bootstrap interval {low:.4f}-{high:.4f}; "
              f"fastest quarter after/before {fastest_quarter(pair[key]['after']) / fastest_quarter(pair[key]['before']):.4f}, "
              f"fastest run {min(pair[key]['after']) / min(pair[key]['before']):.4f}; "
              f"median Pair s before {statistics.median(pair[key]['before']):.3f}, "
              f"after {statistics.median(pair[key]['after']):.3f}")


if __name__ == "__main__":
    main()
