#!/bin/bash
# A run-in state law on a Slurm cluster: `runin homogenise` runs its LAMMPS samples (one per pressure and seed)
# as partitions of one MPI job started with srun inside this allocation (doc/homogenise.md, "Running on a
# cluster"). Submit it from the RunIn source tree, after tools/build:
#
#   sbatch examples/cluster/homogenise_slurm.sh
#   sbatch --export=ALL,CASE=inputs/homogenise_steel.toml examples/cluster/homogenise_slurm.sh
#
# What to choose:
#   --ntasks    samples that run at the same time: one MPI rank = one LAMMPS partition = one sample. The
#               default case (inputs/homogenise_steel_mild_deep.toml, the dry steel law to its settled depth)
#               is 8 pressures x 3 seeds = 24 samples; more ranks than samples still to run stay idle (runin starts at most one per sample).
#   --time      the slowest sample decides: the low pressures of the rough-on-rough cell take longest. A job
#               that runs out of time loses only its running samples: resubmit it and it continues.
#
# Everything the ranks read and write must be on a filesystem all nodes see: the RunIn tree (deck, material
# file), the cache (each sample writes its log and output there) and the output directory.
#
#SBATCH --job-name=runin-law
#SBATCH --ntasks=24
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --output=runin-law-%j.out

set -euo pipefail

# the MPI that lmp_runin was built with; module names are site specific
# module load openmpi

RUNIN=${RUNIN:-build/runin}
CASE=${CASE:-inputs/homogenise_steel_mild_deep.toml}
OUT=${OUT:-out/law_${SLURM_JOB_ID}}
# the sample cache: keep it across jobs (not in a per-job scratch directory), so a resubmitted job reruns only
# the samples that are missing; a sample is reused only if all its inputs and the lmp_runin binary are the same
CACHE=${CACHE:-$PWD/.cache/homogenise}

# runin replaces {np} by the number of ranks of each run: all samples under one `srun --exact -n N`, then, if a
# sample failed, each missing one alone (`srun --exact -n 1`, up to N at a time) to name the failing ones.
# --exact (Slurm 20.11 and later) lets those single-rank steps share the allocation; drop it on older Slurm.
# The words are passed to srun as they are, without a shell: no quotes or $VARIABLES inside the launcher
# (this script's shell expands the ones outside it).
"$RUNIN" homogenise "$CASE" --output-dir "$OUT" --cache-dir "$CACHE" \
    --np "$SLURM_NTASKS" --launcher "srun --exact -n {np}"

# The law is $OUT/law.json; the continuum elements read it with friction.model = "state_law" (doc/state_law.md).
