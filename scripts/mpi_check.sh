#!/usr/bin/env bash
# The MPI build's check (docs/methods.md s.12; ctest in preset mpi):
# `mpirun -n 2 freestand fragility` must write the same bytes as the same executable run as one
# process, for generated histories (block-ts1, a pool of 2 sets) and for a user suite of records.
# Usage: scripts/mpi_check.sh PATH/TO/freestand
set -euo pipefail
exe="$1"
cd "$(dirname "$0")/.."
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
# Debian's OpenMPI refuses root unless told (CI containers run as root).
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
mpirun_cmd=(mpirun -n 2 --oversubscribe)
for f in 1.5 3.0; do
  awk -v f="$f" 'BEGIN { print "time_s,accel_g";
    for (i = 0; i <= 4000; i++) { t = i * 0.002; a = sin(2 * 3.141592653589793 * f * t);
      printf "%g,%.9g\n", t, a * (t < 1 ? t : 1) } }' >"${work}/sine-${f}.csv"
done
check() {
  local name="$1"; shift
  "${exe}" fragility "$@" --threads 1 --out "${work}/${name}-serial" >/dev/null
  # The ranks must really have split the samples (a build without MPI would run 2 whole copies).
  "${mpirun_cmd[@]}" "${exe}" fragility "$@" --threads 1 --out "${work}/${name}-mpi" \
    | grep -q "samples computed on 2 MPI ranks" \
    || { echo "mpi check ${name}: mpirun did not split the samples over 2 ranks" >&2; exit 1; }
  for f in fragility.json samples.csv report.md report.html fragility.svg; do
    if ! cmp -s "${work}/${name}-serial/${f}" "${work}/${name}-mpi/${f}"; then
      echo "mpi check ${name}: ${f} differs between 1 process and 2 ranks" >&2
      exit 1
    fi
  done
  echo "mpi check ${name}: 2 ranks wrote the serial bytes"
}
check generated cases/block-ts1.toml --pga 0.2,0.5 --samples 6 --pool 2
check records cases/block-ts1.toml --pga 0.3,0.6 --samples 10 --records "${work}/sine-1.5.csv" "${work}/sine-3.0.csv"
