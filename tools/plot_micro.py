#!/usr/bin/python3
"""Plot a RunIn micro run (fix ave/time output of inputs/in.rough_slider or inputs/in.runin_wall)
against the sliding distance (log axis, so the run-in at the start shows): mu_eff (with its adhesion and
ploughing parts when recorded), wear volume, and Rq / Rsk of the worn summits when compute runin/roughness
was recorded.

usage: plot_micro.py DATA PNG [TITLE]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_ave_time(path):
    with open(path) as f:
        lines = f.readlines()
    header = lines[1].lstrip("#").split()
    rows = [list(map(float, line.split())) for line in lines[2:] if line.strip() and not line.startswith("#")]
    return {name: [row[k] for row in rows] for k, name in enumerate(header)}


def figure(data_path, title="RunIn micro: rough Cu-on-Al asperity slider"):
    """The figure (axes[0]: friction, [1]: wear, [2]: Rq/Rsk if recorded). Log distance axis: the run-in (the
    break-away peak and its decay over d_c = 20 nm) happens in the first 0.1 % of a 40 um slide."""
    data = read_ave_time(data_path)
    sliding = [k for k, s in enumerate(data["v_slide"]) if s > 0.0]    # the loading phase has no distance
    s_um = [data["v_slide"][k] * 1e6 for k in sliding]

    def column(name, scale=1.0):
        return [data[name][k] * scale for k in sliding]

    roughness = "c_rough[2]" in data
    fig, axes = plt.subplots(3 if roughness else 2, 1, figsize=(7, 8 if roughness else 6), sharex=True)
    ax_mu, ax_wear = axes[0], axes[1]
    if "c_fric[16]" in data:
        ax_mu.plot(s_um, column("c_fric[16]"), color="black", label="mu_body (reaction on the body)")
    ax_mu.plot(s_um, column("c_fric[3]"), color="tab:red", label="mu_eff (contact frames)")
    if "c_fric[6]" in data and any(column("c_fric[6]")):
        ax_mu.plot(s_um, column("c_fric[6]"), color="tab:orange", linestyle="--", label="adhesion part")
        ax_mu.plot(s_um, column("c_fric[7]"), color="tab:brown", linestyle="-.", label="ploughing part")
    ax_mu.legend(fontsize=8)
    ax_mu.set_ylabel("friction coefficient")
    ax_mu.set_title(title)
    ax_mu.grid(alpha=0.3)
    ax_wear.plot(s_um, column("c_fric[5]", 1e18), color="tab:blue")
    ax_wear.set_ylabel("wear volume [um^3]")
    ax_wear.grid(alpha=0.3)
    if roughness:
        ax_rq = axes[2]
        ax_rq.plot(s_um, column("c_rough[2]", 1e9), color="tab:green")
        ax_rq.set_ylabel("Rq of the summits [nm]", color="tab:green")
        ax_rq.grid(alpha=0.3)
        ax_rsk = ax_rq.twinx()
        ax_rsk.plot(s_um, column("c_rough[3]"), color="tab:purple", linestyle="--")
        ax_rsk.axhline(0.0, color="tab:purple", linewidth=0.5)
        ax_rsk.set_ylabel("Rsk", color="tab:purple")
    axes[-1].set_xscale("log")
    axes[-1].set_xlim(min(s_um), max(s_um))
    axes[-1].set_xlabel("sliding distance [um] (log scale, so the run-in at the start shows)")
    fig.tight_layout()
    return fig


def main(data_path, png_path, title="RunIn micro: rough Cu-on-Al asperity slider"):
    fig = figure(data_path, title)
    tmp = png_path + ".part.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, png_path)


if __name__ == "__main__":
    main(*sys.argv[1:4])
