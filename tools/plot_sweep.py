#!/usr/bin/python3
"""Tornado plot of a `runin sweep` (sweep.csv): for each key, peak friction, break-away time and time to steady
state at every value of the key (grey bar: the range its decade spans; black: the case's own value).

usage: plot_sweep.py SWEEP_CSV PNG [--title TEXT]

A time not reached within a run (an empty cell) is an arrow at the panel's right edge, labelled.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METRICS = [("peak_friction_force_N", "peak friction force [N]"), ("breakaway_time_s", "break-away time [s]"),
           ("steady_time_s", "time to steady state [s]")]


def number(cell):
    return float(cell) if cell not in ("", None) else math.nan


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    keys = list(dict.fromkeys(r["key"] for r in rows))
    fig, axes = plt.subplots(1, len(METRICS), figsize=(4.2 * len(METRICS), 0.9 + 0.55 * len(keys)), sharey=True)
    for axis, (column, label) in zip(axes, METRICS):
        finite = [number(r[column]) for r in rows if r["status"] == "ok" and not math.isnan(number(r[column]))]
        right = max(finite) if finite else 1.0
        for y, key in enumerate(keys):
            mine = sorted((r for r in rows if r["key"] == key), key=lambda r: number(r["factor"]))
            values = [number(r[column]) if r["status"] == "ok" else math.nan for r in mine]
            shown = [v for v in values if not math.isnan(v)]
            if len(shown) >= 2:    # the tornado bar: the range the key's decade spans
                axis.barh(y, max(shown) - min(shown), left=min(shown), height=0.5, color="0.85")
            for r, v in zip(mine, values):
                factor = number(r["factor"])
                colour = "black" if factor == 1.0 else "tab:blue" if factor < 1.0 else "tab:red"
                if math.isnan(v):
                    note = "failed" if r["status"] != "ok" else "not reached"
                    axis.plot([right], [y], marker=">", color=colour)
                    axis.annotate(f"x{factor:.3g} {note}", (right, y), fontsize=7, ha="right", color=colour,
                                  xytext=(-8, 6 if factor > 1.0 else -12), textcoords="offset points")
                else:
                    axis.plot([v], [y], marker="o" if factor == 1.0 else "s", color=colour,
                              label=(f"x {factor:.3g}" if y == 0 else None))
        axis.set_xlabel(label)
        axis.grid(axis="x", alpha=0.3)
    axes[0].set_yticks(range(len(keys)))
    axes[0].set_yticklabels(keys)
    axes[0].legend(loc="best", fontsize=8, title="key value / case value")
    fig.suptitle(args.title or "runin sweep")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)


if __name__ == "__main__":
    main()
