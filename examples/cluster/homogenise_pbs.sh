#!/bin/bash
# A run-in state law on a PBS / Torque cluster (or any machine with an MPI hostfile): `runin homogenise` runs
# its LAMMPS samples (one per pressure and seed) as partitions of one mpirun over the nodes PBS gave the job
# (doc/homogenise.md, "Running on a cluster"). Submit it from the RunIn source tree, after tools/build:
#
#   qsub examples/cluster/homogenise_pbs.sh
#   qsub -v CASE=inputs/homogenise_steel.toml examples/cluster/homogenise_pbs.sh
#
# What to choose:
#   select x ncpus/mpiprocs   samples that run at the same time: one MPI rank = one LAMMPS partition = one
#               sample. The default case (inputs/homogenise_steel_mild_deep.toml, the dry steel law to its
#               settled depth) is 8 pressures x 3 seeds = 24 samples; more ranks than samples still to run stay idle.
#   walltime    the slowest sample decides; a job that runs out of time loses only its running samples:
#               resubmit it and it continues from the cache.
#
# Everything the ranks read and write must be on a filesystem all nodes see: the RunIn tree (deck, material
# file), the cache and the output directory.
#
#PBS -N runin-law
#PBS -l select=2:ncpus=12:mpiprocs=12
#PBS -l walltime=01:00:00
#PBS -j oe

set -euo pipefail
cd "$PBS_O_WORKDIR"    # PBS starts the script in the home directory

# the MPI that lmp_runin was built with; module names are site specific
# module load openmpi

RUNIN=${RUNIN:-build/runin}
CASE=${CASE:-inputs/homogenise_steel_mild_deep.toml}
OUT=${OUT:-out/law_${PBS_JOBID%%.*}}
# kept across jobs: a resubmitted job reruns only the missing samples
CACHE=${CACHE:-$PWD/.cache/homogenise}
# one line per rank slot in the node file
NP=$(wc -l < "$PBS_NODEFILE")

# runin replaces {np} by the number of ranks of each run (all samples under one mpirun, then any failed one
# alone with -np 1). $PBS_NODEFILE is expanded by this script's shell, not by runin: the launcher's words are
# passed to mpirun as they are, without a shell, so write no quotes or $VARIABLES for runin to expand.
# Open MPI built with PBS (tm) support finds the nodes itself and needs no --hostfile; with MPICH write
# "mpiexec -f $PBS_NODEFILE -n {np}".
"$RUNIN" homogenise "$CASE" --output-dir "$OUT" --cache-dir "$CACHE" \
    --np "$NP" --launcher "mpirun --hostfile $PBS_NODEFILE -np {np}"

# The law is $OUT/law.json; the continuum elements read it with friction.model = "state_law" (doc/state_law.md).
