#!/usr/bin/env bash
# Builds the libFuzzer targets (in the asan preset's tree: clang with ASan and UBSan, whose
# libraries they link) and runs each for a bounded time on a scratch copy of its seed corpus
# (fuzz/corpus/<name>; the committed corpus is never modified), as many at once as there are
# cores. Any crash, sanitizer report or escaped exception fails the run, and the crashing input
# is kept in build/asan/findings/<name>/ for a regression test.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 10)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
targets=(at2 cosmos csv spectrum_csv case cli_values fragility_shard batch_shard batch_list shard_file)
[ -f build/asan/CMakeCache.txt ] || cmake --preset asan >/dev/null
cmake --build --preset asan --target "${targets[@]/#/fuzz_}" >/dev/null

run_one() {
  local name="$1" seconds="$2"
  local work="build/asan/fuzz-work/${name}" findings="build/asan/findings/${name}"
  local log="build/asan/fuzz-${name}.log"
  rm -rf "${work}"
  mkdir -p "${work}" "${findings}"
  cp -r "fuzz/corpus/${name}/." "${work}/"
  if "build/asan/fuzz/fuzz_${name}" "${work}" -max_total_time="${seconds}" -max_len=16384 \
      -timeout=10 -rss_limit_mb=2048 -artifact_prefix="${findings}/" -print_final_stats=1 \
      >"${log}" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "${log}" | grep -o '[0-9]*$' || echo "?")
    echo "fuzz ${name}: ${runs} executions in ${seconds} s, no crash"
  else
    echo "fuzz ${name}: FAILED (see ${log}; input kept in ${findings}/)"
    tail -30 "${log}"
    return 1
  fi
}
export -f run_one

failures=0
printf '%s\n' "${targets[@]}" | xargs -P "$(nproc)" -I{} bash -c 'run_one "$@"' _ {} "${seconds}" \
  || failures=1
if [ "${failures}" -ne 0 ]; then
  echo "fuzz: a target failed"
  exit 1
fi
echo "fuzz: ${#targets[@]} targets passed"
