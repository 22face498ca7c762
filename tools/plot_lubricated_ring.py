#!/usr/bin/python3
"""Plot the lubricated mode of `runin piston-ring` (doc/lubricated_piston_ring.md).

usage: plot_lubricated_ring.py runin LUBRICATED_CSV CYCLE_CSV PNG [--title TEXT]
       plot_lubricated_ring.py stribeck STRIBECK_CSV PNG [--title TEXT]

runin: cycle-mean mu and asperity share, R and worn depth over the cycles; h_min, friction force, asperity share
and lambda over the crank angle of the first and last computed cycle.
stribeck: mu, asperity share and lambda against the duty parameter eta U / W'.
Uses Debian's matplotlib: run with /usr/bin/python3.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    return np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")


def plot_runin(args):
    d = read(args.csv)
    c = read(args.cycle_csv)
    cyc = np.atleast_1d(d["cycle"]).astype(float) + 1.0
    fig, ax = plt.subplots(2, 3, figsize=(14, 7.5))
    a = ax[0, 0]
    a.semilogx(cyc, d["mu"], "o-", ms=3, label="cycle-mean mu")
    a.set_xlabel("cycle")
    a.set_ylabel("mu")
    b = a.twinx()
    b.semilogx(cyc, d["asperity_share"], "s-", ms=3, color="tab:red", label="asperity share")
    b.set_ylabel("asperity load share", color="tab:red")
    a.set_title("friction and asperity share")
    a = ax[0, 1]
    a.semilogx(cyc, 1e9 * d["R_m"], "o-", ms=3, label="R (load-weighted ring rq)")
    a.semilogx(cyc, 1e9 * d["max_worn_depth_m"], "^-", ms=3, label="max worn depth")
    a.semilogx(cyc, 1e9 * d["mean_worn_depth_m"], "v-", ms=3, label="mean worn depth")
    a.set_xlabel("cycle")
    a.set_ylabel("nm")
    a.legend(fontsize=8)
    a.set_title("roughness and wear")
    a = ax[0, 2]
    a.semilogx(cyc, d["min_lambda"], "o-", ms=3)
    a.set_xlabel("cycle")
    a.set_ylabel("min lambda over the cycle")
    a.set_title("film parameter")
    for k, (col, lab, scale) in enumerate([("h_min_m", "h_min (um)", 1e6), ("friction_force_N", "friction force (N)", 1.0),
                                           ("asperity_share", "asperity share", 1.0)]):
        a = ax[1, k]
        for which, style in (("first", "-"), ("last", "--")):
            m = c["which"] == which
            if not np.any(m):
                continue
            a.plot(c["crank_angle_deg"][m], scale * c[col][m], style,
                   label=f"{which} cycle ({int(c['cycle'][m][0]) + 1})")
        a.set_xlabel("crank angle (deg from TDC)")
        a.set_ylabel(lab)
        a.legend(fontsize=8)
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110, format="png")


def plot_stribeck(args):
    d = read(args.csv)
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    a = ax[0]
    a.loglog(d["duty_parameter"], d["mu"], "o-", ms=3, label="mu")
    a.set_xlabel("duty parameter eta U / W'")
    a.set_ylabel("mu")
    b = a.twinx()
    b.semilogx(d["duty_parameter"], d["asperity_share"], "s-", ms=3, color="tab:red")
    b.set_ylabel("asperity share", color="tab:red")
    a.set_title("Stribeck curve")
    a = ax[1]
    a.semilogx(d["lambda"], d["mu"], "o-", ms=3)
    a.set_xlabel("lambda = h_min / sigma")
    a.set_ylabel("mu")
    a.set_title("friction vs film parameter")
    fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110, format="png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="mode", required=True)
    r = sub.add_parser("runin")
    r.add_argument("csv")
    r.add_argument("cycle_csv")
    r.add_argument("png")
    r.add_argument("--title", default="")
    r.set_defaults(func=plot_runin)
    s = sub.add_parser("stribeck")
    s.add_argument("csv")
    s.add_argument("png")
    s.add_argument("--title", default="")
    s.set_defaults(func=plot_stribeck)
    args = parser.parse_args()
    args.func(args)


if __name__ == "__main__":
    main()
