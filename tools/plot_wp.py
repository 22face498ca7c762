#!/usr/bin/python3
"""Work-precision plot of a bench/wp_* CSV (columns method, setting, rel_error, wall_time_s):
relative error against wall time, one line per method, each point labelled with its tolerance or step.

usage: plot_wp.py CSV PNG --title T --ylabel Y [--target-error E] [--target-ms M]
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MARKERS = {"cvode_bdf": "o", "cvode_adams": "s", "euler_fixed": "^", "rk4_fixed": "v"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="work-precision")
    parser.add_argument("--ylabel", default="max relative error")
    parser.add_argument("--target-error", type=float, help="horizontal line: the accuracy target")
    parser.add_argument("--target-ms", type=float, help="vertical line: the run-time target")
    args = parser.parse_args()

    data = np.genfromtxt(args.csv, delimiter=",", names=True, dtype=None, encoding="utf-8")
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    for method in dict.fromkeys(data["method"]):    # in the order of the CSV
        rows = data[data["method"] == method]
        ax.loglog(rows["wall_time_s"] * 1e3, np.maximum(rows["rel_error"], 1e-16), marker=MARKERS.get(method, "x"),
                  label=method)
        for r in rows:
            ax.annotate(f"{r['setting']:g}", (r["wall_time_s"] * 1e3, max(r["rel_error"], 1e-16)), fontsize=7,
                        textcoords="offset points", xytext=(3, 3))
    if args.target_error:
        ax.axhline(args.target_error, color="k", linestyle=":", linewidth=0.8, label=f"{args.target_error:g} target")
    if args.target_ms:
        ax.axvline(args.target_ms, color="k", linestyle="--", linewidth=0.8, label=f"{args.target_ms:g} ms target")
    ax.set_xlabel("wall time per run (ms, median)")
    ax.set_ylabel(args.ylabel)
    ax.set_title(args.title)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    tmp = args.png + ".part.png"
    fig.savefig(tmp, dpi=120, format="png")
    os.replace(tmp, args.png)


if __name__ == "__main__":
    main()
