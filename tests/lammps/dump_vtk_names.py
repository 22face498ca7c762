#!/usr/bin/env python3
"""`runin dump-to-vtk` on the per-atom dump of inputs/in.rough_slider names the wear-state arrays by what they hold
(stdlib only).

  dump_vtk_names.py --lmp LMP --runin RUNIN --workdir DIR

The deck dumps f_RUNIN_WEAR_STATE[1..4] (fix RUNIN/WEAR_STATE: volume lost, volume gained, worn depth, flat
radius); asserted: every .vtp of the series has the point arrays volume_lost, volume_gained, worn_depth and
flat_radius, and none named f_RUNIN_WEAR_STATE[n]; a one-atom dump with columns 5 and 6 and the film coverage
(f_RUNIN_FILM) gets volume_flattened, surface_rise and film_coverage.
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
    # the columns the deck does not dump: flattened volume, surface rise (pair rise) and film coverage (junction/film)
    with open(os.path.join(workdir, "columns.dump"), "w") as f:
        f.write("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp ff\n0 1\n0 1\n0 1\n"
                "ITEM: ATOMS id type x y z f_RUNIN_WEAR_STATE[5] f_RUNIN_WEAR_STATE[6] f_RUNIN_FILM\n"
                "1 1 0.5 0.5 0.5 1e-21 2e-9 0.75\n")
    result = subprocess.run([args.runin, "dump-to-vtk", "columns.dump", "--output-dir", "vtk_columns"], cwd=workdir,
                            capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"runin dump-to-vtk exited with {result.returncode}: {result.stdout}{result.stderr}")
    text = "".join(open(p, errors="replace").read() for p in glob.glob(os.path.join(workdir, "vtk_columns", "*.vtp")))
    names = re.findall(r'<DataArray[^>]*Name="([^"]+)"', text)
    missing = [n for n in ("volume_flattened", "surface_rise", "film_coverage") if n not in names]
    if missing or [n for n in names if n.startswith("f_RUNIN")]:
        fail(f"columns.dump: arrays {names}: missing {missing}")
    print(f"flattened volume, rise and film coverage: {', '.join(names)}")
    print("PASS")


if __name__ == "__main__":
    main()
