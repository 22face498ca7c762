#!/usr/bin/python3
"""Plot a pin-on-disk run-in curve written by `runin pin-on-disk`.

usage: plot_curves.py CSV PNG [--title TEXT]
       plot_curves.py --overlay SWEEP_CSV PNG [--title TEXT]

Top panel: friction force, mobilised friction coefficient F/W and the law's run-in
value (during slip: mu(s), or the state law's mu(p, h) over the pin face) vs time; stick phase shaded, break-away marked. Second panel: sliding
speed and sliding distance vs time. With the pin contact modelled, two more panels: wear volume
and contact radius, and peak/mean contact pressure vs time.
--overlay: friction force and speed of each mu0 of a sweep (pin_on_disk_mu0.csv) on shared axes.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="pin-on-disk run-in")
    parser.add_argument("--overlay", action="store_true", help="CSV is a mu0 sweep")
    args = parser.parse_args()
    if args.overlay:
        overlay(args)
        return
    figure(args.csv, args.title).savefig(args.png, dpi=120, format="png")


def volume_unit(largest_m3):
    """(scale, unit) that keeps a wear volume axis free of an offset multiplier: um^3 below 1e5 um^3, else mm^3."""
    return (1e18, "um^3") if largest_m3 * 1e18 < 1e5 else (1e9, "mm^3")


def figure(csv_path, title="pin-on-disk run-in"):
    """The figure: axes [friction, speed, (wear, pressure)] as described in the module docstring."""
    data = np.genfromtxt(csv_path, delimiter=",", names=True)
    # a state-law run (worn depth per node) takes mu(p_i, h_i); a mu(s) law run the law's value at s
    state_law = "h_mean_m" in data.dtype.names
    t = data["t_s"]
    slip = data["state_slip"] > 0.5

    contact = "contact_radius_m" in data.dtype.names and np.any(data["contact_radius_m"] > 0)
    fig, axes = plt.subplots(4 if contact else 2, 1, sharex=True, figsize=(8, 12 if contact else 7),
                             constrained_layout=True)
    top, bottom = axes[0], axes[1]
    fig.suptitle(textwrap.fill(title, 90), fontsize=10)

    top.plot(t, data["friction_force_N"], color="tab:red", label="friction force")
    top.set_ylabel("friction force (N)", color="tab:red")
    mu_axis = top.twinx()
    mu_axis.plot(t, data["mu"], color="tab:blue", linestyle="--", label="mu = F / W")
    mu_axis.plot(t[slip], data["mu_law"][slip], color="tab:orange", linestyle="-.",
                 label="state law mu(p, h) over the pin face" if state_law else "law mu(s), no speed term")
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

    if contact:
        wear = axes[2]
        disk = "disk_wear_volume_m3" in data.dtype.names and np.any(data["disk_wear_volume_m3"] > 0)
        largest = max(data["wear_volume_m3"].max(), data["disk_wear_volume_m3"].max() if disk else 0.0)
        scale, unit = volume_unit(largest)
        # the pin as a wide pale band under the disk's dashed line: both stay visible where they coincide
        wear.plot(t, data["wear_volume_m3"] * scale, color="tab:brown", linewidth=4, alpha=0.45, label="pin")
        if disk:
            same = np.allclose(data["disk_wear_volume_m3"], data["wear_volume_m3"], rtol=1e-6, atol=0.0)
            wear.plot(t, data["disk_wear_volume_m3"] * scale, color="tab:olive", linestyle="--",
                      label="disk (track)" + (": equal to the pin's" if same else ""))
            wear.legend(loc="upper left", fontsize=8)
            wear.set_ylabel(f"wear volume ({unit})", color="tab:brown")
        else:
            wear.set_ylabel(f"pin wear volume ({unit})", color="tab:brown")
        wear.ticklabel_format(axis="y", style="plain", useOffset=False)
        radius = wear.twinx()
        radius.plot(t, data["contact_radius_m"] * 1e6, color="tab:gray", linestyle=":")
        radius.set_ylabel("contact radius (um)", color="tab:gray")
        wear.grid(alpha=0.3)
        pressure = axes[3]
        pressure.plot(t, data["peak_pressure_Pa"] / 1e6, color="tab:red", linestyle="--", label="peak")
        pressure.plot(t, data["mean_pressure_Pa"] / 1e6, color="tab:pink", linestyle="-.", label="mean W / pi a^2")
        pressure.set_ylabel("contact pressure (MPa)")
        pressure.legend(loc="upper right", fontsize=8)
        pressure.set_xlabel("time t (s)")
        pressure.grid(alpha=0.3)
    return fig


def overlay(args):
    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 7), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title, 90), fontsize=10)
    for mu0 in sorted(set(data["mu0"]), reverse=True):
        rows = data["mu0"] == mu0
        line, = top.plot(data["t_s"][rows], data["friction_force_N"][rows], label=f"mu0 = {mu0:g}")
        bottom.plot(data["t_s"][rows], data["speed_m_s"][rows], color=line.get_color())
    top.set_ylabel("friction force (N)")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    bottom.set_ylabel("speed V (m/s)")
    bottom.set_xlabel("time t (s)")
    bottom.grid(alpha=0.3)
    fig.savefig(args.png, dpi=120, format="png")


if __name__ == "__main__":
    main()
