#!/usr/bin/env python3
"""Pair time of two lmp_runin builds on the contact-dense scene, interleaved (A B A B ...), per style.

  /usr/bin/python3 bench/micro/compare_builds.py --before OLD/lmp_runin --after NEW/lmp_runin
      [--styles d,f] [--repeats 7] [--nside 87] [--out DIR]

For a refactor that must not slow the kernel: both builds run the same deck, so they evaluate the same contacts
(checked: their thermo rows must agree to 1e-9 relative) and the ratio of Pair timers is the ratio per evaluated
contact-step. Each repeat runs both builds back to back in alternating order; the quoted figure is the median of
the paired ratios after/before, with their range, so drifts of the machine's speed cancel pair by pair.
"""
import argparse
import os
import statistics
import sys
import tempfile

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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", required=True, help="lmp_runin of the tree before the change")
    ap.add_argument("--after", required=True, help="lmp_runin of the tree after the change")
    ap.add_argument("--styles", default="d,f", help="style keys of bench/micro/run_micro.py (default d,f)")
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--nside", type=int, default=rm.SCENES["dense"]["full"]["nside"])
    ap.add_argument("--out", default=None)
    args = ap.parse_args()
    for path in (args.before, args.after):
        if not os.access(path, os.X_OK):
            sys.exit(f"compare_builds: --before/--after: {path} is not an executable lmp_runin")
    styles = dict(rm.STYLES, **rm.DENSE_EXTRA)
    keys = args.styles.split(",")
    for key in keys:
        if key not in styles:
            sys.exit(f"compare_builds: --styles: unknown style '{key}' (known: {', '.join(styles)})")
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
    print(f"dense scene, nside {args.nside}, {args.repeats} paired repeats; Pair time after/before "
          "(> 1: the change is slower):")
    for key in keys:
        r = ratios[key]
        print(f"  ({key}) {styles[key][1]}: median {statistics.median(r):.4f} (range {min(r):.4f}-{max(r):.4f}); "
              f"median Pair s before {statistics.median(pair[key]['before']):.3f}, "
              f"after {statistics.median(pair[key]['after']):.3f}")


if __name__ == "__main__":
    main()
