#!/usr/bin/python3
"""The groove check of the disk's track wear (doc/pin_on_disk.md, stdlib only).

usage: check_disk_groove.py RUNIN SOURCE_DIR WORKDIR

- inputs/pin_on_disk_feedback.toml as shipped (k_d = 1e-4): the groove line reports h_d / elastic approach
  below 0.05, "negligible", and no groove WARNING;
- the same case with wear.disk_k = 1e-2: the ratio scales with k_d (x 100 to 1e-3, since the groove is not fed
  back into the contact) and the run prints the groove WARNING.
"""
import os
import re
import subprocess
import sys


def run(runin, case, out):
    p = subprocess.run([runin, "pin-on-disk", case, "--output-dir", out, "--no-plot"], capture_output=True,
                       text=True, timeout=300)
    if p.returncode != 0:
        sys.exit(f"check_disk_groove: {case}: exit {p.returncode}: {p.stderr}")
    return p.stdout


def ratio(stdout):
    m = re.search(r"track depth / elastic approach <= ([0-9.eE+-]+)", stdout)
    if not m:
        sys.exit("check_disk_groove: no groove line in the summary")
    return float(m.group(1))


def main():
    runin, source, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    shipped = os.path.join(source, "inputs", "pin_on_disk_feedback.toml")
    text = open(shipped).read()
    big = re.sub(r"^disk_k = 1e-4", "disk_k = 1e-2", text, flags=re.M)
    big = big.replace('"potentials/CuAl.runin"', '"' + os.path.join(source, "potentials", "CuAl.runin") + '"')
    if big == text:
        sys.exit("check_disk_groove: could not set disk_k in the feedback case")
    big_case = os.path.join(work, "feedback_disk_k_1e-2.toml")
    open(big_case, "w").write(big)
    small_out, big_out = run(runin, shipped, os.path.join(work, "small")), run(runin, big_case, os.path.join(work, "big"))
    problems = []
    small, large = ratio(small_out), ratio(big_out)
    warning = "WARNING: the disk's track depth reaches"
    if not (0.0 < small <= 0.05 and "(negligible" in small_out) or warning in small_out:
        problems.append(f"shipped case: ratio {small}, expected (0, 0.05], 'negligible' and no groove WARNING")
    if abs(large / small - 100.0) > 100.0 * 1e-3 * 2:  # both printed to 3 digits
        problems.append(f"ratio {large} at k_d = 1e-2 is not 100 x {small}")
    if warning not in big_out:
        problems.append("no groove WARNING at k_d = 1e-2")
    for p in problems:
        print("check_disk_groove:", p, file=sys.stderr)
    print(f"groove / elastic approach {small} (k_d = 1e-4), {large} (k_d = 1e-2)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
