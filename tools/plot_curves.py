#!/usr/bin/python3
"""Plot a pin-on-disk run-in curve written by `runin pin-on-disk`.

usage: plot_curves.py CSV PNG [--title TEXT]

Top panel: friction force, mobilised friction coefficient F/W and the law's run-in
value mu(s) (during slip) vs time; stick phase shaded, break-away marked. Bottom panel: sliding speed and sliding distance vs time.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="pin-on-disk run-in")
    args = parser.parse_args()

    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    t = data["t_s"]
    slip = data["state_slip"] > 0.5

    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(args.title)

    top.plot(t, data["friction_force_N"], color="tab:red", label="friction force")
    top.set_ylabel("friction force (N)", color="tab:red")
    mu_axis = top.twinx()
    mu_axis.plot(t, data["mu"], color="tab:blue", linestyle="--", label="mu = F / W")
    mu_axis.plot(t[slip], data["mu_law"][slip], color="tab:orange", linestyle="-.",
                 label="law mu(s), no speed term")
    mu_axis.set_ylabel("friction coefficient", color="tab:blue")
    mu_axis.legend(loc="lower left", fontsize=8)

    # Shade the stick intervals and mark each stick -> slip transition.
    edges = np.flatnonzero(np.diff(slip.astype(int)) != 0)
    bounds = np.concatenate(([0], edges + 1, [len(t)]))
    for start, stop in zip(bounds[:-1], bounds[1:]):
        if not slip[start]:
            top.axvspan(t[start], t[stop - 1], color="0.9", zorder=0)
    for i in edges:
        if not slip[i] and slip[i + 1]:
            top.axvline(t[i + 1], color="k", linewidth=0.8, linestyle=":")
            top.annotate(" break-away", (t[i + 1], top.get_ylim()[1]), va="top", fontsize=8)
    top.grid(alpha=0.3)

    bottom.plot(t, data["speed_m_s"], color="tab:green")
    bottom.set_ylabel("speed V (m/s)", color="tab:green")
    distance_axis = bottom.twinx()
    distance_axis.plot(t, data["sliding_distance_m"], color="tab:purple", linestyle="--")
    distance_axis.set_ylabel("sliding distance s (m)", color="tab:purple")
    bottom.set_xlabel("time t (s)")
    bottom.grid(alpha=0.3)

    fig.savefig(args.png, dpi=120, format="png")


if __name__ == "__main__":
    main()
