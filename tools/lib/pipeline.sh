# Sourced by tools/run-pipeline.

# The machine's core count. Not plain `nproc`: GNU nproc honours OMP_NUM_THREADS, which the pipeline sets to 1
# for LAMMPS, and would then report one core.
machine_cores() {
  getconf _NPROCESSORS_ONLN 2>/dev/null || nproc --all
}

# lammps_stage DIR NP ARGS...: runs `mpirun -np NP lmp_runin ARGS` in DIR (log DIR/log.lammps, no screen output)
# and prints its progress: every 10 s the current `run` of the deck and how far it is (as far as the log has been
# written), then each run of the deck with its step count and loop time. Needs $build.
lammps_stage() {
  local dir=$1 np=$2 start=$SECONDS last="" line
  shift 2
  (cd "$dir" && mpirun -np "$np" --oversubscribe "$build/lmp_runin" "$@" -log log.lammps -screen none) &
  local pid=$!
  while kill -0 "$pid" 2>/dev/null; do
    sleep 2
    [ $(( (SECONDS - start) % 10 )) -lt 2 ] || continue
    line=$(awk '/^run +[0-9]+/ {runs++; length_ = $2} $1 == "Step" {table = 1; first = ""} /^Loop time/ {table = 0}
                table && $1 ~ /^[0-9]+$/ {if (first == "") first = $1; step = $1}
                END {if (step != "") printf "run %d: step %d of %s", runs, step - first, length_}' \
           "$dir/log.lammps" 2>/dev/null || true)
    if [ -n "$line" ] && [ "$line" != "$last" ]; then
      echo "   ... $line, $((SECONDS - start)) s"
      last=$line
    fi
  done
  wait "$pid"
  awk '/^Loop time of/ {printf "   run %d: %s steps in %.1f s on %s MPI ranks\n", ++n, $9, $4, $6}' "$dir/log.lammps"
  echo "   done in $((SECONDS - start)) s ($dir/log.lammps)"
}
