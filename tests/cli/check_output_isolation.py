#!/usr/bin/python3
"""Outputs are isolated per run and never partial (stdlib only; ctest label cli).

usage: check_output_isolation.py RUNIN SOURCE_DIR WORKDIR

1. Case A then case B of the same subcommand into one directory leaves exactly the files (names
   and bytes of the CSVs) that B alone writes into a fresh directory: no stale VTK frames or mu0
   sweep files of A. Checked for pin-on-disk (A: 4 VTK frames + mu0 sweep, B: 2 frames, no sweep)
   and feedback (A with a B sweep, B without).
2. A run whose plot fails (RUNIN_PYTHON=/bin/false) exits 1 with one "runin: error:" line and
   leaves the directory byte-for-byte as the previous complete run left it; into a new directory
   it leaves nothing. No staging directory is left behind in either case.
"""
import hashlib
import os
import shutil
import subprocess
import sys


def snapshot(directory):
    """{relative path: sha256} of every file below directory."""
    files = {}
    for root, _, names in os.walk(directory):
        for name in names:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, directory)] = hashlib.sha256(f.read()).hexdigest()
    return files


def run(cmd, env=None, expect=0):
    p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=300)
    if p.returncode != expect:
        sys.exit(f"check_output_isolation: {' '.join(cmd)}: exit {p.returncode} (expected {expect}): {p.stderr}")
    return p


def staging_left(work):
    return [n for n in os.listdir(work) if ".staging-" in n]


def main():
    runin, source, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    inputs = os.path.join(source, "inputs")
    failures = []
    pairs = [("pin-on-disk", "pin_on_disk.toml", "pin_on_disk_feedback.toml"),
             ("feedback", "feedback_lubricated.toml", "feedback_dry.toml")]
    for command, case_a, case_b in pairs:
        shared, fresh = os.path.join(work, command + "_shared"), os.path.join(work, command + "_fresh")
        run([runin, command, os.path.join(inputs, case_a), "--output-dir", shared, "--no-plot"])
        after_a = snapshot(shared)
        run([runin, command, os.path.join(inputs, case_b), "--output-dir", shared, "--no-plot"])
        run([runin, command, os.path.join(inputs, case_b), "--output-dir", fresh, "--no-plot"])
        got, want = snapshot(shared), snapshot(fresh)
        stale = sorted(set(got) - set(want))
        missing = sorted(set(want) - set(got))
        differ = sorted(k for k in set(got) & set(want) if k.endswith(".csv") and got[k] != want[k])
        print(f"{command}: {case_a} wrote {len(after_a)} files, then {case_b} leaves {len(got)} "
              f"(fresh run: {len(want)})")
        if stale or missing or differ:
            failures.append(f"{command}: stale {stale}, missing {missing}, differing CSVs {differ}")
        if len(set(after_a) - set(want)) == 0:
            failures.append(f"{command}: case A writes no file that B does not; the check proves nothing")

        # A failing plot after a complete run: the directory keeps that run, byte for byte.
        before = snapshot(shared)
        env = dict(os.environ, RUNIN_PYTHON="/bin/false")
        p = run([runin, command, os.path.join(inputs, case_a), "--output-dir", shared], env=env, expect=1)
        lines = p.stderr.strip().splitlines()
        if len(lines) != 1 or not lines[0].startswith("runin: error: plotting failed"):
            failures.append(f"{command}: failing plot: stderr {p.stderr!r}")
        if snapshot(shared) != before:
            failures.append(f"{command}: failing plot changed the previous complete output")
        new_dir = os.path.join(work, command + "_never")
        run([runin, command, os.path.join(inputs, case_a), "--output-dir", new_dir], env=env, expect=1)
        if os.path.exists(new_dir):
            failures.append(f"{command}: failing plot into a new directory left {new_dir}")
        print(f"{command}: failing plot (RUNIN_PYTHON=/bin/false): exit 1, '{lines[0] if lines else ''}'")
    if staging_left(work):
        failures.append(f"staging directories left behind: {staging_left(work)}")
    for f in failures:
        print("check_output_isolation:", f, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
