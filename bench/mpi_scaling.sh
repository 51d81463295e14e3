#!/usr/bin/env bash
# MPI against the threaded single process at equal cores, and strong scaling over ranks.
# Runs each configuration three times and reports the median of the wall time the program
# records in its result file (attribute wall_time_s).
# Usage: bench/mpi_scaling.sh [ENSEMBLE.toml] (default: ensembles/model-1-3-builtin.toml)
set -euo pipefail
cd "$(dirname "$0")/.."
ensemble=${1:-ensembles/model-1-3-builtin.toml}
binary=build/src/caskdem
out=$(mktemp -d)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
wall() { /usr/bin/python3 -c "import h5py, sys; print(h5py.File(sys.argv[1])['/'].attrs['wall_time_s'])" "$1"; }
median() { printf '%s\n' "$@" | sort -g | sed -n 2p; }
run() {  # label, command prefix, threads
  local times=()
  for i in 1 2 3; do
    $2 $binary ensemble "$ensemble" --out "$out/r.h5" --threads "$3" --quiet --no-plot >/dev/null
    times+=("$(wall "$out/r.h5")")
  done
  printf '%-34s %8.2f s   (runs: %s)\n' "$1" "$(median "${times[@]}")" "${times[*]}"
}
echo "ensemble: $ensemble"
run "1 process, 1 thread" "" 1
run "1 process, 2 threads" "" 2
run "mpirun -n 1, 1 thread" "mpirun -n 1 --bind-to none" 1
run "mpirun -n 2, 1 thread each" "mpirun -n 2 --bind-to none" 1
rm -rf "$out"
