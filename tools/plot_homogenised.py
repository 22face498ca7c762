#!/usr/bin/python3
"""Micro and continuum run-in side by side: the state law (runin homogenise) and the machine elements
that ran on it (runin pin-on-disk / journal-bearing / piston-ring with friction.model = "state_law").

usage: plot_homogenised.py LAW_JSON PNG CSV [--element LABEL CSV PRESSURE_PA] ...

Panels: (1) mu_body against the worn depth h: the cell at each law pressure (mean, seed band) and each element's
mu_eff against its mean node depth; (2) Rq against h (cell; each element's Rq(p, h_mean) from the law); (3) mu
against time for each element, with the seed band of the law along the element's (p, h_mean(t)).
An element CSV needs t_s, mu_eff and h_mean_m columns (the journal bearing's lower_ half is used when present).
The CSV output holds the element curves with their band: element, t_s, h_mean_m, mu_eff, mu_low, mu_high, rq_m.
Uses Debian's matplotlib and numpy: run with /usr/bin/python3.
"""
import argparse
import csv
import math
import os
import tempfile

import numpy as np
import matplotlib

from state_law import StateLaw  # the C++ reader's interpolation rule (tools/state_law.py)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_element(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    prefix = "lower_" if "lower_mu_eff" in rows[0] else ""
    for key in ("t_s", prefix + "mu_eff", prefix + "h_mean_m"):
        if key not in rows[0]:
            raise SystemExit(f"{path}: no column {key} (run the element with friction.model = \"state_law\")")
    t = np.array([float(r["t_s"]) for r in rows])
    mu = np.array([float(r[prefix + "mu_eff"]) for r in rows])
    h = np.array([float(r[prefix + "h_mean_m"]) for r in rows])
    return t, mu, h


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("law")
    parser.add_argument("png")
    parser.add_argument("csv")
    parser.add_argument("--element", nargs=3, action="append", default=[], metavar=("LABEL", "CSV", "PRESSURE_PA"))
    args = parser.parse_args()
    law = StateLaw(args.law)

    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(law.p)))
    h_nm = np.array(law.h) * 1e9
    for i, p in enumerate(law.p):
        for ax, field, scale in ((axes[0], "mu_body", 1.0), (axes[1], "rq", 1e9)):
            mean = np.array(law.grid(field)[i]) * scale
            ax.plot(h_nm, mean, color=colours[i], lw=1.2, label=f"cell {p / 1e6:.3g} MPa" if ax is axes[0] else None)
            if "low" in law.fields[field]:
                ax.fill_between(h_nm, np.array(law.grid(field, "low")[i]) * scale, np.array(law.grid(field, "high")[i]) * scale,
                                color=colours[i], alpha=0.2, lw=0)

    rows = []
    for (label, path, pressure), style in zip(args.element, ("--", "-.", ":", (0, (5, 1)))):
        p = float(pressure)
        t, mu, h = read_element(path)
        low = np.array([law.value("mu_body", p, x, "low") for x in h])
        high = np.array([law.value("mu_body", p, x, "high") for x in h])
        rq = np.array([law.value("rq", p, x) for x in h])
        axes[0].plot(h * 1e9, mu, "k", ls=style, lw=1.5, label=f"{label} (continuum, {p / 1e6:.3g} MPa)")
        axes[1].plot(h * 1e9, rq * 1e9, "k", ls=style, lw=1.5, label=f"{label} Rq(p, h_mean)")
        axes[2].plot(t, mu, "k", ls=style, lw=1.5, label=label)
        axes[2].fill_between(t, low, high, color="0.6", alpha=0.35, lw=0)
        rows += [(label, a, b, c, d, e, f) for a, b, c, d, e, f in zip(t, h, mu, low, high, rq)]

    axes[0].set(xlabel="mean worn depth h [nm]", ylabel="mu_body", title="friction against worn depth")
    axes[1].set(xlabel="mean worn depth h [nm]", ylabel="Rq [nm]", title="roughness against worn depth")
    axes[2].set(xlabel="t [s]", ylabel="mu_eff", title="machine elements (band: the law's seed band)")
    for ax in axes[:2]:  # the law's range (it holds its last column beyond; elements may wear further)
        ax.set_xlim(0.0, 1.5 * h_nm[-1])
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(f"Micro (cell, seed bands) and continuum (per-node state law): {os.path.basename(args.law)}")
    fig.tight_layout()
    for target, writer in ((args.png, lambda name: fig.savefig(name, dpi=120)),
                           (args.csv, lambda name: write_csv(name, rows))):
        directory = os.path.dirname(os.path.abspath(target))
        fd, tmp = tempfile.mkstemp(dir=directory, suffix=os.path.splitext(target)[1])
        os.close(fd)
        writer(tmp)
        os.replace(tmp, target)  # atomic: a reader never sees half a file


def write_csv(name, rows):
    with open(name, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["element", "t_s", "h_mean_m", "mu_eff", "mu_low", "mu_high", "rq_m"])
        for r in rows:
            out.writerow([r[0]] + [f"{x:.9g}" if isinstance(x, float) or isinstance(x, np.floating) else x
                                   for x in r[1:]])


if __name__ == "__main__":
    main()
