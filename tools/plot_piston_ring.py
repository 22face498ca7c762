#!/usr/bin/python3
"""Plot the output of `runin piston-ring`.

usage: plot_piston_ring.py curve CSV LINER_CSV RING_CSV PNG [--title TEXT]
       plot_piston_ring.py sweep SWEEP_CSV PNG [--title TEXT]
       plot_piston_ring.py wp WP_CSV PNG            (bench/wp_piston_ring output)

curve: friction and land force vs time (whole run, scaled to the forces after the start-up, and the
start-up), friction force over the stroke position (every sample, coloured by time), wear volumes and peak contact pressure vs time, liner wear depth vs distance
from TDC, ring-face profile (crown, wear, final pressure).
sweep: friction force vs time for each mu0 (the thesis's 0.95 / 0.55 / 0.15 overlay).
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def startup_window(t, slip):
    """End of the start-up zoom: ten times the first break-away, at least 1 % of the run."""
    starts = np.flatnonzero(slip)
    t_b = t[starts[0]] if len(starts) else 0.0
    return min(t[-1], max(10.0 * t_b, 0.01 * (t[-1] - t[0]), 1e-9))


def plot_curve(args):
    figure(args.csv, args.liner_csv, args.ring_csv, args.title).savefig(args.png, dpi=110, format="png")


def legend_above(ax, handles=None, ncol=3):
    """A legend above the panel, where it covers no curve."""
    handles = handles if handles is not None else ax.get_lines()
    return ax.legend(handles, [h.get_label() for h in handles], loc="lower center", bbox_to_anchor=(0.5, 1.0),
                     ncol=ncol, fontsize=8, frameon=False)


def figure(csv_path, liner_csv, ring_csv, title="piston ring run-in"):
    """The curve figure, axes [[forces, start-up], [friction over the stroke, wear], [liner, ring face]]."""
    d = np.genfromtxt(csv_path, delimiter=",", names=True)
    liner = np.genfromtxt(liner_csv, delimiter=",", names=True)
    ring = np.genfromtxt(ring_csv, delimiter=",", names=True)
    t = d["t_s"]
    slip = d["state_slip"] > 0.5
    fig, axes = plt.subplots(3, 2, figsize=(12, 11.5), constrained_layout=True)
    fig.suptitle(textwrap.fill(title, 90), fontsize=10)
    end = startup_window(t, slip)

    ax = axes[0, 0]
    ax.plot(t, d["friction_force_N"], color="tab:red", label="friction force (liner)")
    ax.plot(t, d["land_force_N"], color="tab:gray", linestyle="--", linewidth=0.8, label="land force (piston on ring)")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("force (N)")
    # the axis fits the forces after the start-up (its land-force spike, tens of times larger, has its own panel)
    after = t > end
    if np.any(after):
        top = max(np.abs(d["friction_force_N"][after]).max(), np.abs(d["land_force_N"][after]).max())
        bottom = min(0.0, d["friction_force_N"][after].min(), d["land_force_N"][after].min())
        ax.set_ylim(bottom - 0.05 * (top - bottom), 1.15 * top)
    mu_axis = ax.twinx()
    mu_axis.plot(t, d["mu"], color="tab:blue", linewidth=0.6, alpha=0.6, label="mu = |F| / W")
    mu_axis.set_ylabel("mu = |F| / W", color="tab:blue")
    legend_above(ax, ax.get_lines() + mu_axis.get_lines())
    ax.grid(alpha=0.3)

    ax = axes[0, 1]
    m = t <= end
    ax.plot(t[m] * 1e3, d["friction_force_N"][m], color="tab:red", label="friction force")
    ax.plot(t[m] * 1e3, d["land_force_N"][m], color="tab:gray", linestyle="--", label="land force")
    speed_axis = ax.twinx()
    speed_axis.plot(t[m] * 1e3, d["speed_m_s"][m], color="tab:green", linewidth=0.8)
    speed_axis.plot(t[m] * 1e3, d["piston_velocity_m_s"][m], color="tab:green", linestyle=":", linewidth=0.8)
    speed_axis.set_ylabel("ring speed (solid), piston speed (dotted) (m/s)", color="tab:green")
    ax.set_xlabel("time t (ms)")
    ax.set_ylabel("force (N)")
    ax.legend(loc="center right", fontsize=8)
    ax.set_title("start-up: stick, break-away, settling", fontsize=9)
    ax.grid(alpha=0.3)

    ax = axes[1, 0]
    # every sample over the stroke, coloured by time: the first and last strokes of a slow run cover only a
    # few mm of it
    stroke_mm = (d["ring_position_m"] - d["ring_position_m"].max()) * 1e3
    points = ax.scatter(stroke_mm, d["friction_force_N"], c=t, s=2, cmap="viridis")
    fig.colorbar(points, ax=ax, label="time t (s)")
    ax.set_xlabel("ring position relative to its highest point (mm)")
    ax.set_ylabel("friction force (N)")
    ax.set_title("friction over the stroke, whole run (sign = sliding direction)", fontsize=9)
    ax.grid(alpha=0.3)

    ax = axes[1, 1]
    ax.plot(t, d["wear_ring_m3"] * 1e9, linewidth=4, alpha=0.45, label="ring face")   # visible under an equal liner
    ax.plot(t, d["wear_liner_m3"] * 1e9, linestyle="--", label="liner")
    ax.plot(t, d["wear_volume_m3"] * 1e9, color="k", label="total")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("wear volume (mm^3)")
    p_axis = ax.twinx()
    p_axis.plot(t, d["peak_pressure_Pa"] * 1e-6, color="tab:red", linewidth=0.5, alpha=0.7)
    p_axis.set_ylabel("peak contact pressure (MPa)", color="tab:red")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)

    ax = axes[2, 0]
    ax.plot(liner["distance_from_tdc_m"] * 1e3, liner["wear_depth_m"] * 1e6, color="tab:brown")
    ax.set_xlabel("distance of the ring centre from TDC (mm)")
    ax.set_ylabel("liner wear depth (um)")
    ax.set_title("liner wear along the stroke (end of run)", fontsize=9)
    ax.grid(alpha=0.3)

    ax = axes[2, 1]
    z = ring["z_m"] * 1e3
    ax.plot(z, ring["crown_m"] * 1e6, color="0.5", linestyle="--", label="initial crown")
    ax.plot(z, (ring["crown_m"] + ring["wear_depth_m"]) * 1e6, color="k", label="crown + wear (gap)")
    ax.plot(z, ring["wear_depth_m"] * 1e6, color="tab:brown", label="wear depth")
    ax.set_xlabel("axial position on the ring face (mm)")
    ax.set_ylabel("profile (um)")
    pr_axis = ax.twinx()
    pr_axis.plot(z, ring["final_pressure_Pa"] * 1e-6, color="tab:red")
    pr_axis.set_ylabel("final contact pressure (MPa)", color="tab:red")
    legend_above(ax)
    ax.grid(alpha=0.3)
    return fig


def plot_sweep(args):
    d = np.genfromtxt(args.csv, delimiter=",", names=True)
    fig, (full, zoom) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
    fig.suptitle(textwrap.fill(args.title + ": static coefficient mu0", 90), fontsize=10)
    ends = []
    for mu0 in sorted(set(d["mu0"]), reverse=True):
        m = d["mu0"] == mu0
        t, f = d["t_s"][m], d["friction_force_N"][m]
        full.plot(t, f, label=f"mu0 = {mu0:g}")
        ends.append(startup_window(t, d["state_slip"][m] > 0.5))
        line, = zoom.plot(t * 1e3, f, label=f"mu0 = {mu0:g}")
        zoom.plot(t * 1e3, d["land_force_N"][m], color=line.get_color(), linestyle="--", linewidth=0.8)
    zoom.set_xlim(0, max(ends) * 1e3)
    full.set_xlabel("time t (s)")
    zoom.set_xlabel("time t (ms)")
    for ax in (full, zoom):
        ax.set_ylabel("friction force at the liner (N)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    zoom.set_title("start-up (dashed: land force, piston on ring)", fontsize=9)
    fig.savefig(args.png, dpi=110, format="png")


def plot_wp(args):
    d = np.genfromtxt(args.csv, delimiter=",", names=True, dtype=None, encoding=None)
    cases = sorted(set(d["mu0"]), reverse=True)
    fig, axes = plt.subplots(1, len(cases), figsize=(5 * len(cases), 4.5), constrained_layout=True, squeeze=False)
    fig.suptitle(textwrap.fill("piston-ring thesis case (2 s): error vs wall time, closed-form reference", 90), fontsize=10)
    styles = {"cvode_bdf": "o-", "cvode_adams": "s-", "fixed_euler": "x--", "fixed_rk4": "d--"}
    for ax, mu0 in zip(axes[0], cases):
        for method, style in styles.items():
            m = (d["mu0"] == mu0) & (d["method"] == method)
            if m.any():
                ax.loglog(d["seconds"][m] * 1e3, np.maximum(d["error"][m], 1e-16), style, label=method)
        ax.axhline(1e-6, color="0.5", linestyle=":", linewidth=0.8)
        ax.axvline(20, color="0.5", linestyle=":", linewidth=0.8)
        ax.set_xlabel("wall time (ms, median)")
        ax.set_ylabel("max relative error")
        ax.set_title(f"mu0 = {mu0:g}", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.savefig(args.png, dpi=110, format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="mode", required=True)
    curve = sub.add_parser("curve")
    curve.add_argument("csv")
    curve.add_argument("liner_csv")
    curve.add_argument("ring_csv")
    curve.add_argument("png")
    curve.add_argument("--title", default="piston ring run-in")
    sweep = sub.add_parser("sweep")
    sweep.add_argument("csv")
    sweep.add_argument("png")
    sweep.add_argument("--title", default="piston ring run-in")
    wp = sub.add_parser("wp")
    wp.add_argument("csv")
    wp.add_argument("png")
    args = parser.parse_args()
    {"curve": plot_curve, "sweep": plot_sweep, "wp": plot_wp}[args.mode](args)


if __name__ == "__main__":
    main()
