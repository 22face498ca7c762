#!/usr/bin/python3
"""Plot the two-mechanism roughness-feedback model written by `runin feedback`.

usage: plot_feedback.py curve CSV PNG [--title T] --r-star R --r-min-wear R --r-min-friction R --mu-min MU
       plot_feedback.py sweep CURVES_CSV SWEEP_CSV PNG --parameter NAME [--title T]

curve: mu(t) (top) and R(t) (bottom) with R*, R_min_wear and R_min_friction as horizontal
lines, the analogue of thesis Figs. 3.3/3.4. sweep: the same two panels, one curve per value.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def curve(args):
    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    t = data["t"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    top.plot(t, data["mu"], color="tab:blue", label="mu(t)")
    top.axhline(args.mu_min, color="k", linestyle=":", linewidth=1, label=f"global min mu = {args.mu_min:.4g}")
    top.set_ylabel("friction coefficient mu")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)

    bottom.plot(t, data["R"], color="tab:red", label="R(t)")
    lines = [(args.r_star, "R* (stationary)", "k", "--"),
             (args.r_min_wear, "R_min_wear", "tab:green", ":"),
             (args.r_min_friction, "R_min_friction", "tab:purple", "-.")]
    for value, name, colour, style in lines:
        bottom.axhline(value, color=colour, linestyle=style, linewidth=1.2, label=f"{name} = {value:.4g}")
    bottom.set_ylabel("roughness R")
    bottom.set_xlabel("time t")
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
    fig.savefig(args.png, dpi=120, format="png")


def sweep(args):
    data = np.genfromtxt(args.curves, delimiter=",", names=True)
    summary = np.genfromtxt(args.sweep, delimiter=",", names=True)
    values = np.atleast_1d(summary[summary.dtype.names[0]])
    r_star = np.atleast_1d(summary["R_star"])
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(textwrap.fill(f"{args.title}: sweep of {args.parameter}", 90), fontsize=10)
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(values)))
    for value, rs, colour in zip(values, r_star, colours):
        rows = data["value"] == value
        label = f"{args.parameter} = {value:.4g}"
        top.plot(data["t"][rows], data["mu"][rows], color=colour, label=label)
        bottom.plot(data["t"][rows], data["R"][rows], color=colour, label=label)
        bottom.axhline(rs, color=colour, linestyle="--", linewidth=0.8)
    top.set_ylabel("friction coefficient mu")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    bottom.set_ylabel("roughness R (dashed: R*)")
    bottom.set_xlabel("time t")
    bottom.grid(alpha=0.3)
    fig.savefig(args.png, dpi=120, format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="mode", required=True)
    c = sub.add_parser("curve")
    c.add_argument("csv")
    c.add_argument("png")
    c.add_argument("--title", default="roughness feedback")
    for name in ("--r-star", "--r-min-wear", "--r-min-friction", "--mu-min"):
        c.add_argument(name, type=float, required=True)
    s = sub.add_parser("sweep")
    s.add_argument("curves")
    s.add_argument("sweep")
    s.add_argument("png")
    s.add_argument("--parameter", required=True)
    s.add_argument("--title", default="roughness feedback")
    args = parser.parse_args()
    curve(args) if args.mode == "curve" else sweep(args)


if __name__ == "__main__":
    main()
