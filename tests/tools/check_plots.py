#!/usr/bin/env python3
"""The pipeline's plots say what they show (tools/plot_*.py, checked on the figures they build).

  check_plots.py --runin RUNIN --workdir DIR

Runs the three machine elements of tools/run-pipeline with the shipped copy of its state law (--no-plot) and
builds each figure with the plot script's own figure() function:
  - micro (plot_micro.py): a log distance axis, so the run-in in the first 0.1 um is not a spike at s = 0;
  - pin-on-disk (plot_curves.py): a state-law run is not labelled "law mu(s)"; the wear axis has no offset
    multiplier (a unit that fits); the pin's wear curve stays visible under the disk's;
  - journal bearing (plot_journal_bearing.py): wear volume on its own axis in mm^3, nothing "scaled";
  - piston ring (plot_piston_ring.py): the force panel is scaled to the forces after the start-up spike, the
    friction-over-the-stroke panel covers the whole stroke, and the legends of the ring-face and force panels
    sit above them, off the curves.
"""
import argparse
import os
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE_DIR, "tools"))
LAW = os.path.join(SOURCE_DIR, "inputs", "state_law_steel_rough.json")
problems = []


def check(condition, message):
    print(("  ok  " if condition else "  FAIL ") + message)
    if not condition:
        problems.append(message)


def run_element(runin, element, work):
    out = os.path.join(work, element.replace("-", "_"))
    name = element.replace("-", "_") + "_state_law.toml"
    case = os.path.join(SOURCE_DIR, "tests", "data", "state_law", "steel", name)   # steel versions: the steel law
    if not os.path.exists(case):
        case = os.path.join(SOURCE_DIR, "inputs", name)
    subprocess.run([runin, element, case, "--law", LAW, "--output-dir", out, "--no-plot"], check=True,
                   capture_output=True, text=True)
    return out


def micro(work):
    import plot_micro
    path = os.path.join(work, "friction.dat")
    s = np.geomspace(5e-9, 4e-5, 400)      # a run-in over the first 30 nm of a 40 um slide
    mu = 0.55 + 0.3 * np.exp(-s / 1e-8)
    with open(path, "w") as f:
        f.write("# Time-averaged data for fix out\n# TimeStep v_slide c_fric[3] c_fric[5] c_fric[16]\n")
        for k, (a, b) in enumerate(zip(s, mu)):
            f.write(f"{k} {a!r} {b!r} {1e-18 * a / 4e-5!r} {b!r}\n")
    fig = plot_micro.figure(path)
    axis = fig.axes[0]
    check(axis.get_xscale() == "log", f"micro: distance axis is {axis.get_xscale()} (log shows the run-in)")
    check("log" in fig.axes[-1].get_xlabel(), f"micro: x label says so ({fig.axes[-1].get_xlabel()!r})")


def pin_on_disk(out):
    import plot_curves
    fig = plot_curves.figure(os.path.join(out, "pin_on_disk.csv"))
    fig.canvas.draw()
    labels = [line.get_label() for axis in fig.axes for line in axis.get_lines()]
    check(not any("mu(s)" in label for label in labels), f"pin-on-disk: no 'law mu(s)' for a state-law run ({labels})")
    check(any("state law" in label for label in labels), "pin-on-disk: the law curve is called the state law")
    wear = next(axis for axis in fig.axes if "wear volume" in axis.get_ylabel())
    offset = wear.yaxis.get_offset_text().get_text()
    check(offset == "", f"pin-on-disk: wear axis without an offset multiplier (got {offset!r}, {wear.get_ylabel()!r})")
    pin = next(line for line in wear.get_lines() if line.get_label() == "pin")
    disk = next(line for line in wear.get_lines() if line.get_label().startswith("disk"))
    check(pin.get_linewidth() > 2 * disk.get_linewidth() and disk.get_linestyle() == "--",
          "pin-on-disk: the pin's curve is a wide band under the disk's dashed line (both visible)")


def journal_bearing(out):
    import plot_journal_bearing
    path = os.path.join(out, "journal_bearing.csv")
    fig = plot_journal_bearing.figure(path)
    labels = [line.get_label() for axis in fig.axes for line in axis.get_lines()]
    check(not any("scaled" in label for label in labels), "journal bearing: nothing drawn scaled onto another axis")
    wear = [axis for axis in fig.axes if axis.get_ylabel() == "wear volume (mm^3)"]
    data = np.genfromtxt(path, delimiter=",", names=True)
    check(len(wear) == 1 and np.allclose(wear[0].get_lines()[0].get_ydata(), data["wear_volume_m3"] * 1e9),
          "journal bearing: wear volume on its own axis, in mm^3")


def piston_ring(out):
    import plot_piston_ring
    path = os.path.join(out, "piston_ring_A.csv")
    fig = plot_piston_ring.figure(path, os.path.join(out, "piston_ring_liner.csv"),
                                  os.path.join(out, "piston_ring_face.csv"))
    fig.canvas.draw()
    data = np.genfromtxt(path, delimiter=",", names=True)
    forces = fig.axes[0]
    after = data["t_s"] > plot_piston_ring.startup_window(data["t_s"], data["state_slip"] > 0.5)
    largest = np.abs(data["friction_force_N"][after]).max()
    check(forces.get_ylim()[1] <= 2.0 * largest,
          f"piston ring: force panel up to {forces.get_ylim()[1]:.3g} N for a friction force of {largest:.3g} N")
    stroke = next(axis for axis in fig.axes if axis.get_title().startswith("friction over the stroke"))
    x = np.concatenate([c.get_offsets()[:, 0] for c in stroke.collections] +
                       [line.get_xdata() for line in stroke.get_lines()])
    span = (data["ring_position_m"].max() - data["ring_position_m"].min()) * 1e3
    check(x.max() - x.min() >= 0.99 * span,
          f"piston ring: friction over the stroke covers {x.max() - x.min():.3g} of {span:.3g} mm")
    renderer = fig.canvas.get_renderer()
    for name, axis in (("force", forces), ("ring face", next(a for a in fig.axes if a.get_ylabel() == "profile (um)"))):
        legend = axis.get_legend()
        inside = legend is not None and legend.get_window_extent(renderer).y0 < axis.get_window_extent(renderer).y1 - 1
        check(legend is not None and not inside, f"piston ring: {name} panel's legend above the panel, off the curves")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runin", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    micro(args.workdir)
    pin_on_disk(run_element(args.runin, "pin-on-disk", args.workdir))
    journal_bearing(run_element(args.runin, "journal-bearing", args.workdir))
    piston_ring(run_element(args.runin, "piston-ring", args.workdir))
    if problems:
        print(f"FAIL: {len(problems)} plot check(s)")
        sys.exit(1)
    print("ok: the pipeline's plots")


if __name__ == "__main__":
    main()
