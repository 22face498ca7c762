#!/usr/bin/env python3
"""Checks of tools/run-pipeline's own steps (no full pipeline run).

  check_pipeline.py partitions
      The partition count the script passes to `runin homogenise --np`, evaluated as the script does it, with
      OMP_NUM_THREADS=1 exported (as the script exports it), must be the machine's core count (getconf): GNU
      nproc honours OMP_NUM_THREADS and gave 1. The script must also print the count.
  check_pipeline.py progress --lmp-dir BUILD --workdir DIR
      The micro stages print their progress: every LAMMPS run of the script goes through lammps_stage, which
      (run here on a short inputs/in.runin_wall) prints a line per run of the deck with its step count.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from runin_common import fail  # noqa: E402

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SCRIPT = os.path.join(SOURCE_DIR, "tools", "run-pipeline")
LIBRARY = os.path.join(SOURCE_DIR, "tools", "lib", "pipeline.sh")


def bash(code, env_extra=None):
    env = dict(os.environ, OMP_NUM_THREADS="1", **(env_extra or {}))
    return subprocess.run(["bash", "-c", code], capture_output=True, text=True, env=env)


def partitions(_args):
    text = open(SCRIPT).read()
    command = re.search(r'runin" homogenise .*?--np "([^"]+)"', text, re.S)
    if not command:
        fail("tools/run-pipeline: no `runin homogenise ... --np \"...\"` command")
    expression = command.group(1)
    setup = ""
    variable = re.fullmatch(r"\$\{?(\w+)\}?", expression)
    if variable:    # --np "$name": the assignment of name, as the script has it
        assignment = re.search(rf"^{variable.group(1)}=(.*)$", text, re.M)
        if not assignment:
            fail(f"tools/run-pipeline: --np {expression} but no assignment of {variable.group(1)}")
        setup = assignment.group(0)
    preamble = f'here={SOURCE_DIR!r}; [ -f {LIBRARY!r} ] && . {LIBRARY!r}; '
    result = bash(preamble + (setup + "; " if setup else "") + f'echo "{expression}"')
    cores = bash("getconf _NPROCESSORS_ONLN").stdout.strip()
    used = result.stdout.strip()
    print(f"--np {expression} -> {used!r} with OMP_NUM_THREADS=1; getconf _NPROCESSORS_ONLN = {cores}")
    if result.returncode != 0 or used != cores:
        fail(f"tools/run-pipeline runs `runin homogenise` on {used!r} partitions, the machine has {cores} cores "
             f"{result.stderr.strip()}")
    if variable and not re.search(rf'echo "[^"]*\${variable.group(1)}\b[^"]*partition', text):
        fail(f"tools/run-pipeline does not print the partition count (${variable.group(1)})")
    print(f"ok: homogenise on {used} partitions = the machine's {cores} cores")


def progress(args):
    text = open(SCRIPT).read()
    direct = [line for line in text.splitlines() if "lmp_runin" in line and "mpirun" in line]
    if direct:
        fail(f"tools/run-pipeline runs LAMMPS without lammps_stage (no progress): {direct[0].strip()}")
    stages = len(re.findall(r"^lammps_stage ", text, re.M))
    if stages < 2:
        fail(f"tools/run-pipeline: {stages} lammps_stage call(s), want one per micro LAMMPS run (2)")
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    code = (f'. {LIBRARY!r}; build={os.path.abspath(args.lmp_dir)!r}; lammps_stage {args.workdir!r} 1 -in '
            f'{os.path.join(SOURCE_DIR, "inputs", "in.runin_wall")!r} -var nside 10 -var nload 300 -var nslide 500 '
            f'-var thermo_every 100 -var out runin.dat')
    result = bash(code, {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
    print(result.stdout + result.stderr)
    if result.returncode != 0:
        fail(f"lammps_stage exited with {result.returncode}")
    for run, steps in ((1, 300), (2, 500)):
        if not re.search(rf"^   run {run}: {steps} steps in [0-9.]+ s on 1 MPI ranks$", result.stdout, re.M):
            fail(f"lammps_stage did not report run {run} ({steps} steps)")
    if not re.search(r"^   done in \d+ s", result.stdout, re.M):
        fail("lammps_stage did not report its elapsed time")
    print(f"ok: {stages} micro LAMMPS stages in tools/run-pipeline, each reporting its runs")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0], epilog=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check", choices=["partitions", "progress"])
    parser.add_argument("--lmp-dir", help="directory holding lmp_runin (the build directory)")
    parser.add_argument("--workdir", default="pipeline_progress")
    args = parser.parse_args()
    {"partitions": partitions, "progress": progress}[args.check](args)


if __name__ == "__main__":
    main()
