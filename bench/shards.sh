#!/usr/bin/env bash
# Shards against threads (docs/methods.md s.12): one fragility run as one process on N threads,
# and as N `--shard K/N` processes of one thread each, started together, then merged, both with
# the history pool in a warm cache (filled first by `freestand cache fill`, as a cluster job
# would). Prints the wall times, their ratio, and checks that the merged folder is the single
# run's bytes.
# Usage: bench/shards.sh [FREESTAND] [N] [SAMPLES]   (default build/ci/freestand, N = nproc, 2000)
set -euo pipefail
cd "$(dirname "$0")/.."
exe="${1:-build/ci/freestand}"
n="${2:-$(nproc)}"
samples="${3:-2000}"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
case_file=cases/block-ts3.toml
run=(fragility "${case_file}" --pga 0.1:0.6:0.1 --samples "${samples}" --pool 20
     --cache "${work}/cache")
now() { date +%s.%N; }

t0=$(now)
"${exe}" cache fill "${case_file}" --sets 20 --cache "${work}/cache" >/dev/null
t1=$(now)
"${exe}" "${run[@]}" --threads "${n}" --out "${work}/threads" >/dev/null
t2=$(now)
for k in $(seq 1 "${n}"); do
  "${exe}" "${run[@]}" --threads 1 --shard "${k}/${n}" --out "${work}/shards" >/dev/null &
done
wait
"${exe}" merge "${work}/shards" --out "${work}/merged" >/dev/null
t3=$(now)
for f in fragility.json samples.csv report.md report.html; do
  cmp -s "${work}/threads/${f}" "${work}/merged/${f}" || { echo "shards: ${f} differs" >&2; exit 1; }
done
awk -v t0="${t0}" -v t1="${t1}" -v t2="${t2}" -v t3="${t3}" -v n="${n}" -v s="${samples}" 'BEGIN {
  fill = t1 - t0; thr = t2 - t1; sh = t3 - t2;
  printf "block-ts3, 6 levels x %d samples, pool of 20 sets, %d cores\n", s, n;
  printf "   cache fill (20 sets)            %7.2f s\n", fill;
  printf "   one process, --threads %-2d       %7.2f s\n", n, thr;
  printf "   %2d shards of 1 thread + merge   %7.2f s   (%.2fx the threads run)\n", n, sh, sh / thr;
  printf "   merged folder: the same bytes\n" }'
