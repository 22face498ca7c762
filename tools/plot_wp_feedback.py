#!/usr/bin/python3
"""Work-precision plot of bench/wp_feedback: relative error of R vs wall time per method.

usage: plot_wp_feedback.py CSV PNG [TITLE]
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    csv, png = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else "work-precision"
    data = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding="utf-8")
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    for method, marker in (("cvode_bdf", "o"), ("cvode_adams", "s"), ("euler_fixed", "^"), ("rk4_fixed", "v")):
        rows = data[data["method"] == method]
        if len(rows) == 0:
            continue
        ax.loglog(rows["wall_time_s"] * 1e3, np.maximum(rows["rel_error"], 1e-16), marker=marker, label=method)
        for r in rows:
            ax.annotate(f"{r['setting']:g}", (r["wall_time_s"] * 1e3, max(r["rel_error"], 1e-16)), fontsize=7,
                        textcoords="offset points", xytext=(3, 3))
    ax.axhline(1e-8, color="k", linestyle=":", linewidth=0.8, label="1e-8 (CLI default accuracy)")
    ax.set_xlabel("wall time per run (ms, median)")
    ax.set_ylabel("max relative error of R vs closed form, 40 s grid")
    ax.set_title(title)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.savefig(png, dpi=120, format="png")


if __name__ == "__main__":
    main()
