#!/usr/bin/python3
"""Work-precision plot of bench/wp_journal_bearing: error of s vs wall time, one panel per mu0.

usage: plot_wp_journal_bearing.py CSV PNG [TITLE]
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    path, png = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else "journal bearing, 2 s thesis case: work-precision"
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["case"] == "thesis_2s"]
    mus = sorted({r["mu0"] for r in rows}, key=float, reverse=True)
    fig, axes = plt.subplots(1, len(mus), figsize=(4.2 * len(mus), 4), sharey=True, constrained_layout=True)
    fig.suptitle(title)
    for axis, mu0 in zip(np.atleast_1d(axes), mus):
        for method, marker in (("cvode_bdf", "o-"), ("cvode_adams", "s-"), ("euler_fixed", "^--")):
            sel = [r for r in rows if r["mu0"] == mu0 and r["method"] == method]
            axis.loglog([1e3 * float(r["wall_seconds"]) for r in sel], [float(r["error"]) for r in sel], marker,
                        label=method)
            for r in sel:
                axis.annotate(f"{float(r['tolerance_or_step']):g}", (1e3 * float(r["wall_seconds"]), float(r["error"])),
                              fontsize=6, textcoords="offset points", xytext=(3, 3))
        axis.axhline(1e-6, color="0.5", linestyle=":")
        axis.axvline(20, color="0.5", linestyle=":")
        axis.set_title(f"mu0 = {mu0}")
        axis.set_xlabel("wall time (ms, Google Benchmark median)")
        axis.grid(alpha=0.3, which="both")
    np.atleast_1d(axes)[0].set_ylabel("max |s - s_ref| / s_ref(2 s)")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    fig.savefig(png, dpi=110, format="png")


if __name__ == "__main__":
    main()
