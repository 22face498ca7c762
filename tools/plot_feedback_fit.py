#!/usr/bin/python3
"""Plot the data against the fitted feedback model, from the comparison CSV of `runin fit-feedback`.

usage: plot_feedback_fit.py CSV PNG [--title T] --r-star R [--t-label L]

mu(t) (top) and R(t) (bottom): the data as points, the fitted model (exact solution) as a line, R* dashed;
the model's time (t - t0, scaled) on the x axis. Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    parser.add_argument("--r-star", type=float, required=True)
    parser.add_argument("--t-label", default="t - t0")
    args = parser.parse_args()

    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    t = np.atleast_1d(data["t_model"])
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    marker = dict(linestyle="none", marker="o", markersize=3, alpha=0.6)
    top.plot(t, data["mu"], color="tab:blue", label="data", **marker)
    top.plot(t, data["mu_fit"], color="k", linewidth=1.2, label="fit: mu(R(t)) = C1 R + C2/R")
    top.set_ylabel("friction coefficient mu")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)

    bottom.plot(t, data["R"], color="tab:red", label="data", **marker)
    bottom.plot(t, data["R_fit"], color="k", linewidth=1.2, label="fit: R^2 = R*^2 + (R0^2 - R*^2) exp(-2 A K1 t)")
    bottom.axhline(args.r_star, color="k", linestyle="--", linewidth=1, label=f"R* = {args.r_star:.4g}")
    bottom.set_ylabel("roughness R")
    bottom.set_xlabel(args.t_label)
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
    fig.savefig(args.png, dpi=120, format="png")


if __name__ == "__main__":
    main()
