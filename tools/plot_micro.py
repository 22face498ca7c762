#!/usr/bin/python3
"""Plot a RunIn micro run (fix ave/time output of in.rough_slider): mu_eff and wear vs sliding distance."""
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


def main(data_path, png_path):
    data = read_ave_time(data_path)
    s_um = [s * 1e6 for s in data["v_slide"]]
    fig, (ax_mu, ax_wear) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    ax_mu.plot(s_um, data["c_fric[3]"], color="tab:red")
    ax_mu.set_ylabel("mu_eff = |sum F_t| / sum F_n")
    ax_mu.set_title("RunIn micro: rough Cu-on-Al asperity slider")
    ax_mu.grid(alpha=0.3)
    ax_wear.plot(s_um, [v * 1e18 for v in data["c_fric[5]"]], color="tab:blue")
    ax_wear.set_ylabel("wear volume [um^3]")
    ax_wear.set_xlabel("sliding distance [um]")
    ax_wear.grid(alpha=0.3)
    fig.tight_layout()
    tmp = png_path + ".part.png"
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, png_path)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
