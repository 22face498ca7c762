#!/usr/bin/python3
"""Plot journal-bearing run-in curves written by `runin journal-bearing`.

usage: plot_journal_bearing.py curve CSV PNG [--title TEXT]
       plot_journal_bearing.py sweep SWEEP_CSV PNG [--title TEXT]
       plot_journal_bearing.py wp WP_CSV PNG [--title TEXT]

curve: friction force and mu (stick phases shaded) / journal and drive speed / contact
half-angle, peak and mean pressure / wear volume against time.
sweep: friction force and journal speed for every mu0 of the [sweep] (the thesis's
mu0 = 0.95 / 0.55 / 0.15 overlay, cf. its fig. 5.5).
wp: error vs CPU time from bench/wp_journal_bearing, one panel per mu0.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def shade_stick(axis, t, slip):
    stick = ~slip
    start = None
    for i, s in enumerate(stick):
        if s and start is None:
            start = t[i]
        if (not s or i == len(stick) - 1) and start is not None:
            axis.axvspan(start, t[i], color="0.9", zorder=0)
            start = None


def curve(args):
    figure(args.csv, args.title).savefig(args.png, dpi=110, format="png")


def figure(csv_path, title="journal bearing run-in"):
    """The curve figure: axes [friction and mu, speeds, pressures and half-angle, wear volume]."""
    d = np.genfromtxt(csv_path, delimiter=",", names=True)
    t = d["t_s"]
    slip = d["state_slip"] > 0.5
    fig, (top, mid, bottom, wear) = plt.subplots(4, 1, sharex=True, figsize=(8, 11), constrained_layout=True)
    fig.suptitle(textwrap.fill(title, 90), fontsize=10)
    shade_stick(top, t, slip)
    top.plot(t, d["friction_force_N"], color="tab:red", label="friction force F = T_f / R")
    top.set_ylabel("friction force (N)", color="tab:red")
    mu_axis = top.twinx()
    mu_axis.plot(t, d["mu"], color="tab:blue", linestyle="--", label="mu = F / N")
    mu_axis.set_ylabel("friction coefficient", color="tab:blue")
    lines = top.get_lines() + mu_axis.get_lines()
    top.legend(lines, [line.get_label() for line in lines], loc="upper right", fontsize=8)
    top.set_title("grey: stick", fontsize=8, loc="left")

    mid.plot(t, d["journal_speed_rad_s"], color="tab:green", label="journal speed")
    mid.plot(t, d["drive_speed_rad_s"], color="k", linestyle=":", label="drive speed")
    mid.set_ylabel("speed (rad/s)")
    mid.legend(loc="center right", fontsize=8)

    bottom.plot(t, d["peak_pressure_Pa"] / 1e6, color="tab:purple", label="peak pressure")
    bottom.plot(t, d["mean_pressure_Pa"] / 1e6, color="tab:purple", linestyle="--", label="mean pressure")
    if "upper_peak_pressure_Pa" in d.dtype.names:  # two bearing halves: the upper half's own contact
        bottom.plot(t, d["upper_peak_pressure_Pa"] / 1e6, color="tab:pink", linestyle="-.",
                    label="peak pressure, upper half")
    bottom.set_ylabel("pressure (MPa)", color="tab:purple")
    arc = bottom.twinx()
    arc.plot(t, np.degrees(d["contact_half_angle_rad"]), color="tab:orange", label="contact half-angle")
    arc.set_ylabel("half-angle (deg)", color="tab:orange")
    lines = bottom.get_lines() + arc.get_lines()
    bottom.legend(lines, [line.get_label() for line in lines], loc="lower center", fontsize=8, ncol=4,
                  bbox_to_anchor=(0.5, 1.0))   # above the panel, off the curves

    # wear on its own axis, in its own unit (not scaled onto another quantity's axis)
    wear.plot(t, d["wear_volume_m3"] * 1e9, color="tab:brown", label="wear volume")
    wear.set_ylabel("wear volume (mm^3)", color="tab:brown")
    wear.ticklabel_format(axis="y", style="plain", useOffset=False)
    wear.set_xlabel("time (s)")
    wear.grid(alpha=0.3)
    return fig


def sweep(args):
    d = np.genfromtxt(args.csv, delimiter=",", names=True)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title + "\nmu0 overlay", 90), fontsize=10)
    for mu0 in np.unique(d["mu0"])[::-1]:
        rows = d[d["mu0"] == mu0]
        line, = top.plot(rows["t_s"], rows["friction_force_N"], label=f"mu0 = {mu0:g}")
        bottom.plot(rows["t_s"], rows["journal_speed_rad_s"], color=line.get_color())
    top.set_ylabel("friction force (N)")
    top.legend(fontsize=8)
    bottom.set_ylabel("journal speed (rad/s)")
    bottom.set_xlabel("time (s)")
    fig.savefig(args.png, dpi=110, format="png")


def wp(args):
    import csv
    with open(args.csv, newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["case"] == "thesis_2s"]
    mus = sorted({r["mu0"] for r in rows}, key=float, reverse=True)
    fig, axes = plt.subplots(1, len(mus), figsize=(4.2 * len(mus), 4), sharey=True, constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    for axis, mu0 in zip(np.atleast_1d(axes), mus):
        for method, marker in (("cvode_bdf", "o-"), ("cvode_adams", "s-"), ("euler_fixed", "^--")):
            sel = [r for r in rows if r["mu0"] == mu0 and r["method"] == method]
            axis.loglog([1e3 * float(r["cpu_seconds"]) for r in sel], [float(r["error"]) for r in sel], marker,
                        label=method)
        axis.axhline(1e-6, color="0.5", linestyle=":")
        axis.axvline(20, color="0.5", linestyle=":")
        axis.set_title(f"mu0 = {mu0}")
        axis.set_xlabel("CPU time (ms, median of 5; Euler 3)")
    np.atleast_1d(axes)[0].set_ylabel("max |s - s_ref| / s_ref(2 s)")
    np.atleast_1d(axes)[0].legend(fontsize=8)
    fig.savefig(args.png, dpi=110, format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["curve", "sweep", "wp"])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="journal bearing run-in")
    args = parser.parse_args()
    {"curve": curve, "sweep": sweep, "wp": wp}[args.mode](args)


if __name__ == "__main__":
    main()
