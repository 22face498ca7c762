#!/usr/bin/python3
"""A_r H / W against the plasticity index psi from the CSV of tests/lammps/ep_gw.py sweep.

usage: plot_ep_gw.py CSV PNG
Curves: the Hertz-GW and elastic-plastic (Jackson-Green) quadratures at d = sigma (dashed: d = 0 and
2 sigma for the sigma/R family); points: fix runin/wall on 1e4 summits at d = sigma. Shaded: the
Bowden-Tabor band 0.7-1.3. Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FAMILIES = {"sigma/R": ("C0", "o", "E*/H = 112 (steel), sigma/R varied"),
            "E*/H": ("C3", "s", "sigma/R = 0.01, E*/H varied")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    args = parser.parse_args()

    rows = list(csv.DictReader(open(args.csv)))
    for row in rows:
        for key in ("psi", "d_over_sigma", "ArH_over_W_hertz_gw", "ArH_over_W_ep_quadrature"):
            row[key] = float(row[key])

    def select(source, family, d):
        picked = [r for r in rows if r["source"] == source and r["family"] == family and r["d_over_sigma"] == d]
        return sorted(picked, key=lambda r: r["psi"])

    fig, ax = plt.subplots(figsize=(7.5, 5.5), constrained_layout=True)
    ax.axhspan(0.7, 1.3, color="0.9", zorder=0, label="Bowden-Tabor band 0.7-1.3")
    ax.axhline(1.0, color="0.5", linewidth=0.8, zorder=1)
    for psi, text in ((0.6, "psi = 0.6"), (10.0, "psi = 10")):
        ax.axvline(psi, color="0.5", linestyle=":", linewidth=0.8)
        ax.annotate(text, (psi, 40.0), rotation=90, fontsize=8, ha="right", va="top", color="0.4")
    hertz = select("quadrature", "sigma/R", 1.0)
    ax.loglog([r["psi"] for r in hertz], [r["ArH_over_W_hertz_gw"] for r in hertz], color="k",
              label="Hertz-GW quadrature (any family)")
    for d in (0.0, 2.0):
        curve = select("quadrature", "sigma/R", d)
        ax.loglog([r["psi"] for r in curve], [r["ArH_over_W_hertz_gw"] for r in curve], color="k", linestyle="--",
                  linewidth=0.7)
    for family, (color, marker, text) in FAMILIES.items():
        curve = select("quadrature", family, 1.0)
        ax.loglog([r["psi"] for r in curve], [r["ArH_over_W_ep_quadrature"] for r in curve], color=color,
                  label=f"elastic-plastic quadrature, {text}")
        if family == "sigma/R":
            for d in (0.0, 2.0):
                curve = select("quadrature", family, d)
                ax.loglog([r["psi"] for r in curve], [r["ArH_over_W_ep_quadrature"] for r in curve], color=color,
                          linestyle="--", linewidth=0.7)
        points = [r for r in rows if r["source"] == "lammps" and r["family"] == family]
        ax.loglog([r["psi"] for r in points], [float(r["ArH_over_W_lammps"]) for r in points], linestyle="none",
                  marker=marker, markerfacecolor="none", color=color, label=f"fix runin/wall, 1e4 summits ({family})")
    ax.set_xlabel(r"plasticity index $\psi = (E^*/H)\,\sqrt{\sigma/R}$,  H = 2.8 $S_y$")
    ax.set_ylabel(r"$A_r H / W$")
    ax.set_title("Rough surface on a flat: real area x hardness / load (d = sigma; dashed: d = 0, 2 sigma)",
                 fontsize=9)
    ax.set_xlim(0.08, 125)
    ax.set_ylim(0.02, 50)
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=7.5, loc="lower left")
    fig.savefig(args.png, dpi=130)


if __name__ == "__main__":
    main()
