#!/usr/bin/env python3
"""`runin dump-to-vtk` on the per-atom dump of inputs/in.rough_slider names the wear-state arrays by what they hold
(stdlib only).

  dump_vtk_names.py --lmp LMP --runin RUNIN --workdir DIR

The deck dumps f_RUNIN_WEAR_STATE[1..4] (fix RUNIN/WEAR_STATE: volume lost, volume gained, worn depth, flat
radius); asserted: every .vtp of the series has the point arrays volume_lost, volume_gained, worn_depth and
flat_radius, and none named f_RUNIN_WEAR_STATE[n].
"""
import argparse
import glob
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_deck import SOURCE_DIR, fail, fresh_dir, mpi_env  # noqa: E402

READABLE = ["volume_lost", "volume_gained", "worn_depth", "flat_radius"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lmp", required=True)
    parser.add_argument("--runin", required=True)
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    workdir = os.path.abspath(args.workdir)
    fresh_dir(workdir)
    command = [args.lmp, "-in", os.path.join(SOURCE_DIR, "inputs", "in.rough_slider"), "-log", "log.lammps",
               "-screen", "none", "-var", "nsettle", "100", "-var", "nslide", "100", "-var", "thermo_every", "50",
               "-var", "coeffs", os.path.join(SOURCE_DIR, "potentials", "CuAl.runin")]
    result = subprocess.run(command, cwd=workdir, env=mpi_env(), capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"LAMMPS exited with {result.returncode}\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
    result = subprocess.run([args.runin, "dump-to-vtk", "asperities.dump", "--output-dir", "vtk"], cwd=workdir,
                            capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"runin dump-to-vtk exited with {result.returncode}: {result.stdout}{result.stderr}")
    files = sorted(glob.glob(os.path.join(workdir, "vtk", "*.vtp")))
    if not files:
        fail("no .vtp written")
    for path in files:
        text = open(path, errors="replace").read()
        names = re.findall(r'<DataArray[^>]*Name="([^"]+)"', text)
        missing = [name for name in READABLE if name not in names]
        raw = [name for name in names if name.startswith("f_RUNIN_WEAR_STATE")]
        if missing or raw:
            fail(f"{os.path.basename(path)}: arrays {names}: missing {missing}, unnamed {raw}")
    print(f"{len(files)} .vtp files, arrays: {', '.join(names)}")
    print("PASS")


if __name__ == "__main__":
    main()
