#!/usr/bin/env bash
# RunIn example: the multiscale pipeline of tools/run-pipeline on a tiny case, from this folder:
#   1. micro   : ../rough_slider/in.rough_slider, 4 um of sliding (4000 steps), on NP MPI ranks
#                -> friction.dat (mu_body = c_fric[16] against the sliding distance v_slide), log.pipeline_micro
#   2. coupling: runin fit-law -> friction_law.json: mu(s) = mu_ss + (mu_0 - mu_ss) exp(-(s - s_peak)/s0)
#   3. macro   : runin pin-on-disk pin_on_disk.toml with that law -> pin_on_disk/pin_on_disk.csv
#   4. key numbers of all three -> key_numbers.txt
#
#   ./run_pipeline.sh                                  # 1 rank, ../../build/lmp_runin and ../../build/runin
#   NP=4 MPIEXEC=mpirun ./run_pipeline.sh              # micro part on 4 ranks
#   LMP='LAMMPS_PLUGIN_PATH=/path/to/build lmp' ...    # stock LAMMPS with the RunIn plugin
# Environment: LMP (LAMMPS command; leading NAME=VALUE words are exported), NP, MPIEXEC, RUNIN (runin CLI),
# PYTHON (python3 for the key numbers).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
LMP=${LMP:-$here/../../build/lmp_runin}
RUNIN=${RUNIN:-$here/../../build/runin}
NP=${NP:-1}
MPIEXEC=${MPIEXEC:-mpirun}
PYTHON=${PYTHON:-python3}
NSLIDE=${NSLIDE:-4000}

read -r -a lmp <<< "$LMP"
while [ "${#lmp[@]}" -gt 0 ] && [[ "${lmp[0]}" =~ ^(env|[A-Za-z_][A-Za-z0-9_]*=.*)$ ]]; do
  [ "${lmp[0]}" = env ] || export "${lmp[0]}"
  lmp=("${lmp[@]:1}")
done
launch=()
if [ "$NP" -gt 1 ]; then launch=("$MPIEXEC" -np "$NP"); fi
export OMP_NUM_THREADS=1
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export OMPI_MCA_rmaps_base_oversubscribe=1

echo "== 1. micro: rough slider, $NSLIDE sliding steps on $NP rank(s)"
rm -f friction.dat friction_law.json key_numbers.txt
"${launch[@]}" "${lmp[@]}" -in ../rough_slider/in.rough_slider -var nslide "$NSLIDE" -var thermo_every 500 \
  -var out friction.dat -log log.pipeline_micro -screen none

echo "== 2. coupling: runin fit-law (mu_body against sliding distance)"
"$RUNIN" fit-law --input friction.dat --distance-column v_slide --mu-column 'c_fric[16]' --output friction_law.json

echo "== 3. macro: runin pin-on-disk with the fitted law"
"$RUNIN" pin-on-disk pin_on_disk.toml --law friction_law.json --output-dir pin_on_disk --no-plot

echo "== 4. key numbers -> key_numbers.txt"
"$PYTHON" - <<'EOF'
import csv, json
out = []
# micro: last row of the sliding thermo table
blocks, header = [], None
for line in open("log.pipeline_micro"):
    words = line.split()
    if words and words[0] == "Step":
        header, rows = words, []
    elif header and line.startswith("Loop time"):
        blocks.append((header, rows))
        header = None
    elif header and len(words) == len(header):
        rows.append(dict(zip(header, map(float, words))))
_, sliding = blocks[-1]
last = sliding[-1]
out += [("micro_slide_m", last["v_slide"]), ("micro_mu_body", last["c_fric[16]"]), ("micro_mu_eff", last["c_fric[3]"]),
        ("micro_wear_m3", last["c_fric[5]"]), ("micro_archard_ratio", last["v_archard"])]
# coupling: the fitted law
fit = json.load(open("friction_law.json"))["fit"]
out += [("law_mu_0", fit["mu_0"]), ("law_mu_ss", fit["mu_ss"]), ("law_s0_m", fit["s0"]), ("law_s_peak_m", fit["s_peak"]),
        ("law_rms_residual", fit["rms_residual"])]
# macro: the pin-on-disk state at t_end; mu - alpha V (the law part) and the wear against Archard k W s / H
# (k, W, H, alpha: pin_on_disk.toml's values)
rows = list(csv.DictReader(open("pin_on_disk/pin_on_disk.csv")))
end = rows[-1]
k, load, hardness, alpha = 1e-4, 0.981, 0.9e9, 0.68
slide, wear = float(end["sliding_distance_m"]), float(end["wear_volume_m3"])
out += [("pod_t_s", float(end["t_s"])), ("pod_mu", float(end["mu"])), ("pod_mu_law", float(end["mu_law"])),
        ("pod_mu_minus_speed_term", float(end["mu"]) - alpha * float(end["speed_m_s"])),
        ("pod_speed_m_s", float(end["speed_m_s"])), ("pod_sliding_distance_m", slide), ("pod_wear_m3", wear),
        ("pod_archard_ratio", wear / (k * load * slide / hardness)),
        ("pod_contact_radius_m", float(end["contact_radius_m"])), ("pod_mean_pressure_Pa", float(end["mean_pressure_Pa"]))]
with open("key_numbers.txt", "w") as f:
    f.write("# RunIn multiscale pipeline example: key numbers (name value)\n")
    for name, value in out:
        f.write(f"{name} {value!r}\n")
print(open("key_numbers.txt").read(), end="")
EOF
