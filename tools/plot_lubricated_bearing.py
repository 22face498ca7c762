#!/usr/bin/python3
"""Plot the output of the lubricated mode of `runin journal-bearing`.

usage: plot_lubricated_bearing.py runin LUBRICATED_CSV PNG [--title TEXT]
       plot_lubricated_bearing.py stribeck STRIBECK_CSV PNG [--title TEXT]

runin: friction (total, viscous, boundary), asperity load share, lambda and the contact roughness R, worn depth
against time (symmetric-log time: the run-in takes seconds of an hour).
stribeck: friction and asperity share against the Hersey number eta N / P, and friction against lambda.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def runin(args):
    d = np.genfromtxt(args.csv, delimiter=",", names=True)
    t = d["t_s"]
    tp = t
    linthresh = t[1] if len(t) > 1 and t[1] > 0 else 1.0
    fig, axes = plt.subplots(2, 2, figsize=(11, 8), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    ax = axes[0, 0]
    ax.plot(tp, d["mu"], label="total")
    ax.plot(tp, d["mu_viscous"], "--", label="viscous")
    ax.plot(tp, np.maximum(d["mu_boundary"], 1e-12), ":", label="boundary")
    ax.set_yscale("log")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("friction coefficient")
    ax.legend(fontsize=8)
    ax = axes[0, 1]
    ax.plot(tp, np.maximum(d["asperity_share"], 1e-12), color="tab:red")
    ax.set_yscale("log")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("asperity load share")
    ax = axes[1, 0]
    ax.plot(tp, d["lambda"], color="tab:green", label="lambda = h_min / sigma")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("lambda")
    ax2 = ax.twinx()
    ax2.plot(tp, 1e9 * d["R_m"], color="tab:purple", label="R (nm)")
    ax2.set_ylabel("contact roughness R (nm)")
    ax = axes[1, 1]
    ax.plot(tp, 1e9 * d["h_max_m"], label="bore, max")
    ax.plot(tp, 1e9 * d["h_mean_m"], label="bore, mean")
    ax.plot(tp, 1e9 * d["shaft_depth_m"], "--", label="journal, mean")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("worn depth (nm)")
    ax.legend(fontsize=8)
    for ax in list(axes.flat) + [ax2]:
        ax.set_xscale("symlog", linthresh=linthresh)
        ax.set_xlim(0.0, t[-1])
    fig.savefig(args.png, dpi=110, format="png")


def stribeck(args):
    d = np.genfromtxt(args.csv, delimiter=",", names=True)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    ax = axes[0]
    ax.loglog(d["hersey"], d["mu"], "o-", markersize=3, label="mu")
    ax.set_xlabel("Hersey number eta N / P")
    ax.set_ylabel("friction coefficient")
    ax2 = ax.twinx()
    ax2.semilogx(d["hersey"], d["asperity_share"], color="tab:red", label="asperity share")
    ax2.set_ylabel("asperity load share", color="tab:red")
    ax = axes[1]
    ax.loglog(d["lambda"], d["mu"], "o-", markersize=3)
    ax.set_xlabel("lambda = h_min / sigma")
    ax.set_ylabel("friction coefficient")
    fig.savefig(args.png, dpi=110, format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["runin", "stribeck"])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="lubricated journal bearing")
    args = parser.parse_args()
    runin(args) if args.mode == "runin" else stribeck(args)


if __name__ == "__main__":
    main()
